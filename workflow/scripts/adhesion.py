"""Snakemake `adhesion` job: the adhesive run files -> results/adhesion/adhesion.nc and pull_off.csv."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import adhesion

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    adhesion.run(snakemake.params.cfg, runs=snakemake.input.runs, nc=snakemake.output.nc, csv=snakemake.output.csv,
                 html=snakemake.output.html)
