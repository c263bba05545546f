"""Snakemake `stickiness_figures` job: the stickiness run files -> the load-area figure."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.stickiness import run_stickiness_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_stickiness_figures(snakemake.params.sweep, snakemake.input.runs, snakemake.output.loading)
