"""Snakemake `merge` (`merge_coarse`, `merge_fine`) job: all run files -> stiffness.nc, ensemble.nc (a group per surface kind)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import merge

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    merge.run(snakemake.params.cfg, runs=snakemake.input.runs, stiffness=snakemake.output.stiffness,
              ensemble=snakemake.output.ensemble)
