"""The grid error of an ensemble mean, measured on the same physical surfaces on two or three grids.

A study on the ``n × n`` grid with ``grid.realization_of: N`` presses the surfaces of the ``N``
grid seen on its own (their Fourier modes ``|k| < n/2``; :func:`roughcontact.surfaces.self_affine`),
so that, seed by seed, it and the study on ``N`` press the same physical surfaces. Per sphere
combination and load:

* ``grid_error = k̄_n/k̄_N − 1`` (ensemble means over the common seeds), with a percentile
  bootstrap interval whose resamples draw the *same* seeds on both grids (paired: the grid error
  of one realisation is far smaller than the scatter between realisations);
* ``band`` the half-width of the bootstrap interval of ``k̄_N`` relative to ``k̄_N`` (the
  sampling error of the finer ensemble);
* ``grid_resolved``: ``|grid_error| ≤ fraction · band`` — a load is resolved when its grid error
  is a small part of its sampling error, measured, not guessed from a cell count.

With three grids ``n₁ < n₂ < n₃`` (ratio ``r = n₃/n₂``) and a monotone sequence,
:func:`richardson` extrapolates ``k̄`` to the infinitely fine grid (L. F. Richardson, Phil. Trans.
R. Soc. A 226, 299 (1927), doi:10.1098/rsta.1927.0008) with the observed order
``p = ln((k₂ − k₁)/(k₃ − k₂))/ln r`` (for grids of equal ratios); otherwise the difference of the two
finest grids stands as the error. Forces are ``F/(E* L²)``.
"""
from __future__ import annotations

import math
import sys

import numpy as np

from ...errors import MergeError

from .ensemble import combinations, resolved
from ..config.settings import StudySettings
from .statistics import bootstrap_indices, interval

__all__ = ["grid_error", "richardson", "run_grid_error", "run_study_grid_error", "GRID_ERROR_FRACTION"]

#: a load is resolved when its grid error is at most this fraction of the finer ensemble's band
GRID_ERROR_FRACTION = 0.5


def richardson(k_coarse, k_medium, k_fine, ratio: float):
    """``(k_extrapolated, order)`` from three grids of equal refinement *ratio* (> 1), elementwise;
    NaN where the sequence is not monotone (the differences change sign) or does not converge
    (the finer difference is not smaller)."""
    k1, k2, k3 = (np.asarray(k, dtype=float) for k in (k_coarse, k_medium, k_fine))
    d12, d23 = k2 - k1, k3 - k2
    with np.errstate(divide="ignore", invalid="ignore"):
        q = d12 / d23
        ok = (q > 1.0) & np.isfinite(q)
        order = np.where(ok, np.log(np.where(ok, q, 2.0)) / math.log(ratio), np.nan)
        extrapolated = np.where(ok, k3 + d23 / (ratio ** np.where(ok, order, 1.0) - 1.0), np.nan)
    return extrapolated, order


def _combinations(ds):
    """The axes of every combination of *ds* (:func:`ensemble.combinations`)."""
    return [where for where, _ in combinations(ds)]


def grid_error(coarse, fine, *, min_cells: int, bootstrap: int, confidence: float,
               fraction: float = GRID_ERROR_FRACTION):
    """One row per sphere combination and load of the merged sphere Datasets *coarse* (a study on
    ``n`` with ``grid.realization_of`` = the *fine* study's grid) and *fine*, over their common
    seeds and the loads of both (module docstring)."""
    import pandas as pd

    seeds = sorted(set(coarse["seed"].values.tolist()) & set(fine["seed"].values.tolist()))
    if len(seeds) < 2:
        raise ValueError(f"the two studies share {len(seeds)} seed(s); the grid error needs at least 2")
    if not np.allclose(coarse["force"].values, fine["force"].values, rtol=1e-12, atol=0):
        raise ValueError("the two studies have different load paths")
    indices = bootstrap_indices(len(seeds), bootstrap)
    force = fine["force_normalized"].values
    rows = []
    for pick in _combinations(fine):
        if not all(v in coarse[a].values.tolist() for a, v in pick.items()):
            continue
        kc = coarse["stiffness"].sel(pick).sel(seed=seeds).transpose("seed", "force").values
        kf = fine["stiffness"].sel(pick).sel(seed=seeds).transpose("seed", "force").values
        cells_c = coarse["contact_cells"].sel(pick).sel(seed=seeds).mean("seed").values
        cells_f = fine["contact_cells"].sel(pick).sel(seed=seeds).mean("seed").values
        error = kc.mean(0) / kf.mean(0) - 1
        boot_error = kc[indices].mean(1) / kf[indices].mean(1) - 1          # (resamples, force), paired
        boot_fine = kf[indices].mean(1) / kf.mean(0) - 1
        for j in range(force.size):
            low, high = interval(boot_error[:, j], confidence)
            b_low, b_high = interval(boot_fine[:, j], confidence)
            band = 0.5 * (b_high - b_low)
            rows.append({**pick, "force_normalized": float(force[j]), "contact_cells_coarse": float(cells_c[j]),
                         "contact_cells_fine": float(cells_f[j]), "grid_error": float(error[j]),
                         "grid_error_ci_low": low, "grid_error_ci_high": high, "band": band,
                         "cell_resolved": bool(resolved(cells_c[j], min_cells)),
                         "grid_resolved": bool(abs(error[j]) <= fraction * band)})
    return pd.DataFrame(rows)


def run_study_grid_error(study, fine_nc, coarse_nc, out_csv) -> None:
    """``grid_error`` rule: the study's ``stiffness.nc`` (*fine_nc*) against its companion's on
    ``grid.coarse`` (*coarse_nc*, the same surfaces) -> ``grid_error.csv`` (an empty table without
    sphere runs), with the study's fit windows (``fit.zeta``)."""
    import pandas as pd

    from ..files.io import read_groups, write_csv

    zeta = StudySettings.of(study).fit.zeta
    fine, coarse = read_groups(fine_nc), read_groups(coarse_nc)
    table = (grid_error(coarse["sphere"], fine["sphere"], min_cells=zeta.min_cells, bootstrap=zeta.bootstrap,
                        confidence=zeta.confidence) if "sphere" in fine and "sphere" in coarse else pd.DataFrame())
    write_csv(table, out_csv)


def run_grid_error(coarse_results, fine_results, out_csv, *, fraction: float = GRID_ERROR_FRACTION) -> None:
    """The grid error of two studies' ``results`` directories (``stiffness.nc`` each; the fit
    settings of the finer study's configuration) written to *out_csv*."""
    import json
    from pathlib import Path

    import xarray as xr

    from ..files.io import read_groups, write_csv

    for directory in (coarse_results, fine_results):
        if not (Path(directory) / "stiffness.nc").is_file():
            raise MergeError(f"{directory}: no stiffness.nc (the results directory of a study, after its merge rule)")
    coarse, fine = (read_groups(Path(d) / "stiffness.nc") for d in (coarse_results, fine_results))
    if "sphere" not in coarse or "sphere" not in fine:
        raise MergeError(f"{coarse_results} and {fine_results}: the grid error needs sphere runs in both studies")
    with xr.open_datatree(Path(fine_results) / "stiffness.nc", engine="netcdf4") as tree:
        zeta = StudySettings.of(json.loads(tree.attrs["config"])).fit.zeta
    table = grid_error(coarse["sphere"], fine["sphere"], min_cells=zeta.min_cells,
                       bootstrap=zeta.bootstrap, confidence=zeta.confidence, fraction=fraction)
    write_csv(table, out_csv)


def main(argv=None) -> int:
    """``python -m roughcontact.study.analysis.grid_error COARSE FINE -o grid_error.csv``."""
    import argparse

    parser = argparse.ArgumentParser(prog="python -m roughcontact.study.analysis.grid_error",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("coarse", help="results directory of the study on n with grid.realization_of = N")
    parser.add_argument("fine", help="results directory of the study on N")
    parser.add_argument("-o", "--output", required=True, help="CSV to write")
    parser.add_argument("--fraction", type=float, default=GRID_ERROR_FRACTION,
                        help=f"resolved where |grid error| <= this fraction of the band (default {GRID_ERROR_FRACTION})")
    args = parser.parse_args(argv)
    try:
        run_grid_error(args.coarse, args.fine, args.output, fraction=args.fraction)
    except (MergeError, ValueError) as err:   # bad input: one line, nothing written
        print(f"grid_error: {err}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
