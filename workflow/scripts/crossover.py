"""Snakemake `crossover` job: stiffness + zeta -> results/crossover.csv (eq. 16 fitted, F_tr with a 95 % interval)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.crossover import run_crossover
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_crossover(snakemake.params.cfg, snakemake.input.stiffness, snakemake.input.zeta, snakemake.output.csv,
                  snakemake.output.nc)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "crossover")
