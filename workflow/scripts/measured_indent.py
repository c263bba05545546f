"""Snakemake `measured_indent` / `spectrum_indent` job: one tile or seed, one radius -> one run file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_indent

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    measured_indent.run(snakemake.params.job, snakemake.input[0], run=snakemake.output.run)
