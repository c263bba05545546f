"""Snakemake `fine_reference` job: stiffness.nc of the study and of its grid.fine (and grid.coarse) companions -> fine_reference.csv."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import fine_reference

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    fine_reference.run(snakemake.params.cfg, stiffness=snakemake.input.stiffness, fine=snakemake.input.fine,
                       csv=snakemake.output.csv, html=snakemake.output.html, coarse=snakemake.input.coarse or None)
