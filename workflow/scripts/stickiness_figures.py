"""Snakemake `stickiness_figures` job: the stickiness run files -> the load-area figure."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import stickiness_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    stickiness_figures.run(snakemake.params.sweep, runs=snakemake.input.runs, loading=snakemake.output.loading)
