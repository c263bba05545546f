# file: workflow/scripts/resolved_loads.py
"""Snakemake `resolved_loads` job: stiffness.nc -> results/resolved_loads.csv (the resolved loads of every sphere)."""
from roughcontact.study.analysis.resolved_loads import run_resolved_loads
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_resolved_loads(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv)
