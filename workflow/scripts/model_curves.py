"""Snakemake `model_curves` job: the config -> results/model_curves.nc (the precomputable models' curves, once)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import model_curves

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    model_curves.run(snakemake.params.cfg, snakemake.output.nc)
