# The pressure and gap histograms of one load (fields.histograms): the report's figure, from the
# merged runs (study.report.histograms).


rule histograms_figure:
    input:
        stiffness=rules.merge.output.stiffness,
    output:
        png=report(
            f"{FIGURE_DIR}/histograms.png",
            caption=f"{CAPTION_DIR}/histograms.rst",
            category="Area and gap",
            labels={"figure": "pressure and gap histograms"},
        ),
    log:
        "logs/histograms_figure.log",
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["histograms_figure"],  # the figure's code and the ensemble-mean histograms
    script:
        "../scripts/histograms_figure.py"
