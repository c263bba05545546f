"""Snakemake `summary` job: claims, crossover, zeta, models tables and Fig. 3 -> results/summary.html (the report's landing page)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.summary import write_summary

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    write_summary(snakemake.params.cfg, snakemake.input.claims, snakemake.input.crossover, snakemake.input.zeta,
                  snakemake.input.models, list(snakemake.input.figures), snakemake.output.html)
