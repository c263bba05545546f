"""Paired effects of the optional sweep axes on the stiffness (claims (i)–(k)).

A run with a short-wavelength cutoff, a roll-off or a hardness is compared with
the run of the same seed without it (equal seeds give the same random phases,
so the pair differs only by the axis); intervals resample the seeds of both
sides together (:func:`roughcontact.study.analysis.statistics.bootstrap_indices`).

* (i) "the contact stiffness ... is determined by the large wavelength in the
  power spectrum" (Conclusions): a cutoff changes k by less than
  :data:`INSENSITIVE_TOLERANCE` at every resolved load whose apparent contact
  radius ``a = k/(2E*)`` (without the cutoff) exceeds the cutoff wavelength.
* (j) a roll-off's effect on the low-force slope (the paper expects none for
  "arbitrary power spectrum"; Pastewka et al., Phys. Rev. E 87, 062809
  (2013) find a linear k(F) for a flat surface with a roll-off at small loads).
* (k) "the assumption of elasticity on all scales does not play a crucial role":
  a hardness cap changes the unloading and the loading stiffness by less than
  :data:`INSENSITIVE_TOLERANCE` at every resolved load.

Forces F/(E* L²), stiffnesses k/(E* L).
"""
from __future__ import annotations

import math

import numpy as np

from ..config import axes
from ..analysis.ensemble import resolved
from ..analysis.statistics import (NOT_SWEPT, UNRESOLVED, bootstrap_indices, interval, judge, log_log_slope, untested,
                                   verdict_bound)
from .registry import Claim, register, row

__all__ = ["INSENSITIVE_TOLERANCE"]

#: k is "unchanged" by a cutoff or a hardness if no resolved load moves by more than this (relative)
INSENSITIVE_TOLERANCE = 0.10

_STATEMENTS = {
    "cutoff": ("i", f"a short-wavelength cutoff changes k by < {INSENSITIVE_TOLERANCE:.0%} where the contact "
                    "radius exceeds the cutoff (Conclusions)"),
    "rolloff": ("j", "a roll-off leaves the low-force slope unchanged (arbitrary spectrum, Conclusions)"),
    "hardness": ("k", f"a hardness cap changes k by < {INSENSITIVE_TOLERANCE:.0%} (elasticity on all scales "
                      "is not crucial, Conclusions)"),
}


def _untested(axis, because, why, paper):
    claim, statement = _STATEMENTS[axis]
    return {"claim": claim, "statement": statement, "measured": math.nan, "low": math.nan, "high": math.nan,
            "paper": paper, "verdict_text": untested(because, why)}


def _not_paired(ds, axis: str, length: float, paper):
    """The untested row of the claim of *axis* where the sphere Dataset *ds* cannot pair runs (the
    axis not swept, or no run at its paper setting), else ``None``."""
    baseline = axes.paper_coordinates(length)[axis]   # the run without it: the paper's setting
    values = ds[axis].values.tolist()
    if baseline not in values or len(values) < 2:
        return _untested(axis, NOT_SWEPT, f"no {axis} swept" if values == [baseline]
                         else f"no run without a {axis} to compare with", paper)
    return None


def _paper_value(axis: str) -> float:
    """The paper value column of the claim of *axis*: no change of the slope (roll-off), else the
    tolerance on the change of k."""
    return 0.0 if axis == "rolloff" else INSENSITIVE_TOLERANCE


def _pair(axis, where, baseline, with_, without, crossover, study):
    """The rows of one combination *where* (the axis off its paper value) against the run of the
    same seeds at *baseline*: *with_*, *without* their ``(seed, force)`` slices, *crossover* the
    baseline's row of ``crossover.csv`` (or ``None``)."""
    claim, statement = _STATEMENTS[axis]
    L, E = study.grid.length, study.e_star
    level, paper, value = study.fit.confidence, _paper_value(axis), where[axis]
    indices = bootstrap_indices(with_.sizes["seed"], study.fit.bootstrap)
    force = with_["force"].values / (E * L**2)
    min_cells = study.fit.resolved_cells
    both = (resolved(with_["contact_cells"].mean("seed"), min_cells)
            & resolved(without["contact_cells"].mean("seed"), min_cells)).values
    sweep = (f"sphere H = {where['hurst']:g}, R = {where['radius']:g}, h_rms = {where['h_rms']:g}, {axis} = {value:g} "
             f"against {axis} = {baseline:g}, {with_.sizes['seed']} paired seeds, n = {study.grid.n}")
    if axis == "cutoff":
        # the apparent contact radius of the run without the cutoff, from k = 2 E* a (flat punch)
        radius = without["stiffness"].mean("seed").values / (2 * study.e_star)
        mask = both & (radius > value)
        names = [("stiffness", "")]
        loads = f"{int(mask.sum())} resolved loads with contact radius > cutoff {value:g}"
    elif axis == "hardness":
        mask = both
        names = [("stiffness", " (unloading stiffness)"), ("loading_stiffness", " (loading tangent)")]
        loads = f"{int(mask.sum())} resolved loads"
    else:
        f_tr = crossover["Ftr_pred_fit"] if crossover is not None else math.nan
        if not math.isfinite(f_tr) and crossover is not None:
            f_tr = crossover["Ftr_pred_estimate"]
        mask = both & (force <= study.fit.slopes.low_max_ratio * f_tr)
        names = [("stiffness", "")]
        loads = f"{int(mask.sum())} resolved loads with F <= {study.fit.slopes.low_max_ratio:g} F_tr"
    rows = []
    for name, what in names:
        if mask.sum() < (2 if axis == "rolloff" else 1):
            rows.append({**_untested(axis, UNRESOLVED, f"{int(mask.sum())} loads qualify", paper), **where,
                         "sweep": sweep, "loads": loads})
            continue
        k_with = with_[name].transpose("seed", "force").values[:, mask]
        k_without = without[name].transpose("seed", "force").values[:, mask]
        if axis == "rolloff":
            log_f = np.log(force[mask])

            def measure(a, b):
                return log_log_slope(log_f, np.log(a) - np.log(b))
        else:
            def measure(a, b):
                return np.abs(a / b - 1).max(-1)
        value_measured = float(measure(k_with.mean(0), k_without.mean(0)))
        low, high = interval(measure(k_with[indices].mean(1), k_without[indices].mean(1)), level)
        text = (judge(0.0, low, high) if axis == "rolloff"
                else verdict_bound(INSENSITIVE_TOLERANCE, low, high, side="below"))
        rows.append({"claim": claim, "statement": statement + what, "measured": value_measured, "low": low,
                     "high": high, "paper": paper, "verdict_text": text, "sweep": sweep, "loads": loads,
                     "note": ("measured: change of the low-force slope d ln k/d ln F" if axis == "rolloff"
                              else "measured: max |k_with/k_without - 1|"), **where})
    return rows


def _claim_of(axis: str) -> Claim:
    """The claim of one optional axis: per sphere combination with the axis off its paper value,
    the rows of the pair with the same combination at the paper value (:func:`_pair`); one
    untested row where the sweep cannot pair runs (:func:`_not_paired`)."""
    def rows(inputs):
        if "sphere" not in inputs.groups:
            return []
        untested = _not_paired(inputs.groups["sphere"], axis, inputs.study.grid.length, _paper_value(axis))
        return [row(**untested)] if untested is not None else []

    def applies(combination):
        if combination.kind != "sphere":
            return None
        baseline = axes.paper_coordinates(combination.study.grid.length)[axis]
        paired = combination.axes[axis] != baseline and combination.with_axes(**{axis: baseline}) is not None
        return "" if paired else None

    def estimate(combination):
        without = combination.with_axes(**{axis: axes.paper_coordinates(combination.study.grid.length)[axis]})
        return [row(**r) for r in _pair(axis, combination.axes, without.axes[axis], combination.data, without.data,
                                         without.crossover, combination.study)]

    claim, statement = _STATEMENTS[axis]
    return Claim(claim, statement, rows, needs=("groups",), estimate=estimate, applies=applies)


for _axis in ("cutoff", "rolloff", "hardness"):
    register(_claim_of(_axis))
