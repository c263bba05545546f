"""Snakemake `claims` job: crossover and zeta tables -> results/claims.csv and claims.html (the paper's claims, verdicts)."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import claims

snakemake = globals()["snakemake"]
inputs = snakemake.input
with log_to(snakemake.log[0]):
    claims.run(snakemake.params.cfg, crossover=inputs.crossover, replicates=inputs.replicates, zeta=inputs.zeta,
               zeta_replicates=inputs.zeta_replicates, stiffness=inputs.stiffness, exponents=inputs.exponents,
               csv=snakemake.output.csv, html=snakemake.output.html, pull_off=inputs.pull_off or None,
               stickiness=inputs.stickiness or None, tangential=inputs.tangential or None, tables=list(inputs.tables))
