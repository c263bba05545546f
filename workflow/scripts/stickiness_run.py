"""Snakemake `stickiness_run` job: one flat surface loaded into a Dugdale half-space -> its run file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.runs.stickiness import run_stickiness_job

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_stickiness_job(snakemake.params.run, snakemake.output.run)
