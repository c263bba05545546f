"""Snakemake `models` job: stiffness + zeta (+ grid error) -> results/models.csv, .nc, .html and one figure per sphere combination."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import models

snakemake = globals()["snakemake"]
inputs, out = snakemake.input, snakemake.output
with log_to(snakemake.log[0]):
    models.run(snakemake.params.cfg, stiffness=inputs.stiffness, zeta=inputs.zeta, csv=out.csv, nc=out.nc,
               html=out.html, figures=list(out.figures), grid_error=inputs.grid_error or None,
               fine_reference=inputs.fine_reference or None, model_curves=inputs.model_curves)
