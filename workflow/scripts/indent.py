"""Snakemake `indent` job: the runs of one combination and block of seeds (jobs.batch; one run
with batch 1) -> results/runs/<combo>/seed<seed>.nc, one file and one log per run
(roughcontact.study.rules.indent). A failed run is one line on the console; its log has the
traceback.
"""
import os
import sys

from roughcontact.study.rules import indent

snakemake = globals()["snakemake"]  # injected by Snakemake's script: directive
try:
    indent.run(snakemake.params.settings, outputs=snakemake.output, logs=snakemake.log)
except Exception as err:  # noqa: BLE001  (every failure: one line here, the details in its log)
    # One write of the line with its newline: jobs running side by side share the console,
    # and a pipe keeps a single write of under 4 kB whole (sys.exit(text) writes the text and
    # its newline apart, and two jobs' lines were seen joined).
    os.write(2, (indent.failure_line(snakemake.rule, err) + "\n").encode(errors="replace"))
    sys.exit(1)
