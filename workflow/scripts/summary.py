"""Snakemake `summary` job: claims, crossover, zeta, models tables and Fig. 3 (a generated study), the
measured scans' fits and scorecards and the measured spectra's merged files and figures -> results/summary.html
(the report's landing page)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import summary

snakemake = globals()["snakemake"]
inputs = snakemake.input
with log_to(snakemake.log[0]):
    summary.run(snakemake.params.cfg, snakemake.output.html, claims_csv=inputs.claims or None,
                crossover_csv=inputs.crossover or None, zeta_csv=inputs.zeta or None,
                models_csv=inputs.models or None, figure_paths=list(inputs.figures),
                grid_error_csv=inputs.grid_error or None,
                measured_fits=list(inputs.measured_fits), measured_scorecards=list(inputs.measured_scorecards),
                spectrum_merged=list(inputs.spectrum_merged), spectrum_figures=list(inputs.spectrum_figures))
