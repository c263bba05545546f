"""The grid error's estimate against the actual error: a study, its companion and a twice finer reference.

A study on ``n`` with ``grid.realization_of: 2n`` and ``grid.coarse: n_c`` estimates its grid
error ``ê`` at every load from its companion (:func:`roughcontact.study.analysis.grid_error.estimate`,
``results/grid_error.csv``); the same surfaces on ``2n`` (a study on ``2n``) give the actual
error of the study's ensemble mean, ``e = k̄_n/k̄_2n − 1`` (:func:`~roughcontact.study.analysis.grid_error.grid_error`
of the study against the reference). Per sphere combination and load :func:`compare` writes

* ``g`` (the companion's difference ``k̄_{n_c}/k̄_n − 1``), ``estimate`` (``ê``), ``actual`` (``e``);
* ``bounded``: ``ê ≥ |e|``; ``looseness``: ``ê/|e|``;
* ``order``: the observed order ``ln(g/(−e))/ln r`` of the three grids where both differences
  have the sign of a monotone sequence (Richardson's, :func:`~roughcontact.study.analysis.grid_error.richardson`),
  NaN otherwise;
* ``cell_resolved``: the study's mean contact has at least ``fit.resolved_cells`` cells;
  ``resolved``: the study calls the load resolved (``cell_resolved`` and ``grid_resolved`` of its
  table, ``ê`` at most half the band), the loads its scorecard counts as resolved by the grid.

:func:`summary` counts, over the loads the study calls resolved, the fraction bounded and the
median looseness (and the same over every load with enough contact cells). Since a monotone
sequence has ``|k_n/k_∞ − 1| ≥ |k_n/k_2n − 1|``, ``ê`` (an estimate of the former) bounding
``e`` is the least a safe estimate must do. Forces are ``F/(E* L²)``.
"""
from __future__ import annotations

import math
import sys

import numpy as np

__all__ = ["compare", "summary", "run_validation"]

_AXES = ("hurst", "radius", "exponent", "h_rms", "rolloff", "cutoff", "hardness")


def compare(study_table, actual_table):
    """One row per sphere combination and load of the two tables (module docstring).

    Parameters
    ----------
    study_table : pandas.DataFrame
        The study's ``grid_error.csv`` (against its companion).
    actual_table : pandas.DataFrame
        :func:`~roughcontact.study.analysis.grid_error.grid_error` of the study (as the coarser
        grid) against the reference on twice its grid.

    Returns
    -------
    pandas.DataFrame
        The axes, ``force_normalized``, ``contact_cells`` (of the study), ``g``, ``estimate``,
        ``actual``, ``band``, ``bounded``, ``looseness``, ``order`` and ``resolved``.
    """
    keys = [a for a in _AXES if a in study_table and a in actual_table] + ["force_normalized"]
    left = study_table.assign(force_normalized=study_table["force_normalized"].round(15))
    right = actual_table.assign(force_normalized=actual_table["force_normalized"].round(15))
    both = left.drop(columns="cell_resolved").merge(
        right[keys + ["grid_error", "cell_resolved"]].rename(columns={"grid_error": "actual"}), on=keys, how="inner")
    if not len(both):
        raise ValueError("the study's and the reference's tables share no combination and load")
    g, actual, est = (both[c].to_numpy(float) for c in ("grid_error", "actual", "grid_error_estimate"))
    ratio = both["grid_ratio"].to_numpy(float)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = g / -actual                       # monotone: the coarse and the fine differ in sign
        order = np.where(q > 0, np.log(np.where(q > 0, q, 1.0)) / np.log(ratio), np.nan)
        looseness = est / np.abs(actual)
    return both[keys].assign(contact_cells=both["contact_cells_fine"], g=g, estimate=est, actual=actual,
                             band=both["band"], bounded=est >= np.abs(actual), looseness=looseness, order=order,
                             cell_resolved=both["cell_resolved"].astype(bool),
                             resolved=both["cell_resolved"].astype(bool) & both["grid_resolved"].astype(bool))


def summary(table) -> dict:
    """The validation's numbers of a :func:`compare` table.

    Returns
    -------
    dict
        ``resolved_loads``, ``bounded_fraction`` and ``median_looseness`` over the loads the
        study calls resolved; ``cell_loads``, ``cell_bounded_fraction`` and
        ``cell_median_looseness`` over the loads with ``cell_resolved`` only (the estimate's
        resolution rule left out); ``median_order`` over the monotone loads of the latter.
    """
    out = {}
    for prefix, mask in (("", table["resolved"].to_numpy(bool)), ("cell_", table["cell_resolved"].to_numpy(bool))):
        sub = table[mask]
        out["resolved_loads" if not prefix else "cell_loads"] = int(len(sub))
        out[f"{prefix}bounded_fraction"] = float(sub["bounded"].mean()) if len(sub) else math.nan
        finite = sub["looseness"].to_numpy(float)
        finite = finite[np.isfinite(finite)]
        out[f"{prefix}median_looseness"] = float(np.median(finite)) if finite.size else math.nan
    orders = table[table["cell_resolved"].to_numpy(bool)]["order"].to_numpy(float)
    out["median_order"] = float(np.nanmedian(orders)) if np.isfinite(orders).any() else math.nan
    return out


def run_validation(study_results, reference_results, out_csv=None) -> dict:
    """:func:`summary` of a study's ``results`` directory (with ``grid_error.csv``) against the
    reference study's on twice its grid; the :func:`compare` table written to *out_csv* if given."""
    import tempfile
    from pathlib import Path

    import pandas as pd

    from ...errors import MergeError
    from ..files.io import write_csv
    from .grid_error import run_grid_error

    table_path = Path(study_results) / "grid_error.csv"
    if not table_path.is_file():
        raise MergeError(f"{study_results}: no grid_error.csv (a study with grid.coarse, after its grid_error rule)")
    with tempfile.TemporaryDirectory() as tmp:
        run_grid_error(study_results, reference_results, Path(tmp) / "actual.csv")
        actual = pd.read_csv(Path(tmp) / "actual.csv")
    table = compare(pd.read_csv(table_path), actual)
    if out_csv:
        write_csv(table, out_csv)
    return summary(table)


def main(argv=None) -> int:
    """``python -m roughcontact.study.analysis.grid_error_validation STUDY REFERENCE [-o table.csv]``."""
    import argparse

    from ...errors import MergeError

    parser = argparse.ArgumentParser(prog="python -m roughcontact.study.analysis.grid_error_validation",
                                     description=__doc__.split("\n\n")[0])
    parser.add_argument("study", help="results directory of the study (grid.coarse, grid.realization_of = 2n)")
    parser.add_argument("reference", help="results directory of the same surfaces on 2n")
    parser.add_argument("-o", "--output", help="CSV of every load to write")
    args = parser.parse_args(argv)
    try:
        numbers = run_validation(args.study, args.reference, args.output)
    except (MergeError, ValueError) as err:   # bad input: one line
        print(f"grid_error_validation: {err}", file=sys.stderr)
        return 2
    for key, value in numbers.items():
        print(f"{key}: {value:.4g}" if isinstance(value, float) else f"{key}: {value}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
