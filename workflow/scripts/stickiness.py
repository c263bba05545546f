"""Snakemake `stickiness` job: the stickiness run files -> results/stickiness/stickiness.nc and stickiness.csv."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import stickiness

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    stickiness.run(snakemake.params.sweep, runs=snakemake.input.runs, nc=snakemake.output.nc,
                   csv=snakemake.output.csv, html=snakemake.output.html)
