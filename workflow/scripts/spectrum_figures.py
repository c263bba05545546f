"""Snakemake `spectrum_figures` job: the report figure of one measured spectrum."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import spectrum_figures

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    spectrum_figures.run(snakemake.params.cfg, snakemake.wildcards.spec, merged=snakemake.input.merged,
                         kf=snakemake.output.kf)
