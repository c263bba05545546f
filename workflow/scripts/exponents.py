"""Snakemake `exponents` job: stiffness.nc -> results/exponents.csv and a figure (local d ln k/d ln F with intervals)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import exponents

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    exponents.run(snakemake.params.cfg, stiffness=snakemake.input.stiffness, csv=snakemake.output.csv,
                  png=snakemake.output.png, html=snakemake.output.html)
