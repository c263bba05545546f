"""End-to-end benchmark: a preset through ``snakemake --cores 2`` in a fresh directory.

Runs the whole workflow (all indent jobs, merge, fits, figures), then the report, and
prints the wall time of each and a table of the ``indent`` jobs from Snakemake's own
per-job benchmark files (``results/benchmarks/indent/*.tsv``: wall seconds and peak
resident memory ``max_rss``), split by surface kind (sphere or flat).

Usage::

    python benchmarks/pipeline.py [--configfile presets/paper.yaml] [--cores 2] [--keep DIR]
"""

from __future__ import annotations

import argparse
import math
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import machine_lines  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


def snakemake(workdir: Path, configfile: Path, *args: str) -> float:
    """Run snakemake on the checkout's Snakefile in ``workdir``; return its wall time (s)."""
    command = [sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(workdir),
               "--configfile", str(configfile), *args]
    tick = time.perf_counter()
    result = subprocess.run(command, cwd=workdir, capture_output=True, text=True)
    seconds = time.perf_counter() - tick
    if result.returncode != 0:
        sys.exit(f"snakemake failed ({' '.join(args)}):\n{result.stderr[-3000:]}")
    return seconds


def job_table(workdir: Path) -> pd.DataFrame:
    """One row per indent job: kind (sphere/flat), wall seconds, peak RSS (MB)."""
    rows = []
    for path in sorted((workdir / "results/benchmarks/indent").glob("*.tsv")):
        record = pd.read_csv(path, sep="\t").iloc[0]
        radius = path.name.split("_R", 1)[1].split("_h", 1)[0]
        rows.append({"kind": "flat" if radius == "inf" else "sphere",
                     "seconds": float(record["s"]), "max_rss_mb": float(record["max_rss"])})
    if not rows:
        sys.exit(f"no per-job benchmark files under {workdir / 'results/benchmarks/indent'}")
    return pd.DataFrame(rows)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--configfile", type=Path, default=REPO / "presets/paper.yaml",
                        help="sweep to run (default presets/paper.yaml)")
    parser.add_argument("--cores", type=int, default=2, help="snakemake --cores (default 2)")
    parser.add_argument("--keep", type=Path, default=None,
                        help="run in this (new) directory and keep it; default: a temporary one")
    args = parser.parse_args(argv)
    configfile = args.configfile.resolve()

    for line in machine_lines([]):
        print(line)
    workdir = args.keep.resolve() if args.keep else Path(tempfile.mkdtemp(prefix="rc-pipeline-"))
    workdir.mkdir(parents=True, exist_ok=True)
    try:
        run_seconds = snakemake(workdir, configfile, "--cores", str(args.cores))
        report_seconds = snakemake(workdir, configfile, "--report", "results/report.html")
        jobs = job_table(workdir)
    finally:
        if args.keep is None:
            shutil.rmtree(workdir, ignore_errors=True)

    print(f"sweep: {configfile.relative_to(REPO) if configfile.is_relative_to(REPO) else configfile}, "
          f"snakemake --cores {args.cores}, fresh directory")
    header = (f"{'kind':>7} {'jobs':>5} | {'job s median':>12} {'max':>7} {'sum':>8} | "
              f"{'peak RSS MB median':>18} {'max':>7}")
    print(header)
    print("-" * len(header))
    for kind, group in [*jobs.groupby("kind"), ("all", jobs)]:
        print(f"{kind:>7} {len(group):5d} | {group.seconds.median():12.2f} {group.seconds.max():7.2f} "
              f"{group.seconds.sum():8.1f} | {group.max_rss_mb.median():18.0f} {group.max_rss_mb.max():7.0f}")
    print("-" * len(header))
    total = run_seconds + report_seconds
    print(f"wall time: workflow {run_seconds:.1f} s + report {report_seconds:.1f} s = {total:.1f} s "
          f"({math.floor(total / 60):.0f} min {total % 60:.0f} s); "
          f"sum of indent job times / workflow wall time = {jobs.seconds.sum() / run_seconds:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
