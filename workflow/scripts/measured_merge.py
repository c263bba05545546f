"""Snakemake `measured_merge` / `spectrum_merge` job: the runs of one surface -> one NetCDF file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.analysis.measured_merge import merge_surface

snakemake = globals()["snakemake"]
source = snakemake.params.source
name = snakemake.wildcards.topo if source == "topography" else snakemake.wildcards.spec
with log_to(snakemake.log[0]):
    merge_surface(snakemake.params.cfg, source, name, snakemake.input.runs, snakemake.output.nc,
                  surface_file=snakemake.input.surface if source == "topography" else None)
