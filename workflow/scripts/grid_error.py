"""Snakemake `grid_error` job: stiffness.nc of the study and of its grid.coarse companion -> grid_error.csv."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import grid_error

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    grid_error.run(snakemake.params.cfg, fine=snakemake.input.fine, coarse=snakemake.input.coarse,
                   csv=snakemake.output.csv, html=snakemake.output.html)
