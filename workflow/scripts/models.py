"""Snakemake `models` job: stiffness + zeta (+ grid error) -> results/models.csv, .nc, .html and one figure per sphere combination."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.report.scorecard import run_models

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_models(snakemake.params.cfg, snakemake.input.stiffness, snakemake.input.zeta, snakemake.output.csv,
               snakemake.output.nc, snakemake.output.html, list(snakemake.output.figures),
               grid_error_csv=snakemake.input.grid_error or None,
               fine_reference_csv=snakemake.input.fine_reference or None,
               model_curves_nc=snakemake.input.model_curves)
