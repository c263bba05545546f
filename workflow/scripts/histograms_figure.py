"""Snakemake `histograms_figure` job: stiffness.nc -> the pressure and gap histograms of one load (PNG)."""
from roughcontact.study.report.histograms import make_histogram_figure
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    make_histogram_figure(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.png)
