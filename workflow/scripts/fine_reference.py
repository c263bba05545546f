"""Snakemake `fine_reference` job: stiffness.nc of the study and of its grid.fine (and grid.coarse) companions -> fine_reference.csv."""
from roughcontact.study.analysis.fine_reference import run_fine_reference
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_fine_reference(snakemake.params.cfg, snakemake.input.stiffness, snakemake.input.fine, snakemake.output.csv,
                       coarse_nc=snakemake.input.coarse or None)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "fine_reference")
