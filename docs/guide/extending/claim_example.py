# module: roughcontact.study.claims.stiffening
"""Claim (x): the ensemble-mean stiffness of every sphere combination rises with the load.

An elastic contact stiffens as it is pressed (more and larger contacts): a property every model
of the scorecard has, tested here on the BEM ensemble of each sphere combination, whatever its
axes. The registry loops over the combinations (the rule ``sphere``) and runs the claim in
isolation; the estimator sees one combination.
"""
from __future__ import annotations

import numpy as np

from ..analysis.statistics import bootstrap_indices, interval, verdict_bound
from .registry import Claim, register, row, sphere


def smallest_rise(mean_stiffness):
    """The smallest relative rise ``k(F_{i+1})/k(F_i) − 1`` between neighbouring loads (last axis)."""
    return (np.diff(mean_stiffness, axis=-1) / mean_stiffness[..., :-1]).min(-1)


def stiffening(combination):
    """The smallest relative rise of the mean k between neighbouring loads of one combination, with
    its bootstrap-over-seeds interval; consistent when the interval lies above 0."""
    k = combination.data["stiffness"].values                       # (seed, force), k/(E* L)
    fit = combination.study.fit.zeta                               # the study's bootstrap settings
    samples = smallest_rise(k[bootstrap_indices(k.shape[0], fit.bootstrap)].mean(1))
    low, high = interval(samples, fit.confidence)
    return row("x", "the ensemble-mean stiffness rises with the load at every load",
               float(smallest_rise(k.mean(0))), low, high, 0.0,
               verdict_bound(0.0, low, high, side="above"),      # consistent: the interval lies above 0
               note="measured: min over loads of k(F_i+1)/k(F_i) - 1", **combination.axes)


register(Claim("x", "the ensemble-mean stiffness rises with the load", estimate=stiffening, applies=sphere))
