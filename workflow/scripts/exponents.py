"""Snakemake `exponents` job: stiffness.nc -> results/exponents.csv and a figure (local d ln k/d ln F with intervals)."""
from roughcontact.study.report.exponents import run_exponents
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_exponents(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv, snakemake.output.png)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "exponents")
