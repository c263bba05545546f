# One job per run (H, R, h_rms, optional axes, seed): surface, warm-started load path, stiffness.
rule indent:
    output:
        run=RUN_PATTERN,
    log:
        LOG_PATTERN,
    benchmark:
        BENCHMARK_PATTERN
    wildcard_constraints:
        combo=r"H[^/]+",
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    resources:
        mem_mb=indent_mem_mb,
        runtime=indent_runtime,  # minutes
    params:
        settings=lambda wc: study_settings.settings_from_wildcards(STUDY, wc),
        solver_version=SOLVER_VERSION,  # bumped on purpose when results change
    script:
        "../scripts/indent.py"


# The same run on the coarse grid of the grid error (grid.coarse): the study's surface seen there.
rule indent_coarse:
    output:
        run=COARSE_RUN_PATTERN,
    log:
        COARSE_LOG_PATTERN,
    benchmark:
        COARSE_BENCHMARK_PATTERN
    wildcard_constraints:
        combo=r"H[^/]+",
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    resources:
        mem_mb=indent_mem_mb,
        runtime=indent_runtime,  # minutes
    params:
        settings=lambda wc: study_settings.settings_from_wildcards(COARSE, wc),
        solver_version=SOLVER_VERSION,  # bumped on purpose when results change
    script:
        "../scripts/indent.py"
