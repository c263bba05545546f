"""Snakemake `tangential` job: run files, crossover.csv -> tangential.nc, tangential.csv and its page."""
from roughcontact.study.report.tangential import run_tangential
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_tangential(snakemake.params.cfg, snakemake.input.runs, snakemake.input.crossover, snakemake.output.nc,
                   snakemake.output.csv, snakemake.output.html)
