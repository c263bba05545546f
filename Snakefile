# roughcontact parameter study (Pohrt & Popov 2013): `snakemake --cores 2`
# Sweep: config.yaml (or --configfile presets/*.yaml); output: results/; report:
# `snakemake --report results/report.html`.  See README.md.
from snakemake.utils import min_version

min_version("9.0")


configfile: "config.yaml"


include: "workflow/rules/common.smk"


report: "workflow/report/workflow.rst"


include: "workflow/rules/indent.smk"
include: "workflow/rules/analysis.smk"
include: "workflow/rules/figures.smk"


localrules:
    all,
    merge,
    fit_zeta,
    crossover,
    exponents,
    claims,
    models,
    figures,


rule all:
    default_target: True
    input:
        rules.merge.output,
        rules.fit_zeta.output,
        rules.crossover.output,
        rules.exponents.output,
        rules.claims.output,
        rules.models.output,
        rules.figures.output,
