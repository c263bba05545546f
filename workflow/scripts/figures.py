"""Snakemake `figures` job: Figs. 1-4, zeta(H), collapse plot (PNG, in the report)."""
from roughcontact.figures import make_figures

snakemake = globals()["snakemake"]
make_figures(snakemake.params.cfg, snakemake.input.stiffness, snakemake.input.ensemble, snakemake.input.zeta,
             snakemake.input.crossover, outputs=list(snakemake.output), log=snakemake.log[0])
