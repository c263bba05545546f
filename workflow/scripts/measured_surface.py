"""Snakemake `measured_surface` job: one scan -> results/measured_surface/{topo}.nc."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.runs.measured import prepare_surface

snakemake = globals()["snakemake"]
surface = snakemake.params.cfg   # units and tile only: another setting keeps the tiles' runs
with log_to(snakemake.log[0]):
    prepare_surface(snakemake.params.entry, snakemake.output.nc, length_unit=surface["units"]["length"],
                    tile=surface["tile"])
