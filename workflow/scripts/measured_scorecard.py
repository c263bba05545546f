"""Snakemake `measured_scorecard` job: every model against the tiles of one scan (CSV and report page)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.measured import run_measured_scorecard

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_measured_scorecard(snakemake.params.cfg, snakemake.wildcards.topo, snakemake.input.merged,
                           snakemake.input.spectrum, snakemake.output.csv, snakemake.output.html)
