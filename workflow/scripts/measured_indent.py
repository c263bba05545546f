"""Snakemake `measured_indent` / `spectrum_indent` job: one tile or seed, one radius -> one run file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.runs.measured import run_job

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_job(snakemake.params.job, snakemake.input[0], snakemake.output.run)
