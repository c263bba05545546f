"""Snakemake `grid_error` job: stiffness.nc of the study and of its grid.coarse companion -> grid_error.csv."""
from roughcontact.study.analysis.grid_error import run_study_grid_error
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_study_grid_error(snakemake.params.cfg, snakemake.input.fine, snakemake.input.coarse, snakemake.output.csv)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "grid_error")
