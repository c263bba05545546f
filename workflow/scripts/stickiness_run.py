"""Snakemake `stickiness_run` job: one flat surface loaded into a Dugdale half-space -> its run file."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import stickiness_run

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    stickiness_run.run(snakemake.params.run, output=snakemake.output.run)
