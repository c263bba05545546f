"""Snakemake `measured_figures` job: the report figures of one scan."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.measured import make_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    make_figures(snakemake.params.cfg, snakemake.wildcards.topo, snakemake.input.surface,
                 snakemake.input.merged, snakemake.output, spectrum_file=snakemake.input.spectrum)
