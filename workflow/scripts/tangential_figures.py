"""Snakemake `tangential_figures` and `partial_slip_figures` jobs: tangential.nc, tangential.csv -> figures."""
from roughcontact.study.files.logs import log_to
from roughcontact.study.rules import tangential_figures

snakemake = globals()["snakemake"]
out = snakemake.output
with log_to(snakemake.log[0]):
    tangential_figures.run(snakemake.params.cfg, nc=snakemake.input.nc, csv=snakemake.input.csv,
                           ratio=out.get("ratio"), slip=out.get("slip"), micro_slip=out.get("micro_slip"))
