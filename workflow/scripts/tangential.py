"""Snakemake `tangential` job: run files, crossover.csv -> tangential.nc, tangential.csv and its page."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import tangential

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    tangential.run(snakemake.params.cfg, runs=snakemake.input.runs, crossover=snakemake.input.crossover,
                   nc=snakemake.output.nc, csv=snakemake.output.csv, html=snakemake.output.html)
