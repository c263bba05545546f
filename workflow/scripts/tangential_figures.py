"""Snakemake `tangential_figures` and `partial_slip_figures` jobs: tangential.nc, tangential.csv -> figures."""
from roughcontact.study.report.tangential import make_tangential_figures
from roughcontact.study.files.logs import log_to

snakemake = globals()["snakemake"]
out = snakemake.output
with log_to(snakemake.log[0]):
    make_tangential_figures(snakemake.params.cfg, snakemake.input.nc, snakemake.input.csv,
                            out.get("ratio"), out.get("slip"), out.get("micro_slip"))
