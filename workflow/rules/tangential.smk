# Tangential contact of the sphere runs (axes poisson, friction): the full-stick stiffness of every
# load and the partial-slip paths merged, the table per load, the report's figures
# (docs/guide/tangential.md).


rule tangential:
    input:
        runs=run_files,
        crossover=rules.crossover.output.csv,
    output:
        nc="results/tangential/tangential.nc",
        csv="results/tangential/tangential.csv",
        html=report(
            "results/tangential/tangential.html",
            caption="../report/tangential_table.rst",
            category="Tangential contact",
            labels={"table": "k_t/k_n per load"},
        ),
    log:
        "logs/tangential.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/tangential.py"


rule tangential_figures:
    input:
        nc=rules.tangential.output.nc,
        csv=rules.tangential.output.csv,
    output:
        ratio=report(
            "results/tangential/ratio.png",
            caption="../report/tangential_ratio.rst",
            category="Tangential contact",
            labels={"figure": "k_t/k_n against Mindlin"},
        ),
    log:
        "logs/tangential_figures.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/tangential_figures.py"


rule partial_slip_figures:
    input:
        nc=rules.tangential.output.nc,
        csv=rules.tangential.output.csv,
    output:
        slip=report(
            "results/tangential/partial_slip.png",
            caption="../report/tangential_slip.rst",
            category="Tangential contact",
            labels={"figure": "k_t(Q) in partial slip"},
        ),
        micro_slip=report(
            "results/tangential/micro_slip.png",
            caption="../report/tangential_micro_slip.rst",
            category="Tangential contact",
            labels={"figure": "largest micro-slip"},
        ),
    log:
        "logs/partial_slip_figures.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/tangential_figures.py"
