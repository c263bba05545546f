"""How many seeds decide the crossover force: the 95 % interval of F_tr against the seed count.

Reads a finished sweep (``results/stiffness.nc`` and ``results/zeta.csv`` of a directory run
with one sphere combination, e.g. ``presets/crossover.yaml``, 400 seeds) and recomputes the
crossover estimate of ``crossover.csv`` (:func:`roughcontact.crossover.crossover_table`: eq. 16
with free prefactors, percentile bootstrap over seeds) on

* the first N seeds, N = 25, 50, 100, … up to all of them: the half-width of the interval
  against N (it should shrink as 1/√N);
* disjoint blocks of ``--block`` seeds (default 50, the paper's ensemble size): independent
  ensembles, whose scatter of F_tr should match the width of their bootstrap intervals.

Prints one table: seeds, which seeds, F_tr, interval, half-width ``(high − low)/2`` in % of
F_tr, and eq. 17 with its verdicts (fitted ζ, and ζ = 1.7/(H+1)). The fitted ζ is the one of the
whole run (``zeta.csv``) for every subset, so only F_tr and its interval are independent between
the disjoint blocks, not the verdicts against eq. 17 with the fitted ζ.

Usage::

    snakemake --cores 2 --configfile presets/crossover.yaml --directory results/crossover
    python benchmarks/seeds.py --configfile presets/crossover.yaml --directory results/crossover
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd

from roughcontact.study.config import resolve as config
from roughcontact.study.files import io as study_io
from roughcontact.study.analysis import crossover

COLUMNS = ["Ftr_measured", "Ftr_ci_low", "Ftr_ci_high", "Ftr_pred_fit", "verdict_fit",
           "Ftr_pred_estimate", "verdict_estimate"]


def estimate(groups: dict, zeta: pd.DataFrame, cfg: dict, seeds: np.ndarray) -> dict:
    """The crossover row of :func:`~roughcontact.crossover.crossover_table` on the seeds ``seeds``."""
    subset = {kind: ds.isel(seed=seeds) for kind, ds in groups.items()}
    table, _ = crossover.crossover_table(subset, zeta, cfg)
    if len(table) != 1:
        raise SystemExit(f"expected one sphere combination, found {len(table)}")
    row = table.iloc[0]
    half = (row["Ftr_ci_high"] - row["Ftr_ci_low"]) / 2 / row["Ftr_measured"]
    return {**{c: row[c] for c in COLUMNS}, "half_width_percent": 100 * half}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--configfile", type=Path, default=Path("presets/crossover.yaml"))
    parser.add_argument("--directory", type=Path, default=Path("results/crossover"))
    parser.add_argument("--block", type=int, default=50, help="seeds per disjoint block")
    args = parser.parse_args()
    cfg = config.resolve_config(config.load_config(args.configfile))
    stiffness = args.directory / "results" / "stiffness.nc"
    if not stiffness.exists():
        raise SystemExit(f"{stiffness} not found: run the sweep first, e.g. snakemake --cores 2 "
                         f"--configfile {args.configfile} --directory {args.directory}")
    groups = study_io.read_groups(stiffness)
    if "sphere" not in groups:
        raise SystemExit(f"{stiffness} holds no sphere runs: the crossover needs spheres")
    zeta = pd.read_csv(args.directory / "results" / "zeta.csv")
    total = groups["sphere"].sizes["seed"]
    rows = []
    counts = sorted({n for n in (25, 50, 100, 200, 400, 800) if n < total} | {total})
    for n in counts:
        rows.append({"seeds": n, "which": f"first {n}", **estimate(groups, zeta, cfg, np.arange(n))})
    for start in range(0, total - args.block + 1, args.block):
        which = np.arange(start, start + args.block)
        rows.append({"seeds": args.block, "which": f"{start}..{start + args.block - 1}",
                     **estimate(groups, zeta, cfg, which)})
    table = pd.DataFrame(rows)
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(table.to_string(index=False, float_format=lambda x: f"{x:.3g}"))
    blocks = table[table["which"].str.contains(r"\.\.")]
    if len(blocks) > 1:
        log_ftr = np.log(blocks["Ftr_measured"])
        print(f"\n{len(blocks)} disjoint blocks of {args.block} seeds: F_tr scatters by "
              f"{100 * log_ftr.std(ddof=1):.0f} % (standard deviation of ln F_tr); the mean bootstrap "
              f"half-width is {blocks['half_width_percent'].mean():.0f} %, "
              f"i.e. {blocks['half_width_percent'].mean() / 1.96:.0f} % per standard deviation")


if __name__ == "__main__":
    main()
