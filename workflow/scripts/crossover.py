"""Snakemake `crossover` job: ensemble + zeta -> results/crossover.csv (eqs. 16, 17)."""
from roughcontact.analysis import run_crossover

snakemake = globals()["snakemake"]
run_crossover(snakemake.params.cfg, snakemake.input.ensemble, snakemake.input.zeta, snakemake.output.csv,
              log=snakemake.log[0])
