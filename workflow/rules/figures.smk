# The paper's Figs. 1-4, zeta(H) and a collapse plot, all in the report.
from roughcontact.study import (
    figures as _figures,
)  # noqa: E402  (matplotlib only inside make_figures)

FIGURE_SPECS = _figures.figure_specs(STUDY)


rule figures:
    input:
        ensemble=rules.merge.output.ensemble,
        zeta=rules.fit_zeta.output.csv,
        crossover=rules.crossover.output.csv,
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
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["figures"],  # the figures' code
    script:
        "../scripts/figures.py"
