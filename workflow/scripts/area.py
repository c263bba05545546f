"""Snakemake `area` job: the merged runs -> results/area/area_models.csv, .html and area.png (the real contact area)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import area

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    area.run(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv, snakemake.output.html,
             snakemake.output.png)
