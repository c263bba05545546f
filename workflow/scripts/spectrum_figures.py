"""Snakemake `spectrum_figures` job: the report figure of one measured spectrum."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.measured import make_spectrum_figure

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    make_spectrum_figure(snakemake.params.cfg, snakemake.wildcards.spec, snakemake.input.merged, snakemake.output)
