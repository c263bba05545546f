"""Snakemake `measured_merge` / `spectrum_merge` job: the runs of one surface -> one NetCDF file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_merge

snakemake = globals()["snakemake"]
source = snakemake.params.source
name = snakemake.wildcards.topo if source == "topography" else snakemake.wildcards.spec
with log_to(snakemake.log[0]):
    measured_merge.run(snakemake.params.cfg, source, name, runs=snakemake.input.runs, nc=snakemake.output.nc,
                       surface=snakemake.input.get("surface"))
