"""Snakemake `adhesion` job: the adhesive run files -> results/adhesion/adhesion.nc and pull_off.csv."""
from roughcontact.study.analysis.adhesion import run_adhesion
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.adhesion import write_pull_off_page

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_adhesion(snakemake.params.cfg, snakemake.input.runs, snakemake.output.nc, snakemake.output.csv)
    write_pull_off_page(snakemake.output.csv, snakemake.output.html)
