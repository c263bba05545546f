# The paper's Figs. 1-4, zeta(H) and a collapse plot, all in the report.
from roughcontact.study.report import (
    figures as _figures,
)  # noqa: E402  (matplotlib only inside make_figures)

FIGURE_SPECS = _figures.figure_specs(STUDY)


rule figures:
    input:
        ensemble=rules.merge.output.ensemble,
        zeta=rules.crossover.output.zeta_csv,
        crossover=rules.crossover.output.csv,
        model_curves=rules.model_curves.output.nc,
    output:
        *[
            report(
                f"{FIGURE_DIR}/{s['file']}",
                caption=f"{CAPTION_DIR}/{s['caption']}",
                category=s["category"],
                labels=s["labels"],
            )
            for s in FIGURE_SPECS
        ],
    log:
        "logs/figures.log",
    priority: ANALYSIS_PRIORITY + 1  # the longest analysis job
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["figures"],  # the figures' code
    script:
        "../scripts/figures.py"


# The report's landing page: verdict counts, headline numbers and one Fig. 3, inlined by
# workflow/report/workflow.rst (study.rules.summary).
# A sweep of measured scans only (hurst empty) gets a page of the scans' fits and best models.
rule summary:
    input:
        claims=rules.claims.output.csv if STUDY.generated else [],
        crossover=rules.crossover.output.csv if STUDY.generated else [],
        zeta=rules.crossover.output.zeta_csv if STUDY.generated else [],
        models=rules.models.output.csv if STUDY.generated else [],
        figures=rules.figures.output if STUDY.generated else [],
        grid_error=grid_error_table if STUDY.generated else [],
        measured_fits=measured_tables("measured_spectrum"),
        measured_scorecards=measured_tables("measured_scorecard"),
        spectrum_merged=spectrum_outputs("spectrum_merge", "nc"),
        spectrum_figures=spectrum_outputs("spectrum_figures", "kf"),
    output:
        html=report(
            "results/summary.html",
            caption=f"{CAPTION_DIR}/summary.rst",
            category="0. Answer",
            labels={"page": "summary"},
        ),
    log:
        "logs/summary.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["summary"],  # the landing page's code
    script:
        "../scripts/summary.py"
