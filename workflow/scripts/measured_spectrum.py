"""Snakemake `measured_spectrum` job: the spectrum fit (CSV) and the models' k(F) (NetCDF) of one scan."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.measured_spectrum import run_spectrum
from roughcontact.study.report.tables import csv_to_html

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_spectrum(snakemake.params.cfg, snakemake.wildcards.topo, snakemake.input.surface, snakemake.output.csv,
                 snakemake.output.nc)
    csv_to_html(snakemake.output.csv, snakemake.output.html, "spectrum_fit")
