"""Snakemake `crossover` job: stiffness.nc -> results/zeta.csv, zeta.nc (eq. 11) and results/crossover.csv,
crossover.nc (eq. 16 fitted, F_tr with a 95 % interval), each table with its report page."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import crossover

snakemake = globals()["snakemake"]
out = snakemake.output
with log_to(snakemake.log[0]):
    crossover.run(snakemake.params.cfg, snakemake.input.stiffness, zeta_csv=out.zeta_csv, zeta_html=out.zeta_html,
                  zeta_nc=out.zeta_nc, crossover_csv=out.csv, crossover_html=out.html, crossover_nc=out.nc)
