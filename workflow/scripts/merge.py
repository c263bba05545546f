"""Snakemake `merge` job: all run files -> results/stiffness.nc, results/ensemble.nc (a group per surface kind)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.merge import run_merge

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_merge(snakemake.params.cfg, snakemake.input.runs, snakemake.output.stiffness, snakemake.output.ensemble)
