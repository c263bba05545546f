"""Snakemake `indent` job: one (H, R, h_rms, seed) -> results/runs/...nc.

The work is done by roughcontact.study.runs.indent.run_indent, the same function behind
`roughcontact indent` on the command line.
"""
from roughcontact.study.runs.indent import run_indent

snakemake = globals()["snakemake"]  # injected by Snakemake's script: directive
run_indent(snakemake.params.settings, snakemake.output.run, log=snakemake.log[0])
