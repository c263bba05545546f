# Merge the runs, fit zeta(H) (eq. 11), check the crossover (eqs. 16, 17).
rule merge:
    input:
        runs=study.run_paths(config),
    output:
        stiffness="results/stiffness.nc",
        ensemble="results/ensemble.nc",
    params:
        cfg=config,  # resolved config: a change of any setting reruns the analysis
    log:
        "logs/merge.log",
    conda:
        "../../envs/roughcontact.yaml"
    script:
        "../scripts/merge.py"


rule fit_zeta:
    input:
        stiffness=rules.merge.output.stiffness,
    output:
        csv=report(
            "results/zeta.csv",
            caption="../report/zeta_table.rst",
            category="Tables",
            labels={"table": "zeta(H)"},
        ),
        nc="results/zeta.nc",
    params:
        cfg=config,
    log:
        "logs/fit_zeta.log",
    conda:
        "../../envs/roughcontact.yaml"
    script:
        "../scripts/fit_zeta.py"


rule crossover:
    input:
        ensemble=rules.merge.output.ensemble,
        zeta=rules.fit_zeta.output.csv,
    output:
        csv=report(
            "results/crossover.csv",
            caption="../report/crossover_table.rst",
            category="Tables",
            labels={"table": "crossover"},
        ),
    params:
        cfg=config,
    log:
        "logs/crossover.log",
    conda:
        "../../envs/roughcontact.yaml"
    script:
        "../scripts/crossover.py"
