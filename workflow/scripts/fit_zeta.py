"""Snakemake `fit_zeta` job: results/stiffness.nc -> results/zeta.csv, results/zeta.nc (eq. 11)."""
from roughcontact.analysis import run_fit_zeta

snakemake = globals()["snakemake"]
run_fit_zeta(snakemake.params.cfg, snakemake.input.stiffness, snakemake.output.csv, snakemake.output.nc,
             log=snakemake.log[0])
