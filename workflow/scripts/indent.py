"""Snakemake `indent` job: the runs of one combination and block of seeds (jobs.batch; one run
with batch 1) -> results/runs/<combo>/seed<seed>.nc, one file and one log per run.

The work is done by roughcontact.study.runs.indent.run_batch, one run_indent per run (the
function behind `roughcontact indent` on the command line). A failed run is one line on the
console; its log has the traceback.
"""
import os
import sys

from roughcontact.study.runs.indent import run_batch

snakemake = globals()["snakemake"]  # injected by Snakemake's script: directive
try:
    run_batch(snakemake.params.settings, snakemake.output, logs=snakemake.log)
except Exception as err:  # noqa: BLE001  (every failure: one line here, the details in its log)
    log = getattr(err, "run_log", None)
    line = f"Error in rule {snakemake.rule}: {type(err).__name__}: {err}" + (f" (log: {log})" if log else "")
    # One write of the line with its newline: jobs running side by side share the console,
    # and a pipe keeps a single write of under 4 kB whole (sys.exit(text) writes the text and
    # its newline apart, and two jobs' lines were seen joined).
    os.write(2, (line + "\n").encode(errors="replace"))
    sys.exit(1)
