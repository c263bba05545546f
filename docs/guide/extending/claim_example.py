# module: roughcontact.study.claims.stiffening
"""Claim (x): the ensemble-mean stiffness of every sphere combination rises with the load.

An elastic contact stiffens as it is pressed (more and larger contacts): a property every model
of the scorecard has, tested here on the BEM ensemble of each sphere combination, whatever its
axes, at its resolved loads (:func:`roughcontact.study.analysis.ensemble.resolved`: the loads
whose ensemble-mean contact has at least ``fit.resolved_cells`` cells; below them one or two cells
carry the load and k does not follow it). The registry loops over the combinations (the rule
``sphere``) and runs the claim in isolation; the estimator sees one combination.
"""
from __future__ import annotations

import math

import numpy as np

from ..analysis.ensemble import resolved
from ..analysis.statistics import UNRESOLVED, bootstrap_indices, interval, untested, verdict_bound
from .registry import Claim, register, row, sphere

STATEMENT = "the ensemble-mean stiffness rises with the load at every resolved load"


def smallest_rise(mean_stiffness):
    """The smallest relative rise ``k(F_{i+1})/k(F_i) − 1`` between neighbouring loads (last axis)."""
    return (np.diff(mean_stiffness, axis=-1) / mean_stiffness[..., :-1]).min(-1)


def stiffening(combination):
    """The smallest relative rise of the mean k between neighbouring resolved loads of one
    combination, with its bootstrap-over-seeds interval; consistent when the interval lies above 0,
    untested (unresolved) with fewer than two resolved loads."""
    fit = combination.study.fit                                    # the study's resolved-load and bootstrap settings
    cells = combination.data["contact_cells"].values.mean(0)       # (force,), ensemble-mean contact cells
    k = combination.data["stiffness"].values[:, resolved(cells, fit.resolved_cells)]  # (seed, resolved force), k/(E* L)
    note = f"measured: min over the resolved loads (>= {fit.resolved_cells} contact cells) of k(F_i+1)/k(F_i) - 1"
    if k.shape[1] < 2:
        return row("x", STATEMENT, math.nan, math.nan, math.nan, 0.0,
                   untested(UNRESOLVED, f"{k.shape[1]} resolved load(s), two needed"), note=note, **combination.axes)
    samples = smallest_rise(k[bootstrap_indices(k.shape[0], fit.bootstrap)].mean(1))
    low, high = interval(samples, fit.confidence)
    return row("x", STATEMENT, float(smallest_rise(k.mean(0))), low, high, 0.0,
               verdict_bound(0.0, low, high, side="above"),      # consistent: the interval lies above 0
               loads=f"{k.shape[1]} resolved loads", note=note, **combination.axes)


register(Claim("x", "the ensemble-mean stiffness rises with the load", estimate=stiffening, applies=sphere))
