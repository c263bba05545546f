"""The grid error of an ensemble mean, measured on the same physical surfaces on two or three grids.

A study on the ``n × n`` grid with ``grid.realization_of: N`` presses the surfaces of the ``N``
grid seen on its own (their Fourier modes ``|k| < n/2``; :func:`roughcontact.surfaces.self_affine`),
so that, seed by seed, it and the study on ``N`` press the same physical surfaces. Per sphere
combination and load:

* ``grid_error = g = k̄_n/k̄_N − 1`` (ensemble means over the common seeds), with a percentile
  bootstrap interval ``[g₋, g₊]`` whose resamples draw the *same* seeds on both grids (paired: the
  grid error of one realisation is far smaller than the scatter between realisations);
* ``grid_error_estimate``, the estimate ``ê`` of the finer grid's own error ``|k̄_N/k̄_∞ − 1|``
  (below), with ``grid_ratio`` ``r = N/n``;
* ``band`` the half-width of the bootstrap interval of ``k̄_N`` relative to ``k̄_N`` (the
  sampling error of the finer ensemble);
* ``grid_resolved``: ``ê ≤ fraction · band`` — a load is resolved when its grid error is a small
  part of its sampling error, measured, not guessed from a cell count.

The estimate (the rule of the study's grid error; ``grid.coarse``)::

    G = max(|g₋|, |g₊|),    a = G/(r^p − 1),    ê = F_s · a/(1 − a)       (∞ where a ≥ 1)

Richardson's error estimate (:func:`estimate`; the grid convergence index of P. J. Roache,
J. Fluids Eng. 116, 405 (1994), doi:10.1115/1.2910291) applied to the far end ``G`` of the
paired interval of the difference, not to ``|g|``: the grid error of an ensemble mean is mostly
the mean of per-seed errors of either sign (the contact moves between asperities as the grid
refines), so ``g`` changes sign from load to load and the twice finer grid's difference is not
``g/r^p`` load by load; ``G`` bounds its magnitude at the study's confidence. Measured
2026-11-27 on ``presets/grid-error-calibration.yaml`` (the default study's H, R, h_rms and
loads; 97², 193² and the reference 385², the same surfaces, 6 seeds): the rms of ``g`` over
the loads with ≥ 20 coarse contact cells falls with the grid at an order 1.0–1.4 (and 0.3–0.5
below 20 cells, where the finer grid resolves new asperities), so ``p = 1``
(:data:`GRID_ERROR_ORDER`); with it ``ê`` bounds ``|k̄_n/k̄_2n − 1|`` at 42 of the 44 loads with
≥ 20 study cells for ``F_s`` = 0.75 or 1, and at 41 for 0.5 or 0.6, so ``F_s = 0.75``
(:data:`GRID_ERROR_SAFETY`, the smallest that keeps ≥ 95 %). The raw ``|g|`` bounds it at
28 of those 44 loads only. The held-out validation (``presets/grid-error-validation.yaml``,
:mod:`roughcontact.study.analysis.grid_error_validation`) is in docs/guide/pipeline.md.

With three grids ``n₁ < n₂ < n₃`` (ratio ``r = n₃/n₂``) and a monotone sequence,
:func:`richardson` extrapolates ``k̄`` to the infinitely fine grid (L. F. Richardson, Phil. Trans.
R. Soc. A 226, 299 (1927), doi:10.1098/rsta.1927.0008) with the observed order
``p = ln((k₂ − k₁)/(k₃ − k₂))/ln r`` (for grids of equal ratios); otherwise the difference of the two
finest grids stands as the error. Forces are ``F/(E* L²)``.
"""
from __future__ import annotations

import dataclasses
import math
import sys

import numpy as np

from ...errors import MergeError

from .ensemble import combinations, resolved
from ..config.settings import StudySettings
from ..files.io import REASON
from .statistics import bootstrap_indices, interval

__all__ = ["grid_error", "richardson", "estimate", "run_grid_error", "GridErrorStatement", "statement",
           "NO_COMPANION", "GRID_ERROR_FRACTION",
           "GRID_ERROR_ORDER", "GRID_ERROR_SAFETY"]

#: a load is resolved when its grid error is at most this fraction of the finer ensemble's band
GRID_ERROR_FRACTION = 0.5
#: the convergence order p of the ensemble-mean stiffness in the cell size L/n that the study's
#: estimate assumes (measured on presets/grid-error-calibration.yaml, module docstring)
GRID_ERROR_ORDER = 1.0
#: the factor F_s of the study's estimate on the far end of the difference's interval (module docstring)
GRID_ERROR_SAFETY = 0.75


def estimate(g, ratio: float, *, order: float = GRID_ERROR_ORDER, safety: float = GRID_ERROR_SAFETY):
    """The grid error of the finer grid from the coarser grid's difference (Richardson's error estimate).

    With ``k_n = k_∞ + C (L/n)^p`` on the finer grid ``n`` and the coarser ``n_c = n/r``,
    ``k_{n_c} − k_n = (r^p − 1)(k_n − k_∞)``; in terms of ``g = k_{n_c}/k_n − 1``::

        a = g/(r^p − 1),     k_n/k_∞ − 1 = a/(1 − a),     ê = F_s |a/(1 − a)|

    (the grid convergence index of P. J. Roache, J. Fluids Eng. 116, 405 (1994),
    doi:10.1115/1.2910291, on the ensemble mean; ``F_s = 1`` and the true order give the exact
    error of such a sequence).

    Parameters
    ----------
    g : array_like
        ``k̄_{n_c}/k̄_n − 1`` at each load (1).
    ratio : float
        The refinement ratio ``r = n/n_c`` (> 1).
    order : float, keyword-only
        The convergence order ``p`` (> 0).
    safety : float, keyword-only
        The safety factor ``F_s`` (≥ 1 for a bound).

    Returns
    -------
    numpy.ndarray
        ``ê``, the estimated ``|k̄_n/k̄_∞ − 1|`` (1); NaN where *g* is NaN, ∞ where ``a ≥ 1``
        (the coarser grid too far from the finer one for an estimate).
    """
    if not ratio > 1 or not order > 0:
        raise ValueError(f"the grid error estimate needs a ratio > 1 and an order > 0, got {ratio}, {order}")
    a = np.asarray(g, dtype=float) / (ratio ** order - 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(a < 1.0, safety * np.abs(a / (1.0 - a)), np.where(np.isnan(a), np.nan, np.inf))


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


#: the columns of grid_error.csv after the sphere axes
GRID_ERROR_COLUMNS = ("force_normalized", "contact_cells_coarse", "contact_cells_fine", "grid_error",
                      "grid_error_ci_low", "grid_error_ci_high", "grid_ratio", "grid_error_estimate", "band",
                      "cell_resolved", "grid_resolved")


def grid_error(coarse, fine, *, min_cells: int, bootstrap: int, confidence: float, ratio: float,
               fraction: float = GRID_ERROR_FRACTION, order: float = GRID_ERROR_ORDER,
               safety: float = GRID_ERROR_SAFETY):
    """One row per sphere combination and load of the merged sphere Datasets *coarse* (a study on
    ``n_c`` with ``grid.realization_of`` = the *fine* study's grid) and *fine* (on ``n = ratio·n_c``),
    over their common seeds and the loads of both (module docstring); ``grid_error_estimate`` is
    :func:`estimate` of the far end ``G`` of the paired interval, with *order* and *safety*."""
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
            bound = float(estimate(max(abs(low), abs(high)), ratio, order=order, safety=safety))
            b_low, b_high = interval(boot_fine[:, j], confidence)
            band = 0.5 * (b_high - b_low)
            rows.append({**pick, "force_normalized": float(force[j]), "contact_cells_coarse": float(cells_c[j]),
                         "contact_cells_fine": float(cells_f[j]), "grid_error": float(error[j]),
                         "grid_error_ci_low": low, "grid_error_ci_high": high, "grid_ratio": float(ratio),
                         "grid_error_estimate": bound, "band": band,
                         "cell_resolved": bool(resolved(cells_c[j], min_cells)),
                         "grid_resolved": bool(bound <= fraction * band)})
    return pd.DataFrame(rows)


def empty_reason(fine: dict, coarse: dict) -> str | None:
    """Why the grid error of the merged groups *fine* and *coarse* (``{kind: Dataset}``) cannot be
    measured (no sphere, or fewer than 2 common seeds: no interval), or ``None`` where it can."""
    if "sphere" not in fine or "sphere" not in coarse:
        return "the sweep has no sphere (every radius is .inf): the grid error is measured on the sphere runs"
    seeds = set(fine["sphere"]["seed"].values.tolist()) & set(coarse["sphere"]["seed"].values.tolist())
    if len(seeds) < 2:
        return (f"the sweep has {len(seeds)} seed: the grid error's interval (a bootstrap over seeds) needs at "
                "least 2")
    return None


#: why the grid error is not measured when the study has no companion on a coarser grid
NO_COMPANION = "grid.coarse is null: no companion study on a coarser grid"


@dataclasses.dataclass(frozen=True, kw_only=True)
class GridErrorStatement:
    """The study's grid error, stated once for every page and table that mentions it (the landing
    page's study sentence and recommended models, the scorecard's lead and matrix).

    Attributes
    ----------
    measured : bool
        Whether ``grid_error.csv`` has a finite estimate ``ê`` at some load.
    coarse : int or None
        The companion's grid (``grid.coarse``).
    reason : str
        Why it is not measured ("" when it is): :data:`NO_COMPANION`, or the reason
        ``grid_error.csv`` was written empty with (:func:`empty_reason`).
    largest, median : float
        The largest and the median finite ``ê`` over the resolved loads (relative; NaN unmeasured).
    """

    measured: bool
    coarse: int | None = None
    reason: str = ""
    largest: float = math.nan
    median: float = math.nan

    @property
    def why_not(self) -> str:
        """Why a page's scores hold no grid error: :attr:`reason`, or :data:`NO_COMPANION` for a
        study that has no statement or whose grid error is measured (a table without it then has
        no companion value)."""
        return self.reason or NO_COMPANION

    def sentence(self) -> str:
        """``grid error measured against 193²: up to 16 % (median 9.2 %) at the resolved loads`` or
        ``grid error not measured: <reason>``."""
        if not self.measured:
            return f"grid error not measured: {self.reason}"
        return (f"grid error measured against {self.coarse}²: up to {100 * self.largest:.2g} % "
                f"(median {100 * self.median:.2g} %) at the resolved loads")


def statement(table, coarse: int | None) -> GridErrorStatement:
    """The :class:`GridErrorStatement` of ``grid_error.csv`` as read by
    :func:`roughcontact.study.files.io.read_csv` (its empty reason in ``attrs``), or of ``None``
    (the study has no companion: *coarse* is ``None``)."""
    if table is None or coarse is None:
        return GridErrorStatement(measured=False, coarse=coarse, reason=NO_COMPANION)
    values = np.asarray([], dtype=float)
    if len(table) and "grid_error_estimate" in table:
        rows = table[table["cell_resolved"].astype(bool)] if "cell_resolved" in table else table
        values = np.abs(rows["grid_error_estimate"].to_numpy(float))
        values = values[np.isfinite(values)]
    if not values.size:
        reason = getattr(table, "attrs", {}).get(REASON) or "no resolved load has a finite estimate"
        return GridErrorStatement(measured=False, coarse=coarse, reason=str(reason))
    return GridErrorStatement(measured=True, coarse=coarse, largest=float(values.max()),
                              median=float(np.median(values)))


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
        fit = StudySettings.of(json.loads(tree.attrs["config"])).fit
        n_fine = int(tree.attrs["grid_n"])
    with xr.open_datatree(Path(coarse_results) / "stiffness.nc", engine="netcdf4") as tree:
        n_coarse = int(tree.attrs["grid_n"])
    if n_coarse >= n_fine:
        raise MergeError(f"{coarse_results} ({n_coarse}²) is not on a coarser grid than {fine_results} ({n_fine}²)")
    table = grid_error(coarse["sphere"], fine["sphere"], min_cells=fit.resolved_cells, bootstrap=fit.bootstrap,
                       confidence=fit.confidence, ratio=n_fine / n_coarse, fraction=fraction)
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
