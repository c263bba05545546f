# Adhesive runs (work_of_adhesion > 0): their retract paths and pull-off merged, the pull-off
# table, the report's figures (docs/guide/adhesion.md).


rule adhesion:
    input:
        runs=adhesive_run_files,
    output:
        nc="results/adhesion/adhesion.nc",
        csv="results/adhesion/pull_off.csv",
        html=report(
            "results/adhesion/pull_off.html",
            caption="../report/pull_off_table.rst",
            category="Adhesion",
            labels={"table": "pull-off"},
        ),
    log:
        "logs/adhesion.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/adhesion.py"


rule adhesion_figures:
    input:
        adhesion=rules.adhesion.output.nc,
        stiffness=rules.merge.output.stiffness,
        pull_off=rules.adhesion.output.csv,
    output:
        paths=report(
            "results/adhesion_figures/paths.png",
            caption="../report/adhesion_paths.rst",
            category="Adhesion",
            labels={"figure": "load and retract paths"},
        ),
        pull_off=report(
            "results/adhesion_figures/pull_off.png",
            caption="../report/adhesion_pull_off.rst",
            category="Adhesion",
            labels={"figure": "pull-off against roughness"},
        ),
    log:
        "logs/adhesion_figures.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/adhesion_figures.py"
