# One job per run (H, R, h_rms, optional axes, seed): surface, warm-started load path, stiffness.
rule indent:
    output:
        run=study.RUN_PATTERN,
    log:
        study.LOG_PATTERN,
    benchmark:
        study.BENCHMARK_PATTERN
    wildcard_constraints:
        combo=r"H[^/]+",
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    resources:
        # both grow with the attempt: a job killed over a limit is retried with more
        mem_mb=lambda wc, attempt: study.indent_resources(config)["mem_mb"] * attempt,
        runtime=lambda wc, attempt: study.indent_resources(config)["runtime"] * attempt,  # minutes
    params:
        settings=lambda wc: study.settings_from_wildcards(config, wc),
    script:
        "../scripts/indent.py"
