# One job per (H, R, h_rms, seed): surface, warm-started load path, stiffness.
rule indent:
    output:
        run=study.RUN_PATTERN,
    log:
        study.LOG_PATTERN,
    benchmark:
        study.BENCHMARK_PATTERN
    wildcard_constraints:
        hurst=r"[0-9.e+-]+",
        radius=r"[0-9.e+-]+|inf",
        h_rms=r"[0-9.e+-]+",
        seed=r"\d+",
    conda:
        "../../envs/roughcontact.yaml"
    threads: 1
    resources:
        **study.indent_resources(config),  # mem_mb, runtime (minutes): for cluster executors
    params:
        settings=lambda wc: study.settings_from_wildcards(config, wc),
    script:
        "../scripts/indent.py"
