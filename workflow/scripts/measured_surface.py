"""Snakemake `measured_surface` job: one scan -> results/measured_surface/{topo}.nc."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_surface

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    measured_surface.run(snakemake.params.entry, snakemake.params.cfg, nc=snakemake.output.nc)
