# Pastewka & Robbins' stickiness of flat surfaces (the config's stickiness section; claim q):
# one loading path per (H, N, seed), merged into a table of the slopes dF/dA with intervals.


# One job per surface and number: the displacement-controlled loading into a Dugdale half-space.
rule stickiness_run:
    output:
        run=STICKINESS_PATTERN,
    log:
        "logs/stickiness_run/{combination}_seed{seed}.log",
    benchmark:
        "results/benchmarks/stickiness_run/{combination}_seed{seed}.tsv"
    wildcard_constraints:
        combination=r"H[^/_]+_N[^/_]+",
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    params:
        run=stickiness_run_settings,
        solver_version=SOLVER_VERSION,  # bumped on purpose when results change
    script:
        "../scripts/stickiness_run.py"


rule stickiness:
    input:
        runs=stickiness_run_files,
    output:
        nc="results/stickiness/stickiness.nc",
        csv="results/stickiness/stickiness.csv",
        html=report(
            "results/stickiness/stickiness.html",
            caption="../report/stickiness_table.rst",
            category="Adhesion",
            labels={"table": "stickiness"},
        ),
    log:
        "logs/stickiness.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        sweep=STICKINESS,
    script:
        "../scripts/stickiness.py"


rule stickiness_figures:
    input:
        runs=stickiness_run_files,
    output:
        loading=report(
            "results/stickiness_figures/loading.png",
            caption="../report/stickiness_loading.rst",
            category="Adhesion",
            labels={"figure": "stickiness: load against area"},
        ),
    log:
        "logs/stickiness_figures.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        sweep=STICKINESS,
    script:
        "../scripts/stickiness_figures.py"
