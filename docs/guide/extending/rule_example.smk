# file: workflow/rules/extra/resolved_loads.smk
# The resolved loads of every sphere combination: a rule of your own. The Snakefile includes
# every file of workflow/rules/extra/; its entry point is the run function of the package's module
# named after it (roughcontact.study.rules.resolved_loads.run), called by its thin script.


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
        code=code_fingerprint("resolved_loads"),  # its module's code: an edit reruns the rule
    script:
        "../../scripts/resolved_loads.py"
