"""The real contact area of the sphere ensemble: when a load's area is resolved, the crossover of
the area laws, and the area scorecard (the models of :mod:`roughcontact.models.area` against the
BEM ensemble, scored as the stiffness models are in :mod:`roughcontact.study.analysis.scorecard`).

Resolution. The area of a contact set on a grid of spacing ``Δ = L/n`` overestimates the converged
area when the contact or the roughness's shortest wavelength ``λ_s`` spans few cells (the cutoff, or
``2Δ``, the grid's Nyquist wavelength, without one). ``benchmarks/area_grid_study.py`` measured it:
one surface per seed (R = 0.5, H = 0.7, a fixed cutoff) pressed on grids 65² … 1025², the
ensemble-mean area against the finest grid's (``docs/guide/area.md``, numbers and date). A load is
*area-resolved* when its ensemble-mean contact cells are at least :func:`min_area_cells` of
``λ_s/Δ`` (:func:`cells_per_wavelength`): the fewest with which the measured area stayed within
:data:`AREA_TOLERANCE` of the converged one at every load above. This is stricter than the
stiffness's rule (``fit.resolved_cells``): the area needs many cells per asperity, the stiffness
(the contact's size) does not.

Scorecard (:func:`area_scorecard`): per sphere combination and area model, over the area-resolved
loads, ``max_rel_dev = max |A_model/A_BEM − 1|`` with its bootstrap-over-seeds interval, the rms of the
same deviations, the mean deviation (systematic; each load weighted by the inverse variance of the
ensemble mean there, as in the stiffness scorecard) below and above the area crossover
:func:`~roughcontact.models.area.laws.area_crossover_force` with its interval and verdict on 0, the
fraction of loads inside the ensemble's band, and the rank by ``rms_rel_dev``; a combination without
an area-resolved load has one row per model saying why (``untested``). Areas in ``length²``, forces
``F/(E* L²)`` in the table.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...models import area as area_models
from ...models.area.laws import SIMULATION_KAPPA, area_crossover_force, single_asperity_force
from ...models.area.three_regime import SUMMIT, rms_curvature
from ..config.settings import StudySettings
from .combination import combination, combo_label
from .ensemble import combinations
from .statistics import UNRESOLVED, bootstrap_indices, interval, untested, verdict, weighted_deviation

__all__ = ["AREA_TOLERANCE", "MIN_AREA_CELLS", "MEASURED_ON", "AreaContext", "cells_per_wavelength",
           "min_area_cells", "area_context", "area_scorecard", "AREA_COLUMNS"]

#: the relative error of the ensemble-mean area the resolution rule allows (that of the grid study)
AREA_TOLERANCE = 0.10
#: fewest ensemble-mean contact cells for the area within AREA_TOLERANCE, by cells per shortest
#: wavelength λ_s/Δ (the largest key not above the grid's): the largest of three grid studies
#: (benchmarks/area_grid_study.py, docs/guide/area.md), rounded up
MIN_AREA_CELLS = {2.0: 600, 4.0: 280, 8.0: 45, 16.0: 20}
#: where MIN_AREA_CELLS was measured (stated in the untested reasons)
MEASURED_ON = "benchmarks/area_grid_study.py, 2026-11-29"


def cells_per_wavelength(n: int, length: float, cutoff) -> float:
    """``λ_s/Δ``: the cells per shortest wavelength of the spectrum (``cutoff`` in length units;
    ``None`` or 0: the grid's Nyquist wavelength, 2 cells)."""
    if cutoff is None or not cutoff > 0:
        return 2.0
    return float(cutoff) * n / length


def min_area_cells(wavelength_cells: float) -> float:
    """The fewest ensemble-mean contact cells an area-resolved load needs at ``λ_s/Δ =
    wavelength_cells`` (:data:`MIN_AREA_CELLS`: the entry of the largest key not above it)."""
    keys = [k for k in sorted(MIN_AREA_CELLS) if k <= wavelength_cells + 1e-9]
    return MIN_AREA_CELLS[keys[-1]] if keys else math.inf


@dataclasses.dataclass(frozen=True)
class AreaContext:
    """What the area claims and the scorecard know of one sphere combination.

    Attributes
    ----------
    surface : roughcontact.models.scorecard.Surface
        The combination as the models read it.
    rms_slope : float
        ``h′_rms = √⟨|∇h|²⟩`` of the grid's spectrum (:func:`roughcontact.models.area.rms_slope`).
    crossover_force : float
        ``F_A`` of the linear law with κ = 2 and Hertz (force units).
    summit_radius : float
        ``R_s = c_s/h″_rms`` (length): the summit radius of
        :mod:`roughcontact.models.area.three_regime` (``c_s`` its fitted ``SUMMIT``, ``h″_rms`` the
        grid spectrum's rms Laplacian); ``inf`` where the spectrum has no curvature.
    summit_force : float
        ``F_1``, the end of the one-asperity regime: the force where one summit's Hertz area
        ``π (3F R_s/(4E*))^(2/3)`` equals the linear law's with κ = 2
        (:func:`roughcontact.models.area.laws.single_asperity_force`; force units).
    wavelength_cells : float
        ``λ_s/Δ`` (:func:`cells_per_wavelength`).
    min_cells : float
        The contact cells a load needs (:func:`min_area_cells`).
    resolved : numpy.ndarray
        ``(force,)`` bool: the ensemble-mean contact cells reach *min_cells*.
    why_unresolved : str
        Why a load is not area-resolved, for the untested reasons.
    """

    surface: object
    rms_slope: float
    crossover_force: float
    summit_radius: float
    summit_force: float
    wavelength_cells: float
    min_cells: float
    resolved: np.ndarray
    why_unresolved: str


def area_context(where: dict, data, study) -> AreaContext:
    """The :class:`AreaContext` of the sphere combination *where* (axis -> merged-file coordinate) with
    its ``(seed, force)`` slice *data*."""
    study = StudySettings.of(study)
    surface = combination(where, study).surface()
    slope = area_models.rms_slope(surface)
    wavelength = cells_per_wavelength(study.grid.n, study.grid.length, surface.cutoff)
    needed = min_area_cells(wavelength)
    cells = np.asarray(data["contact_cells"].values, dtype=float).mean(0)
    scale = "no cutoff: the roughness reaches the grid scale; " if wavelength <= 2 else ""
    why = (f"area needs >= {needed:g} mean contact cells at {wavelength:g} cells per shortest wavelength "
           f"(grid study, {MEASURED_ON}; {scale}a cutoff of more cells or a larger grid.n lowers it)")
    curvature = rms_curvature(surface)
    summit = SUMMIT / curvature if curvature > 0 else math.inf
    return AreaContext(surface, slope, area_crossover_force(radius=surface.radius, e_star=surface.e_star,
                                                            rms_slope=slope, kappa=SIMULATION_KAPPA),
                       summit, single_asperity_force(summit_radius=summit, e_star=surface.e_star, rms_slope=slope,
                                                     kappa=SIMULATION_KAPPA),
                       wavelength, needed, cells >= needed, why)


#: the columns of the area scorecard (the header of a table without a row)
AREA_COLUMNS = ("model", "hurst", "radius", "h_rms", "combination", "max_rel_dev", "max_rel_dev_ci_low",
                "max_rel_dev_ci_high", "rms_rel_dev", "systematic_low", "systematic_low_ci_low",
                "systematic_low_ci_high", "systematic_low_verdict", "systematic_high", "systematic_high_ci_low",
                "systematic_high_ci_high", "systematic_high_verdict", "inside_band", "n_loads", "force_min",
                "force_max", "rms_slope", "crossover_force", "min_area_cells", "rank", "note")


def _systematic(a_model, mean, a_boot, use, level) -> tuple:
    """Mean of ``A_model/A_BEM − 1`` over the loads *use*, each weighted by the inverse variance of
    the ensemble mean there, its bootstrap interval (:func:`~.statistics.weighted_deviation`, the
    stiffness scorecard's systematic deviation too) and verdict on 0."""
    if not use.any():
        return math.nan, math.nan, math.nan, untested(UNRESOLVED, "no area-resolved load on this branch")
    value, low, high = weighted_deviation(a_model, mean, a_boot, use, level)
    return value, low, high, verdict(0.0, low, high)


def area_scorecard(groups: dict, study):
    """The area scorecard (module docstring): a DataFrame of :data:`AREA_COLUMNS` and per
    combination the curves for the figure, ``{label: {"force", "area" (the ensemble mean), "band_low",
    "band_high", "resolved", "crossover_force", "min_cells", "rms_slope", "radius", "exponent", "models": {name: A}}}``
    (areas in length², forces in force units)."""
    import pandas as pd

    study = StudySettings.of(study)
    ds = (groups or {}).get("sphere")
    if ds is None:
        return pd.DataFrame(columns=AREA_COLUMNS), {}
    level = study.fit.confidence
    indices = bootstrap_indices(ds.sizes["seed"], study.fit.bootstrap)
    norm = study.e_star * study.grid.length**2
    rows, curves = [], {}
    for where, sub in combinations(ds):
        if where.get("work_of_adhesion", 0.0) > 0 or math.isfinite(where.get("hardness", math.inf)):
            continue                                       # the area models are elastic and adhesion-free
        context = area_context(where, sub, study)
        force = sub["force"].values
        area = sub["contact_area"].values                  # (seed, force), length²
        mean = area.mean(0)
        boot = area[indices].mean(1)                       # (resample, force)
        with np.errstate(divide="ignore", invalid="ignore"):
            band = np.percentile(boot / mean - 1, [50 * (1 - level), 50 * (1 + level)], axis=0)
        label = combo_label(combination(where, study))
        predicted = area_models.predict(force, context.surface)
        curves[label] = {"force": force, "area": mean, "band_low": band[0], "band_high": band[1],
                         "resolved": context.resolved, "crossover_force": context.crossover_force,
                         "min_cells": context.min_cells, "rms_slope": context.rms_slope,
                         "radius": context.surface.radius, "exponent": context.surface.exponent,
                         "models": predicted}
        use_all = context.resolved & (mean > 0)
        combo_rows = []
        for name, a_model in predicted.items():
            use = use_all & np.isfinite(a_model)
            base = {"model": name, **{a: where.get(a, math.nan) for a in ("hurst", "radius", "h_rms")},
                    "combination": label, "rms_slope": context.rms_slope,
                    "crossover_force": context.crossover_force / norm, "min_area_cells": context.min_cells,
                    "n_loads": int(use.sum())}
            if not use.any():
                combo_rows.append({**base, "note": untested(UNRESOLVED, "no area-resolved load: "
                                                                        + context.why_unresolved)})
                continue
            dev = a_model / mean - 1
            low, high = interval(np.abs(a_model[use] / boot[:, use] - 1).max(-1), level)
            below, above = use & (force < context.crossover_force), use & (force >= context.crossover_force)
            sys_low = _systematic(a_model, mean, boot, below, level)
            sys_high = _systematic(a_model, mean, boot, above, level)
            inside = (dev[use] >= band[0][use]) & (dev[use] <= band[1][use])
            combo_rows.append({
                **base, "max_rel_dev": float(np.abs(dev[use]).max()), "max_rel_dev_ci_low": low,
                "max_rel_dev_ci_high": high, "rms_rel_dev": float(np.sqrt(np.mean(dev[use] ** 2))),
                **dict(zip(("systematic_low", "systematic_low_ci_low", "systematic_low_ci_high",
                            "systematic_low_verdict"), sys_low)),
                **dict(zip(("systematic_high", "systematic_high_ci_low", "systematic_high_ci_high",
                            "systematic_high_verdict"), sys_high)),
                "inside_band": float(inside.mean()), "force_min": float(force[use].min() / norm),
                "force_max": float(force[use].max() / norm), "note": ""})
        scored = sorted((r for r in combo_rows if "rms_rel_dev" in r), key=lambda r: r["rms_rel_dev"])
        for rank, r in enumerate(scored, start=1):
            r["rank"] = rank
        rows += combo_rows
    table = pd.DataFrame(rows, columns=list(AREA_COLUMNS)) if rows else pd.DataFrame(columns=AREA_COLUMNS)
    return table, curves
