"""Snakemake `adhesion_figures` job: adhesion.nc, stiffness.nc, pull_off.csv -> the two adhesion figures."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import adhesion_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    adhesion_figures.run(snakemake.params.cfg, adhesion=snakemake.input.adhesion, stiffness=snakemake.input.stiffness,
                         pull_off=snakemake.input.pull_off, out_paths=snakemake.output.paths,
                         out_pull_off=snakemake.output.pull_off)
