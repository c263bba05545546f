"""Snakemake `claims` job: crossover and zeta tables -> results/claims.csv and claims.html (the paper's claims, verdicts)."""
from roughcontact.study.report.claims import run_claims
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
with log_to(snakemake.log[0]):
    run_claims(snakemake.params.cfg, snakemake.input.crossover, snakemake.input.replicates, snakemake.input.zeta,
               snakemake.input.zeta_replicates, snakemake.input.stiffness, snakemake.input.exponents,
               snakemake.output.csv, snakemake.output.html, pull_off_csv=snakemake.input.pull_off or None,
               stickiness_csv=snakemake.input.stickiness or None, tangential_nc=snakemake.input.tangential or None,
               tables=list(snakemake.input.tables))
