"""Local stiffness exponents ``d ln k/d ln F`` of every combination, with intervals (claim (l)).

At every load whose ``fit.slopes.window`` neighbours (centred on it) are all resolved (mean contact
cells ≥ ``fit.resolved_cells``), the local exponent is the least-squares slope of ``ln k̄`` against
``ln F`` over the window, ``k̄`` the ensemble mean; its 95 % interval comes from the same fit on
every bootstrap-over-seeds resample of the mean. A power law ``k ∝ F^β`` has the exponent β at
every load: the fractal law of eq. 11 has β = 1/(H+1), Hertz 1/3, an interfacial stiffness
``K ∝ p`` (Persson; Pastewka et al., Phys. Rev. E 87, 062809 (2013),
doi 10.1103/PhysRevE.87.062809) β = 1.

Forces are ``F/(E* L²)``.
"""
from __future__ import annotations

import logging

import numpy as np

from .ensemble import combinations, resolved
from .statistics import bootstrap_indices, interval
from ..config import axes
from ..config.settings import StudySettings

#: the columns of exponents.csv after the surface kind and the sweep axes
EXPONENT_COLUMNS = ("force", "local_exponent", "ci_low", "ci_high")

__all__ = ["local_exponents", "exponent_table"]

log = logging.getLogger(__name__)


def local_exponents(force, stiffness, contact_cells, *, window: int, min_cells: int, indices, level: float):
    """Local exponents of one combination.

    Parameters
    ----------
    force : numpy.ndarray
        ``(loads,)`` normalised forces.
    stiffness, contact_cells : numpy.ndarray
        ``(seeds, loads)``.
    window : int
        Odd number of neighbouring loads of each fit.
    min_cells : int
        A load is resolved when its mean contact cells are at least this many.
    indices : numpy.ndarray
        ``(resamples, seeds)`` bootstrap indices (:func:`~roughcontact.study.analysis.statistics.bootstrap_indices`).
    level : float
        Confidence level of the intervals.

    Returns
    -------
    tuple of numpy.ndarray
        ``(exponent, low, high)`` per load; NaN where the window is not resolved.
    """
    half = window // 2
    use = resolved(contact_cells.mean(0), min_cells)
    log_f = np.log(force)
    log_k = np.log(stiffness.mean(0))
    log_boot = np.log(stiffness[indices].mean(1))                       # (resamples, loads)
    out = np.full((3, force.size), np.nan)
    for i in range(half, force.size - half):
        span = slice(i - half, i + half + 1)
        if not use[span].all():
            continue
        x = log_f[span] - log_f[span].mean()
        out[0, i] = float(((log_k[span] - log_k[span].mean()) * x).sum() / (x @ x))
        slopes = ((log_boot[:, span] - log_boot[:, span].mean(-1, keepdims=True)) * x).sum(-1) / (x @ x)
        out[1, i], out[2, i] = interval(slopes, level)
    return out[0], out[1], out[2]


def empty_reason(study) -> str:
    """Why exponents.csv has no row: no load window of ``fit.slopes.window`` consecutive resolved loads."""
    study = StudySettings.of(study)
    return (f"no combination has {study.fit.slopes.window} consecutive loads with at least "
            f"{study.fit.resolved_cells} contact cells (fit.slopes.window, fit.resolved_cells)")


def exponent_table(groups: dict, study):
    """One row per (kind, combination, resolved load): ``local_exponent`` and its interval
    (``exponent`` is the body's exponent m, a sweep axis)."""
    import pandas as pd

    study = StudySettings.of(study)
    L, E = study.grid.length, study.e_star
    fit = study.fit
    rows = []
    for kind, ds in groups.items():
        indices = bootstrap_indices(ds.sizes["seed"], fit.bootstrap)
        force = ds["force"].values / (E * L**2)
        for combo, sub in combinations(ds):
            beta, low, high = local_exponents(
                force, sub["stiffness"].values, sub["contact_cells"].values, window=fit.slopes.window,
                min_cells=fit.resolved_cells, indices=indices, level=fit.confidence)
            for i in np.flatnonzero(np.isfinite(beta)):
                rows.append({"kind": kind, **combo, "force": float(force[i]), "local_exponent": beta[i],
                             "ci_low": low[i], "ci_high": high[i]})
    return pd.DataFrame(rows) if rows else pd.DataFrame(columns=["kind", *axes.AXES, *EXPONENT_COLUMNS])
