"""Snakemake `measured_figures` job: the report figures of one scan."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_figures

snakemake = globals()["snakemake"]
out = snakemake.output
with log_to(snakemake.log[0]):
    measured_figures.run(snakemake.params.cfg, snakemake.wildcards.topo, surface=snakemake.input.surface,
                         merged=snakemake.input.merged, spectrum=snakemake.input.spectrum, heights=out.heights,
                         psd=out.psd, kf=out.kf)
