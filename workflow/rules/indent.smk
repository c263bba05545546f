# The runs: surface, warm-started load path, stiffness, one run file and log per run. One job per
# run with jobs.batch = 1 (rule indent); else one job per combination and block of jobs.batch
# seeds (rules indent_seeds0_5, indent_seeds6_11, ...), its runs one after another in one
# Python. A job's params are its runs' own settings: a new seed reruns only its block. The
# longest jobs start first (priority: the job's expected cost), the short ones fill the end; the
# grid error's companion runs on grid.coarse go with the sphere runs they accompany (the same
# priority), so that merge_coarse is done while the last flat runs are.
from roughcontact.study.files.locks import clear_stale_locks  # noqa: E402

# a hard kill's locks (no Snakemake process left in this directory): the same command resumes;
# only in Snakemake's main process (a job's Snakemake may run on another host)
for lock in clear_stale_locks() if workflow.is_main_process else []:
    print(f"removed the stale lock {lock} of a killed run", file=sys.stderr)

if INDENT_BATCH == 1:

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
        priority: indent_priority(STUDY, 1)
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
        priority: indent_priority(STUDY, 1)  # as the runs it accompanies
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

    # The same run's small loads on the fine grid of the reference (grid.fine).
    rule indent_fine:
        output:
            run=FINE_RUN_PATTERN,
        log:
            FINE_LOG_PATTERN,
        benchmark:
            FINE_BENCHMARK_PATTERN
        wildcard_constraints:
            combo=r"H[^/]+",
            seed=r"\d+",
        priority: indent_priority(FINE, 1)  # called for a fine run only
        conda:
            "../../envs/roughcontact.yaml"
        threads: 1
        resources:
            mem_mb=indent_mem_mb,
            runtime=indent_runtime,  # minutes
        params:
            settings=lambda wc: study_settings.settings_from_wildcards(FINE, wc),
            solver_version=SOLVER_VERSION,  # bumped on purpose when results change
        script:
            "../scripts/indent.py"

else:
    for block in INDENT_BLOCKS:

        rule:
            name:
                f"indent_{block.name}"
            output:
                run=[RUN_PATTERN.format(combo="{combo}", seed=s) for s in block.seeds],
            log:
                [LOG_PATTERN.format(combo="{combo}", seed=s) for s in block.seeds],
            benchmark:
                BATCH_BENCHMARK_PATTERN.format(combo="{combo}", block=block.name)
            wildcard_constraints:
                combo=r"H[^/]+",
            priority: indent_priority(STUDY, len(block.seeds))
            conda:
                "../../envs/roughcontact.yaml"
            threads: 1
            resources:
                mem_mb=indent_mem_mb,
                runtime=batch_runtime(len(block.seeds)),  # minutes
            params:
                settings=batch_settings(STUDY, block.seeds),
                solver_version=SOLVER_VERSION,  # bumped on purpose when results change
            script:
                "../scripts/indent.py"

        # The same runs on the coarse grid of the grid error (grid.coarse).
        rule:
            name:
                f"indent_coarse_{block.name}"
            output:
                run=[
                    COARSE_RUN_PATTERN.format(combo="{combo}", seed=s)
                    for s in block.seeds
                ],
            log:
                [
                    COARSE_LOG_PATTERN.format(combo="{combo}", seed=s)
                    for s in block.seeds
                ],
            benchmark:
                COARSE_BATCH_BENCHMARK_PATTERN.format(combo="{combo}", block=block.name)
            wildcard_constraints:
                combo=r"H[^/]+",
            priority: indent_priority(STUDY, len(block.seeds))  # as the runs it accompanies
            conda:
                "../../envs/roughcontact.yaml"
            threads: 1
            resources:
                mem_mb=indent_mem_mb,
                runtime=batch_runtime(len(block.seeds)),  # minutes
            params:
                settings=batch_settings(COARSE, block.seeds),
                solver_version=SOLVER_VERSION,  # bumped on purpose when results change
            script:
                "../scripts/indent.py"

        # The same runs' small loads on the fine grid of the reference (grid.fine).
        rule:
            name:
                f"indent_fine_{block.name}"
            output:
                run=[
                    FINE_RUN_PATTERN.format(combo="{combo}", seed=s)
                    for s in block.seeds
                ],
            log:
                [FINE_LOG_PATTERN.format(combo="{combo}", seed=s) for s in block.seeds],
            benchmark:
                FINE_BATCH_BENCHMARK_PATTERN.format(combo="{combo}", block=block.name)
            wildcard_constraints:
                combo=r"H[^/]+",
            priority: indent_priority(FINE, len(block.seeds))  # called for a fine run only
            conda:
                "../../envs/roughcontact.yaml"
            threads: 1
            resources:
                mem_mb=indent_mem_mb,
                runtime=batch_runtime(len(block.seeds)),  # minutes
            params:
                settings=batch_settings(FINE, block.seeds),
                solver_version=SOLVER_VERSION,  # bumped on purpose when results change
            script:
                "../scripts/indent.py"
