"""Grid study of the real contact area of a rough sphere: how ``A(F)`` at fixed loads converges with n.

One physical surface per seed (a self-affine sphere with a short-wavelength cutoff ``λ_c``, so
that every grid carries the same modes: ``surfaces.rough_sphere(..., realization_of=N)`` with N
the finest grid) is pressed on the free half-space on grids of ``n`` points per side at the
same loads. Per load and grid it records the contact cells, the number of patches (edge-connected,
:func:`roughcontact.bem.patches.contact_patches`), the area ``A = cells (L/n)²`` and the ratio
``A_n/A_N`` to the finest grid of the same seed. The resolution rule of the area claims
(:mod:`roughcontact.study.claims.area`) is read off this table: the smallest number of cells per
cutoff wavelength, of contact cells and of cells per patch at which ``|A_n/A_N − 1|`` stays below
the claims' tolerance (``--tolerance``, default 0.10) at every load and seed. The numbers of the
last run are in ``docs/guide/area.md``.

Usage::

    python benchmarks/area_grid_study.py [--n 65 129 257 513] [--cutoff 0.0625] [--seeds 0 1]
        [--forces 1e-6 2e-2 12] [--csv area_grid_study.csv]
    python benchmarks/area_grid_study.py --compare-rules a.csv b.csv c.csv   # which count is the rule

Defaults: R = 0.5, H = 0.7, h_rms = 9e-3, L = 1, E* = 1 (the paper's sphere), λ_c = L/16.
"""

from __future__ import annotations

import argparse
import csv
import os
import sys
import time

import numpy as np

from roughcontact import bem, surfaces
from roughcontact.bem.patches import contact_patches


def run(n: int, finest: int, seed: int, forces, args):
    """Rows of one grid and seed: force, cells, patches, area."""
    heights = surfaces.rough_sphere(n, radius=args.radius, hurst=args.hurst, h_rms=args.h_rms, length=1.0,
                                    seed=seed, cutoff=args.cutoff, realization_of=finest)
    rows = []
    for state in bem.iter_load_path(heights, forces, length=1.0, e_star=1.0, periodic=False, tol=args.tol):
        cells = int(np.count_nonzero(state.contact))
        patches = contact_patches(state.contact).count
        rows.append({"n": n, "seed": seed, "force": float(state.force), "contact_cells": cells,
                     "patches": patches, "largest_patch": contact_patches(state.contact).largest,
                     "contact_area": cells / n**2, "cells_per_wavelength": args.cutoff * n})
    return rows


def ensemble_errors(rows):
    """Per grid below the finest and per load: the seed-mean cells, cells per patch
    (mean cells / mean patches), cells per cutoff wavelength and the relative error of the
    seed-mean area against the finest grid's, ``mean A_n / mean A_N - 1``."""
    finest = max(r["n"] for r in rows)
    rows = [{**r, "force": float(f"{r['force']:.6g}")} for r in rows]   # the same load on every grid
    out = []
    for n in sorted({r["n"] for r in rows if r["n"] < finest}):
        for force in sorted({r["force"] for r in rows}):
            here = [r for r in rows if r["n"] == n and r["force"] == force]
            ref = [r for r in rows if r["n"] == finest and r["force"] == force]
            cells = np.mean([r["contact_cells"] for r in here])
            out.append({"n": n, "force": force, "cells": cells,
                        "cells_per_patch": cells / max(np.mean([r["patches"] for r in here]), 1.0),
                        "cells_per_wavelength": here[0]["cells_per_wavelength"],
                        "error": np.mean([r["contact_area"] for r in here])
                        / np.mean([r["contact_area"] for r in ref]) - 1})
    return out


def threshold(errors, key: str, tolerance: float) -> float:
    """The smallest value of *key* at or above which every row's ``|error|`` is within *tolerance*
    (inf: none)."""
    bad = [e[key] for e in errors if abs(e["error"]) > tolerance]
    good = sorted(e[key] for e in errors if abs(e["error"]) <= tolerance and e[key] > max(bad, default=-1.0))
    return good[0] if good else float("inf")


def summary_lines(rows, tolerance: float):
    """The ensemble-mean table and the thresholds of the resolution rule."""
    errors = ensemble_errors(rows)
    yield (f"{'n':>5} {'cells/lambda_c':>14} {'F/(E*L^2)':>10} {'cells':>9} {'cells/patch':>11} "
           f"{'<A_n>/<A_N> - 1':>15}")
    for e in errors:
        yield (f"{e['n']:5d} {e['cells_per_wavelength']:14.1f} {e['force']:10.3g} {e['cells']:9.1f} "
               f"{e['cells_per_patch']:11.1f} {e['error']:+15.3f}")
    for w in sorted({e["cells_per_wavelength"] for e in errors}):
        sub = [e for e in errors if abs(e["cells_per_wavelength"] - w) < 1e-9]
        yield (f"cells per cutoff wavelength {w:.1f}: |error| <= {tolerance:g} from "
               f"{threshold(sub, 'cells', tolerance):.0f} contact cells, from "
               f"{threshold(sub, 'cells_per_patch', tolerance):.1f} cells per patch "
               f"(largest |error| there: {max((abs(e['error']) for e in sub), default=float('nan')):.3f})")


def _wavelength_key(e) -> float:
    """The rule's λ_s/Δ key of a row: the power of 2 nearest its cells per wavelength (2 at least)."""
    return float(2 ** max(1, round(np.log2(max(e["cells_per_wavelength"], 2.0)))))


def compare_rules(studies: dict, tolerance: float):
    """Which count predicts the area's error: per λ_s/Δ, the threshold in contact cells against the
    threshold in cells per patch, each taken from all studies but one and applied to the one left
    out (*studies*: ``{name: rows}``). Yields one line per study and rule: loads accepted, of them
    beyond *tolerance*, and the largest error there."""
    errors = {name: [{**e, "key": _wavelength_key(e)} for e in ensemble_errors(rows)] for name, rows in studies.items()}
    for key in ("cells", "cells_per_patch"):
        accepted = failed = 0
        for name, test in errors.items():
            train = [e for other, rows in errors.items() if other != name for e in rows]
            limits = {w: threshold([e for e in train if e["key"] == w], key, tolerance)
                      for w in {e["key"] for e in test}}
            ok = [e for e in test if e[key] >= limits[e["key"]]]
            bad = [abs(e["error"]) for e in ok if abs(e["error"]) > tolerance]
            accepted, failed = accepted + len(ok), failed + len(bad)
            yield (f"rule on {key}, thresholds from the others, applied to {name}: {len(ok)} loads accepted, "
                   f"{len(bad)} beyond {tolerance:g} (largest {max(bad, default=0.0):.3f})")
        yield f"rule on {key}: {accepted} loads accepted in all, {failed} beyond {tolerance:g}"


def _read_rows(path):
    with open(path) as handle:
        return [{k: (float(v) if k in ("force", "contact_area", "cells_per_wavelength") else int(v))
                 for k, v in r.items()} for r in csv.DictReader(handle)]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[65, 129, 257, 513])
    parser.add_argument("--cutoff", type=float, default=1 / 16, help="short-wavelength cutoff / L (default 1/16)")
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1])
    parser.add_argument("--forces", type=float, nargs=3, default=[1e-6, 2e-2, 12],
                        help="F/(E* L^2): from, to, count (log-spaced)")
    parser.add_argument("--radius", type=float, default=0.5)
    parser.add_argument("--hurst", type=float, default=0.7)
    parser.add_argument("--h-rms", type=float, default=9e-3)
    parser.add_argument("--tol", type=float, default=1e-8)
    parser.add_argument("--tolerance", type=float, default=0.10, help="relative area error called resolved")
    parser.add_argument("--csv", default="area_grid_study.csv")
    parser.add_argument("--from-csv", action="store_true", help="only summarise the rows of --csv")
    parser.add_argument("--compare-rules", nargs="+", metavar="CSV",
                        help="the CSVs of several studies: contact cells against cells per patch as the "
                             "resolution rule, each study left out in turn")
    args = parser.parse_args(argv)
    if args.compare_rules:
        for line in compare_rules({path: _read_rows(path) for path in args.compare_rules}, args.tolerance):
            print(line)
        return 0
    if args.from_csv:
        rows = _read_rows(args.csv)
        for line in summary_lines(rows, args.tolerance):
            print(line)
        return 0
    forces = np.geomspace(args.forces[0], args.forces[1], int(args.forces[2]))
    finest = max(args.n)
    print(f"load average before: {os.getloadavg()[0]:.2f}; cutoff = {args.cutoff:g} L; grids {args.n}", flush=True)
    rows = []
    for n in sorted(args.n):
        for seed in args.seeds:
            tick = time.perf_counter()
            rows += run(n, finest, seed, forces, args)
            print(f"n = {n}, seed {seed}: {time.perf_counter() - tick:.1f} s", flush=True)
            with open(args.csv, "w", newline="") as handle:
                writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
                writer.writeheader()
                writer.writerows(rows)
    for line in summary_lines(rows, args.tolerance):
        print(line)
    print(f"load average after: {os.getloadavg()[0]:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
