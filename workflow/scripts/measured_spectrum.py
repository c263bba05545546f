"""Snakemake `measured_spectrum` job: the spectrum fit (CSV) and the models' k(F) (NetCDF) of one scan."""
from roughcontact.study.logs import log_to
from roughcontact.study.measured.spectrum import run_spectrum

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_spectrum(snakemake.params.cfg, snakemake.wildcards.topo, snakemake.input.surface, snakemake.output.csv,
                 snakemake.output.nc)
