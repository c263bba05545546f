"""Snakemake `exponents` job: stiffness.nc -> results/exponents.csv and a figure (local d ln k/d ln F with intervals)."""
from roughcontact.study.exponents import run_exponents
from roughcontact.study.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_exponents(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv, snakemake.output.png)
