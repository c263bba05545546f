# file: workflow/rules/extra/resolved_loads.smk
# The resolved loads of every sphere combination: a rule of your own. The Snakefile includes
# every file of workflow/rules/extra/; its entry point is one function of the package
# (roughcontact.study.analysis.resolved_loads.run_resolved_loads), called by its thin script.


rule resolved_loads:
    input:
        stiffness=rules.merge.output.stiffness,  # the merged runs: chained by the merge rule's output
    output:
        csv="results/resolved_loads.csv",
    log:
        "logs/resolved_loads.log",
    conda:
        "../../../envs/roughcontact.yaml"
    params:
        cfg=config,
    script:
        "../../scripts/resolved_loads.py"
