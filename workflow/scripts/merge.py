"""Snakemake `merge` job (and `merge_coarse`, `merge_fine`): run files -> stiffness.nc, ensemble.nc (a group per surface kind)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import merge

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    merge.run(snakemake.params.cfg, snakemake.input.runs, snakemake.output.stiffness, snakemake.output.ensemble)
