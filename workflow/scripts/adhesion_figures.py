"""Snakemake `adhesion_figures` job: adhesion.nc, stiffness.nc, pull_off.csv -> the two adhesion figures."""
from roughcontact.study.report.adhesion import make_adhesion_figures
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    make_adhesion_figures(snakemake.params.cfg, snakemake.input.adhesion, snakemake.input.stiffness,
                          snakemake.input.pull_off, snakemake.output.paths, snakemake.output.pull_off)
