"""Snakemake `measured_spectrum` job: the spectrum fit (CSV) and the models' k(F) (NetCDF) of one scan."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_spectrum

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    measured_spectrum.run(snakemake.params.cfg, snakemake.wildcards.topo, surface=snakemake.input.surface,
                          csv=snakemake.output.csv, nc=snakemake.output.nc, html=snakemake.output.html)
