"""Snakemake `stickiness_figures` job: the stickiness run files -> the load-area figure."""
from roughcontact.study.logs import log_to
from roughcontact.study.stickiness.figures import run_stickiness_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_stickiness_figures(snakemake.params.sweep, snakemake.input.runs, snakemake.output.loading)
