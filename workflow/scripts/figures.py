"""Snakemake `figures` job: Figs. 1-4, zeta(H), collapse plot (PNG, in the report)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    figures.run(snakemake.params.cfg, snakemake.input.ensemble, snakemake.input.zeta, snakemake.input.crossover,
                list(snakemake.output), model_curves_nc=snakemake.input.model_curves)
