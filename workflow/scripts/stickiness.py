"""Snakemake `stickiness` job: the stickiness run files -> results/stickiness/stickiness.nc and stickiness.csv."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.stickiness import run_stickiness_merge
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_stickiness_merge(snakemake.params.sweep, snakemake.input.runs, snakemake.output.nc, snakemake.output.csv)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "stickiness")
