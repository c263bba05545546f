"""Paired effects of the optional sweep axes on the stiffness (claims (i)–(k)).

A run with a short-wavelength cutoff, a roll-off or a hardness is compared with
the run of the same seed without it (equal seeds give the same random phases,
so the pair differs only by the axis); intervals resample the seeds of both
sides together (:func:`roughcontact.study.statistics.bootstrap_indices`).

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

import itertools
import math

import numpy as np

from .. import axes
from ..ensemble import resolved
from ..statistics import bootstrap_indices, interval, verdict, verdict_bound
from .registry import Claim, register, row

__all__ = ["effect_rows", "INSENSITIVE_TOLERANCE"]

#: k is "unchanged" by a cutoff or a hardness if no resolved load moves by more than this (relative)
INSENSITIVE_TOLERANCE = 0.10

_STATEMENTS = {
    "cutoff": ("i", f"a short-wavelength cutoff changes k by < {INSENSITIVE_TOLERANCE:.0%} where the contact "
                    "radius exceeds the cutoff (Conclusions)"),
    "rolloff": ("j", "a roll-off leaves the low-force slope unchanged (arbitrary spectrum, Conclusions)"),
    "hardness": ("k", f"a hardness cap changes k by < {INSENSITIVE_TOLERANCE:.0%} (elasticity on all scales "
                      "is not crucial, Conclusions)"),
}


def _untested(axis, why, paper):
    claim, statement = _STATEMENTS[axis]
    return {"claim": claim, "statement": statement, "measured": math.nan, "low": math.nan, "high": math.nan,
            "paper": paper, "verdict_text": f"untested: {why}"}


def effect_rows(ds, cross, study, axis: str) -> list[dict]:
    """Rows of the claim of one optional *axis* (cutoff: (i), rolloff: (j), hardness: (k)) from
    the sphere Dataset *ds* (merged runs) and the crossover table *cross* (for the low-force
    window); keyword dicts of :func:`roughcontact.study.claims.registry.row`."""
    L, E = study.grid.length, study.e_star
    level = study.fit.zeta.confidence
    indices = bootstrap_indices(ds.sizes["seed"], study.fit.zeta.bootstrap)
    force = ds["force"].values / (E * L**2)
    rows = []
    paper = 0.0 if axis == "rolloff" else INSENSITIVE_TOLERANCE
    baseline = axes.paper_coordinates(L)[axis]   # the run without it: the paper's setting
    values = ds[axis].values.tolist()
    if baseline not in values or len(values) < 2:
        return [_untested(axis, f"no {axis} swept" if values == [baseline]
                          else f"no run without a {axis} to compare with", paper)]
    others = [d for d in ds["stiffness"].dims if d not in ("seed", "force", axis)]
    for value in values:
        if value == baseline:
            continue
        for position in itertools.product(*(ds[d].values.tolist() for d in others)):
            pick = dict(zip(others, position))
            rows += _pair(axis, value, baseline, ds.sel(pick), pick, force, cross, study, indices, level, paper)
    return rows


def _pair(axis, value, baseline, ds, pick, force, cross, study, indices, level, paper):
    """The rows of one (axis value, combination) against the baseline."""
    claim, statement = _STATEMENTS[axis]
    with_, without = ds.sel({axis: value}), ds.sel({axis: baseline})
    min_cells = study.fit.zeta.min_cells
    both = (resolved(with_["contact_cells"].mean("seed"), min_cells)
            & resolved(without["contact_cells"].mean("seed"), min_cells)).values
    where = {**pick, axis: value}
    sweep = (f"sphere H = {pick['hurst']:g}, R = {pick['radius']:g}, h_rms = {pick['h_rms']:g}, {axis} = {value:g} "
             f"against {axis} = {baseline:g}, {ds.sizes['seed']} paired seeds, n = {study.grid.n}")
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
        match = cross
        for name, coordinate in {**pick, axis: baseline}.items():
            match = match[match[name] == coordinate]
        f_tr = match["Ftr_pred_fit"].iloc[0] if len(match) else math.nan
        if not math.isfinite(f_tr) and len(match):
            f_tr = match["Ftr_pred_estimate"].iloc[0]
        mask = both & (force <= study.fit.slopes.low_max_ratio * f_tr)
        names = [("stiffness", "")]
        loads = f"{int(mask.sum())} resolved loads with F <= {study.fit.slopes.low_max_ratio:g} F_tr"
    rows = []
    for name, what in names:
        if mask.sum() < (2 if axis == "rolloff" else 1):
            rows.append({**_untested(axis, f"{int(mask.sum())} loads qualify", paper), **where,
                         "sweep": sweep, "loads": loads})
            continue
        k_with = with_[name].transpose("seed", "force").values[:, mask]
        k_without = without[name].transpose("seed", "force").values[:, mask]
        if axis == "rolloff":
            log_f = np.log(force[mask])
            xm = log_f - log_f.mean()

            def measure(a, b):
                return ((np.log(a) - np.log(b)) * xm).sum(-1) / (xm @ xm)
        else:
            def measure(a, b):
                return np.abs(a / b - 1).max(-1)
        value_measured = float(measure(k_with.mean(0), k_without.mean(0)))
        low, high = interval(measure(k_with[indices].mean(1), k_without[indices].mean(1)), level)
        text = (verdict(0.0, low, high) if axis == "rolloff"
                else verdict_bound(INSENSITIVE_TOLERANCE, low, high, side="below"))
        rows.append({"claim": claim, "statement": statement + what, "measured": value_measured, "low": low,
                     "high": high, "paper": paper, "verdict_text": text, "sweep": sweep, "loads": loads,
                     "note": ("measured: change of the low-force slope d ln k/d ln F" if axis == "rolloff"
                              else "measured: max |k_with/k_without - 1|"), **where})
    return rows


def _claim_of(axis: str):
    """The claim of one optional axis: its rows as rows of the table (:func:`effect_rows`)."""
    def rows(inputs):
        if "sphere" not in inputs.groups:
            return []
        return [row(**r) for r in effect_rows(inputs.groups["sphere"], inputs.cross, inputs.study, axis)]
    return rows


for _axis in ("cutoff", "rolloff", "hardness"):
    register(Claim(_STATEMENTS[_axis][0], _STATEMENTS[_axis][1], _claim_of(_axis), needs=("groups",)))
