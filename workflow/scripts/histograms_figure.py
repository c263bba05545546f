"""Snakemake `histograms_figure` job: stiffness.nc -> the pressure and gap histograms of one load (PNG)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import histograms_figure

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    histograms_figure.run(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.png)
