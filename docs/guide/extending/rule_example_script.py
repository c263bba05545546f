# file: workflow/scripts/resolved_loads.py
"""Snakemake `resolved_loads` job: stiffness.nc -> results/resolved_loads.csv (the resolved loads of every sphere)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import resolved_loads

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    resolved_loads.run(snakemake.params.cfg, stiffness=snakemake.input.stiffness, csv=snakemake.output.csv)
