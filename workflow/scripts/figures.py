"""Snakemake `figures` job: Figs. 1-4, zeta(H), collapse plot (PNG, in the report)."""
from roughcontact.study.report.figures import make_figures
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    make_figures(snakemake.params.cfg, snakemake.input.ensemble, snakemake.input.zeta, snakemake.input.crossover,
                 outputs=list(snakemake.output), model_curves_nc=snakemake.input.model_curves)
