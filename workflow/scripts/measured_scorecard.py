"""Snakemake `measured_scorecard` job: every model against the tiles of one scan (CSV and report page)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import measured_scorecard

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    measured_scorecard.run(snakemake.params.cfg, snakemake.wildcards.topo, merged=snakemake.input.merged,
                           spectrum=snakemake.input.spectrum, csv=snakemake.output.csv, html=snakemake.output.html)
