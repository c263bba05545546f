"""Snakemake `merge` job: all run files -> results/stiffness.nc, results/ensemble.nc."""
from roughcontact.analysis import run_merge

snakemake = globals()["snakemake"]
run_merge(snakemake.params.cfg, snakemake.input.runs, snakemake.output.stiffness, snakemake.output.ensemble,
          log=snakemake.log[0])
