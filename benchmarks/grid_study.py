"""Speed at scale: one 1025² flat load path and one 2049² rough-sphere load path, with stiffness.

The two legs are the unit of work of the large presets: (a) a nominally flat self-affine
surface on the periodic half-space (``presets/zeta.yaml`` with ``grid.n = 1025``: 13 loads
F/(E* L²) = 10⁻⁶ … 3·10⁻³), and (b) a rough sphere on the free half-space
(``presets/paper-fine.yaml``: 2049², R = 0.5, H = 0.7, h_rms = 9·10⁻³, 23 loads
10⁻⁶ … 5.6·10⁻⁴). Each leg runs ``bem.iter_load_path`` and the exact tangent stiffness
``bem.stiffness`` at every load, as the ``indent`` job does.

Prints, per leg: n, loads, Polonsky–Keer iterations, FFT convolutions (calls of the grid
operators: ``fft`` double precision, ``fft32`` single precision, counted separately for the
solves and the stiffness ``k``) and dense matrix products, and the seconds of solve and
stiffness; ``--detail`` adds one line per load. Seconds on a
shared machine scatter, so compare runs by the counts, or by time ratios of runs made in
the same session; the load average is printed before and after.

Usage::

    python benchmarks/grid_study.py [--legs flat sphere] [--hurst 0.3 0.7] [--seed 1] [--repeat 1] [--detail]

To compare two versions of the package in one session, run this script alternately with each
on ``PYTHONPATH`` (an older version without single-precision convolutions shows ``fft32 = 0``).
"""

from __future__ import annotations

import argparse
import collections
import contextlib
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import machine_lines

from roughcontact import bem
from roughcontact import surfaces
from roughcontact.bem import operators

#: Counted calls, by phase ("solve" or "stiffness") and kind ("fft" or "dense").
COUNTS: collections.Counter = collections.Counter()
_PHASE = ["solve"]


def _counted(cls, kind, method="__call__"):
    """Wrap ``cls.method`` so that every call adds one to ``COUNTS[(phase, kind)]``."""
    original = getattr(cls, method, None)
    if original is None:  # an older version of the package
        return

    def call(self, *args, **kwargs):
        COUNTS[(_PHASE[0], kind)] += 1
        return original(self, *args, **kwargs)

    setattr(cls, method, call)


_counted(operators.FreeSpaceOperator, "fft")
_counted(operators.PeriodicOperator, "fft")
_counted(operators.FreeSpaceOperator, "fft32", "single")
_counted(operators.PeriodicOperator, "fft32", "single")
_counted(operators.DenseOperator, "dense")


@contextlib.contextmanager
def phase(name):
    """Attribute the operator calls inside the block to ``name``."""
    _PHASE[0] = name
    try:
        yield
    finally:
        _PHASE[0] = "solve"


def legs(args):
    """The legs to run: name, heights, forces, periodic."""
    if "flat" in args.legs:
        for hurst in args.hurst:
            yield (f"flat H={hurst:g}",
                   surfaces.self_affine(args.flat_n, hurst=hurst, h_rms=9e-3, seed=args.seed),
                   np.geomspace(1e-6, 3e-3, 13), True)
    if "sphere" in args.legs:
        yield ("sphere", surfaces.rough_sphere(args.sphere_n, radius=0.5, hurst=0.7, h_rms=9e-3, seed=args.seed),
               np.geomspace(1e-6, 5.62341325e-4, 23), False)


def run_leg(heights, forces, periodic, tol, detail):
    """Load path with stiffness; totals and the per-load rows."""
    rows = []
    totals = collections.Counter()
    path = bem.iter_load_path(heights, forces, length=1.0, e_star=1.0, periodic=periodic, tol=tol)
    while True:
        before = COUNTS.copy()
        tick = time.perf_counter()
        state = next(path, None)
        if state is None:
            break
        solve_seconds = time.perf_counter() - tick
        tick = time.perf_counter()
        with phase("stiffness"):
            stiffness = bem.stiffness(state)
        stiffness_seconds = time.perf_counter() - tick
        spent = COUNTS - before
        row = {"force": state.force, "cells": int(state.contact.sum()), "it": state.iterations,
               "fft": spent[("solve", "fft")], "fft32": spent[("solve", "fft32")],
               "dense": spent[("solve", "dense")], "k_fft": spent[("stiffness", "fft")],
               "k_dense": spent[("stiffness", "dense")], "solve": solve_seconds,
               "stiff": stiffness_seconds, "depth": state.depth, "k": stiffness}
        rows.append(row)
        totals.update({key: row[key] for key in ("it", "fft", "fft32", "dense", "k_fft", "k_dense", "solve",
                                                 "stiff")})
        if detail:
            print(f"  {row['force']:9.3g} {row['cells']:7d} {row['it']:5d} {row['fft']:5d} {row['fft32']:5d} "
                  f"{row['dense']:6d} "
                  f"{row['k_fft']:5d} {row['k_dense']:6d} {row['solve']:8.3f} {row['stiff']:8.3f}   "
                  f"d={row['depth']:.12e} k={row['k']:.12e}", flush=True)
    return totals, rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--legs", nargs="+", choices=["flat", "sphere"], default=["flat", "sphere"])
    parser.add_argument("--hurst", type=float, nargs="+", default=[0.3, 0.7],
                        help="Hurst exponents of the flat leg (default 0.3 0.7)")
    parser.add_argument("--repeat", type=int, default=1,
                        help="runs of each leg; the seconds are the fastest run's (default 1)")
    parser.add_argument("--seed", type=int, default=1, help="surface seed (default 1)")
    parser.add_argument("--flat-n", type=int, default=1025, help="grid of the flat leg (default 1025)")
    parser.add_argument("--sphere-n", type=int, default=2049, help="grid of the sphere leg (default 2049)")
    parser.add_argument("--tol", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    parser.add_argument("--detail", action="store_true", help="one line per load")
    args = parser.parse_args(argv)

    for line in machine_lines([]):
        print(line)
    print("load average before: {:.2f} {:.2f} {:.2f}".format(*os.getloadavg()))
    header = (f"{'leg':>10} {'n':>5} {'loads':>5} {'it':>6} {'fft':>6} {'fft32':>6} {'dense':>7} {'k fft':>6} "
              f"{'k dense':>7} | {'solve s':>8} {'stiff s':>8} {'total s':>8}")
    table = []
    for name, heights, forces, periodic in legs(args):
        if args.detail:
            print(f"{name}: {'F':>9} {'cells':>7} {'it':>5} {'fft':>5} {'fft32':>5} {'dense':>6} {'k fft':>5} "
                  f"{'k dense':>6} {'solve s':>8} {'stiff s':>8}")
        runs = [run_leg(heights, forces, periodic, args.tol, args.detail) for _ in range(args.repeat)]
        totals, rows = min(runs, key=lambda run: run[0]["solve"] + run[0]["stiff"])
        table.append(f"{name:>10} {heights.shape[0]:5d} {len(rows):5d} {totals['it']:6d} {totals['fft']:6d} "
                     f"{totals['fft32']:6d} "
                     f"{totals['dense']:7d} {totals['k_fft']:6d} {totals['k_dense']:7d} | "
                     f"{totals['solve']:8.2f} {totals['stiff']:8.2f} {totals['solve'] + totals['stiff']:8.2f}")
    print(header)
    print("-" * len(header))
    for line in table:
        print(line)
    print("load average after: {:.2f} {:.2f} {:.2f}".format(*os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
