# Merge the runs, fit zeta(H) (eq. 11), measure the crossover (eqs. 16, 17), the claims table.
from roughcontact.study.registries import (
    ANALYSIS_CODE,
    code_fingerprint,
)  # noqa: E402  (standard library only)

# The fingerprint of the code each analysis rule runs: a new or changed model or claim reruns
# the models or claims rule (params trigger), and no run.
CODE = {rule: code_fingerprint(rule) for rule in ANALYSIS_CODE}


# The models' curves that need no run (Persson, Greenwood-Tripp, MDR, this package's models at the
# sphere loads; Fig. 3's Greenwood-Tripp curve), once, from the config: computed while the runs
# are, read by the models and figures rules (study.analysis.model_curves). Its priority puts it
# after the costliest indent jobs and before the cheapest ones, which fill the end of the run phase:
# first, it took a core from the first runs; last, it held figures and models back after them
# (benchmarks/RESULTS.md, section 9).
MODEL_CURVES_PRIORITY = 1 + min(
    (
        study_runs.indent_priority(STUDY, study_runs.combo_name(c), INDENT_BATCH)
        for c in study_runs.combinations(STUDY)
    ),
    default=0,
)


rule model_curves:
    output:
        nc="results/model_curves.nc",
    log:
        "logs/model_curves.log",
    priority: MODEL_CURVES_PRIORITY  # before the cheapest indent jobs
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["model_curves"],  # the registered models and their code
    script:
        "../scripts/model_curves.py"


rule merge:
    input:
        runs=run_files,
    output:
        stiffness="results/stiffness.nc",
        ensemble="results/ensemble.nc",
    log:
        "logs/merge.log",
    priority: ANALYSIS_PRIORITY + 2  # the critical path: merge, crossover, figures
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,  # resolved config: a change of any setting reruns the analysis
    script:
        "../scripts/merge.py"


# The companion's sphere runs on grid.coarse, merged; the grid error of every load and its
# estimate for the study's grid (study.analysis.grid_error).
rule merge_coarse:
    input:
        runs=coarse_run_files,
    output:
        stiffness="results/merge_coarse/stiffness.nc",
        ensemble="results/merge_coarse/ensemble.nc",
    log:
        "logs/merge_coarse.log",
    priority: ANALYSIS_PRIORITY  # as soon as the companion runs are done
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=COARSE_CONFIG,
    script:
        "../scripts/merge.py"


rule grid_error:
    input:
        fine=rules.merge.output.stiffness,
        coarse=rules.merge_coarse.output.stiffness,
    output:
        csv="results/grid_error.csv",
        html=report(
            "results/grid_error.html",
            caption="../report/grid_error_table.rst",
            category="Tables",
            labels={"table": "grid error"},
        ),
    log:
        "logs/grid_error.log",
    priority: ANALYSIS_PRIORITY  # as soon as the companion runs are done
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["grid_error"],  # the estimate's rule and constants (study.analysis.grid_error)
    script:
        "../scripts/grid_error.py"


# The fine reference's sphere runs on grid.fine (their small loads), merged; the study's grid
# error against them and the converged reference of the fractal branch (study.analysis.fine_reference).
rule merge_fine:
    input:
        runs=fine_run_files,
    output:
        stiffness="results/merge_fine/stiffness.nc",
        ensemble="results/merge_fine/ensemble.nc",
    log:
        "logs/merge_fine.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=FINE_CONFIG,
    script:
        "../scripts/merge.py"


rule fine_reference:
    input:
        stiffness=rules.merge.output.stiffness,
        fine=rules.merge_fine.output.stiffness,
        coarse=coarse_stiffness,
    output:
        csv="results/fine_reference.csv",
        html=report(
            "results/fine_reference.html",
            caption="../report/fine_reference_table.rst",
            category="Tables",
            labels={"table": "fine reference"},
        ),
    log:
        "logs/fine_reference.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["fine_reference"],  # the reference's and the estimate's rule and constants
    script:
        "../scripts/fine_reference.py"


# zeta(H) of eq. 11 and the crossover force of eqs. 16, 17 (which uses it): one job, stiffness.nc
# read once (study.rules.crossover); the critical path merge, crossover, figures, summary.
rule crossover:
    input:
        stiffness=rules.merge.output.stiffness,
    output:
        zeta_csv="results/zeta.csv",
        zeta_html=report(
            "results/zeta.html",
            caption="../report/zeta_table.rst",
            category="Tables",
            labels={"table": "zeta(H)"},
        ),
        zeta_nc="results/zeta.nc",
        csv="results/crossover.csv",
        html=report(
            "results/crossover.html",
            caption="../report/crossover_table.rst",
            category="Tables",
            labels={"table": "crossover"},
        ),
        nc="results/crossover.nc",
    log:
        "logs/crossover.log",
    priority: ANALYSIS_PRIORITY + 2  # the critical path: merge, crossover, figures
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/crossover.py"


rule exponents:
    input:
        stiffness=rules.merge.output.stiffness,
    output:
        csv="results/exponents.csv",
        html=report(
            "results/exponents.html",
            caption="../report/exponents_table.rst",
            category="Tables",
            labels={"table": "local exponents"},
        ),
        png=report(
            "results/exponents/local_exponents.png",
            caption="../report/exponents.rst",
            category="zeta(H) and collapse",
            labels={"figure": "local exponents"},
        ),
    log:
        "logs/exponents.log",
    priority: ANALYSIS_PRIORITY + 1  # claims waits for it: beside crossover
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../scripts/exponents.py"


rule claims:
    input:
        crossover=rules.crossover.output.csv,
        replicates=rules.crossover.output.nc,
        zeta=rules.crossover.output.zeta_csv,
        zeta_replicates=rules.crossover.output.zeta_nc,
        stiffness=rules.merge.output.stiffness,
        exponents=rules.exponents.output.csv,
        pull_off=pull_off_table,
        stickiness=stickiness_table,
        tangential=tangential_file,
        tables=claim_tables,
    output:
        csv="results/claims.csv",
        html=report(
            "results/claims.html",
            caption="../report/claims_page.rst",
            category="1. Claims of the paper",
            labels={"table": "claims"},
        ),
    log:
        "logs/claims.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["claims"],  # the registered claims and their code
    script:
        "../scripts/claims.py"


rule models:
    input:
        stiffness=rules.merge.output.stiffness,
        zeta=rules.crossover.output.zeta_csv,
        grid_error=grid_error_table,
        fine_reference=fine_reference_table,
        model_curves=rules.model_curves.output.nc,
    output:
        csv="results/models.csv",
        nc="results/models.nc",
        html=report(
            "results/models.html",
            caption="../report/models_page.rst",
            category="2. Model scorecard",
            labels={"table": "model scorecard"},
        ),
        figures=[
            report(
                f"results/models/{name}.png",
                caption="../report/models_figure.rst",
                category="2. Model scorecard",
                labels={"figure": name},
            )
            for name in study_runs.sphere_names(STUDY, adhesive=False)
        ],
    log:
        "logs/models.log",
    priority: 1  # beside figures, before claims
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["models"],  # the registered models and their code
    script:
        "../scripts/models.py"
