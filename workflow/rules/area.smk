# The real contact area: the area scorecard and the ensemble's A(F) against Hertz and the linear
# law (study.report.area); claims (u) and (v) on the area are rows of the claims rule.


rule area:
    input:
        stiffness=rules.merge.output.stiffness,
    output:
        csv="results/area/area_models.csv",
        html=report(
            "results/area/area_models.html",
            caption="../report/area_table.rst",
            category="2. Model scorecard",
            labels={"table": "area scorecard"},
        ),
        png=report(
            "results/area/area.png",
            caption="../report/area_figure.rst",
            category="2. Model scorecard",
            labels={"figure": "contact area A(F)"},
        ),
    log:
        "logs/area.log",
    priority: ANALYSIS_PRIORITY  # needs only merge: beside crossover and figures, not alone at the end
    conda:
        "../../envs/roughcontact.yaml"
    params:
        cfg=config,
        code=CODE["area"],  # the registered area models and the area's resolution rule
    script:
        "../scripts/area.py"
