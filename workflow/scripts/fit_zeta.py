"""Snakemake `fit_zeta` job: results/stiffness.nc -> results/zeta.csv, results/zeta.nc (eq. 11)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.zeta.fit import run_fit_zeta
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_fit_zeta(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv, snakemake.output.nc)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "zeta")
