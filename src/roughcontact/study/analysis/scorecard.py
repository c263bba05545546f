"""The model scorecard: contact theories against the BEM ensemble of every sphere combination.

Each model of the registry (:mod:`roughcontact.models.scorecard`) predicts the stiffness ``k(F)`` of a rough sphere from what the
configuration says about the surface (H, h_rms, R, the body exponent m, L, n) and, for
``eq16_fitted``, the ζ(H) fitted on the same study. It is scored on the resolved loads of the
ensemble mean (mean contact cells ≥ ``fit.resolved_cells``, as for the verdicts) by

* ``max_rel_dev = max_F |k_model/k_BEM − 1|`` with a 95 % bootstrap-over-seeds interval (the
  ensemble mean recomputed on every resample; the model is deterministic), and
* ``rms_rel_dev``, the root-mean-square of the same deviations.

A model that does not apply to a combination (Greenwood–Tripp off the paraboloid or with a
roll-off or cutoff) has no row for it; an adhesive combination (``work_of_adhesion`` > 0) has
none (the models are elastic; its pull-off is ``results/adhesion/pull_off.csv``). Forces are ``F/(E* L²)``, stiffnesses ``k/(E* L)``.

``paper_setting`` is :func:`roughcontact.study.config.axes.paper_setting`: every optional axis at the
paper's value. Each model declares the optional axes it models
(:attr:`roughcontact.models.scorecard.Model.axes`) and reads every optional axis of the
combination in :attr:`~roughcontact.models.scorecard.Surface.axes`; on a combination off the
paper's value of an axis the model does not declare, ``not_modelled`` names those axes and the
row keeps its deviations but is not scored (no ``rank``, every verdict
``untested: not modelled: <axes>``; :mod:`roughcontact.study.analysis.not_modelled`).

Grid error (``grid.coarse``, :mod:`roughcontact.study.analysis.grid_error`): with the same surfaces pressed
on a coarser grid, ``g = k̄_coarse/k̄ − 1`` at each load gives the estimate ``ê`` of the study's own
grid error (:func:`~roughcontact.study.analysis.grid_error.estimate`: Richardson's with the measured
order and a safety factor, validated to bound the error against a twice finer grid); the
scorecard reads ``ê`` (tables without it: ``|g|``) as the grid error ``g`` below. It adds, per
model and combination, over the same resolved loads:

* ``grid_error_max``: the largest ``|g|``; ``grid_resolved``: the fraction of loads where
  ``|g|`` is at most half the band's half-width (:data:`~roughcontact.study.analysis.grid_error.GRID_ERROR_FRACTION`);
* ``inside_band_total``: the fraction of loads where the model lies inside the ensemble's band
  widened by the grid error in quadrature, ``[−√(b₋² + g²), √(b₊² + g²)]``;
* ``grid_error_low`` / ``grid_error_high``: the weighted mean ``|g|`` of each branch (the weights
  of the systematic deviation), and ``systematic_low_total_verdict`` /
  ``systematic_high_total_verdict``: the verdict on 0 of the systematic deviation's interval
  widened by that mean (``differs``: a model error that neither sampling nor grid explains);
* ``grid_error_note``: empty where the grid error is measured; otherwise why not (no companion
  study, ``grid.coarse`` null; or no companion value at the resolved loads), and then every
  grid-error column is NaN and every ``*_total_verdict`` ``untested: grid error not measured``.

Decision (:mod:`roughcontact.study.analysis.decision`): per combination, the recommended model minimises
``S = max_b sqrt(mean_{F ∈ b}(|k_model/k_BEM − 1| + |g_F|)²)`` (``g`` 0 where not measured, and
the page says so) among the scored rows that hold (:func:`~roughcontact.study.analysis.decision.holds`:
each branch within 3 %, or 5 % and consistent, and inside the widened band at 80 % of the loads;
among every scored row when none holds); the others are ``tied`` (paired bootstrap over the seeds) or
``worse``; a row outside its model's stated range (``outside_range``,
:attr:`roughcontact.models.scorecard.Model.ranges`) is flagged and never recommended. The table
is sorted by combination, then decision.
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ...models import paper
from ...models import scorecard as registry
from ..config import axes
from . import decision
from ..runs import naming as runs
from . import not_modelled as unmodelled
from .combination import Combination, combination, combo_label
from .ensemble import combinations, resolved
from .statistics import bootstrap_indices, interval, inverse_variance_weights, verdict, weighted_deviation
from .crossover import NO_SPHERE
from .grid_error import statement as grid_error_statement
from ..config.settings import StudySettings

__all__ = ["Combination", "MODELS_COLUMNS", "scorecard", "combo_label", "empty_reason", "precomputed_curves"]

log = logging.getLogger(__name__)


def _combinations(ds, study: StudySettings, zeta_of: dict):
    """``(Combination, (seed, force) slice)`` of every sphere combination (:func:`ensemble.combinations`)."""
    for where, sub in combinations(ds):
        combo = combination(where, study)
        combo["zeta_fit"] = float(zeta_of.get(combo["hurst"], math.nan))
        yield combo, sub


def _crossover(c: Combination) -> float:
    """The branches' border ``F/(E* L²)``: eq. 17 with the study's fitted ζ, else eq. 13's."""
    zeta = c["zeta_fit"] if math.isfinite(c["zeta_fit"]) else float(paper.zeta_estimate(c["hurst"]))
    return float(paper.crossover_force(c["radius"], hurst=c["hurst"], h_rms=c["h_rms"], length=c["length"],
                                       e_star=c["e_star"], zeta=zeta, exponent=c["exponent"])
                 / (c["e_star"] * c["length"] ** 2))


def _systematic(k_model, k_mean, k_boot, use, branch: str, level: float) -> dict:
    """The systematic deviation of a model on one branch: the mean of ``k_model/k_BEM − 1`` over the
    loads *use*, each weighted by the inverse variance of the ensemble mean there (its bootstrap),
    with the interval of the same mean over the bootstrap's ensembles and the verdict on 0
    (``differs``: the deviation is significant)."""
    keys = [f"systematic_{branch}", f"systematic_{branch}_ci_low", f"systematic_{branch}_ci_high"]
    if use.sum() < 1:
        return {**dict.fromkeys(keys, math.nan), f"systematic_{branch}_verdict": "untested: no resolved load",
                f"n_loads_{branch}": 0}
    value, low, high = weighted_deviation(k_model, k_mean, k_boot, use, level)
    return {keys[0]: value, keys[1]: low, keys[2]: high, f"systematic_{branch}_verdict": verdict(0.0, low, high),
            f"n_loads_{branch}": int(use.sum())}


#: the reason of ``grid_error_note`` without a companion study
NOT_MEASURED = grid_error_statement(None, None).sentence()
#: ... and with one that has no value at the combination's resolved loads
NOT_MEASURED_HERE = "grid error not measured: the companion has no value at the resolved loads"
#: the grid-error columns, NaN where it is not measured
GRID_COLUMNS = ("grid_error_max", "grid_resolved", "inside_band_total", "grid_error_low", "grid_error_high")


def _grid_errors(grid_error, combo: Combination, force_norm) -> np.ndarray | None:
    """The grid error of the table at each load of *combo*: its ``grid_error_estimate`` (older
    tables: ``|grid_error|``), NaN where the table has none."""
    if grid_error is None or not len(grid_error):
        return None
    column = "grid_error_estimate" if "grid_error_estimate" in grid_error else "grid_error"
    rows = grid_error
    for axis in runs.AXES["sphere"]:
        if axis in rows:
            rows = rows[np.isclose(rows[axis].to_numpy(float), combo[axis], rtol=1e-12, atol=0)
                        | (np.isinf(rows[axis].to_numpy(float)) & math.isinf(combo[axis]))]
    out = np.full(force_norm.size, np.nan)
    for force, g in zip(rows["force_normalized"].to_numpy(float), np.abs(rows[column].to_numpy(float))):
        match = np.isclose(force_norm, force, rtol=1e-9, atol=0)
        out[match] = g
    return out


def _not_measured(reason: str) -> dict:
    """The grid-error columns of a row without a measured grid error: NaN, and the *reason*."""
    return {**dict.fromkeys(GRID_COLUMNS, math.nan),
            **{f"systematic_{b}_total_verdict": "untested: grid error not measured" for b in ("low", "high")},
            "grid_error_note": reason}


def _with_grid(dev, band, g, use, weight_use, k_boot, k_mean, systematic: dict) -> dict:
    """The grid-error columns of one model (module docstring)."""
    from .grid_error import GRID_ERROR_FRACTION

    g_abs = np.abs(g)
    lower = -np.sqrt(band[0] ** 2 + g_abs ** 2)
    upper = np.sqrt(band[1] ** 2 + g_abs ** 2)
    inside = (dev[use] >= lower[use]) & (dev[use] <= upper[use])
    half = 0.5 * (band[1] - band[0])
    out = {"grid_error_max": float(np.nanmax(g_abs[use])) if np.isfinite(g_abs[use]).any() else math.nan,
           "grid_resolved": float(np.mean(g_abs[use] <= GRID_ERROR_FRACTION * half[use])),
           "inside_band_total": float(inside.mean()), "grid_error_note": ""}
    if not np.isfinite(g_abs[use]).any():
        return _not_measured(NOT_MEASURED_HERE)
    for branch, mask in weight_use.items():
        key = f"grid_error_{branch}"
        if mask.sum() < 1:
            out.update({key: math.nan, f"systematic_{branch}_total_verdict": "untested: no resolved load"})
            continue
        weight = inverse_variance_weights(k_boot, k_mean, mask)
        mean_g = float(np.sum(weight * g_abs[mask]) / weight.sum())
        low = systematic[f"systematic_{branch}_ci_low"] - mean_g
        high = systematic[f"systematic_{branch}_ci_high"] + mean_g
        out.update({key: mean_g, f"systematic_{branch}_total_verdict": verdict(0.0, low, high)})
    return out


#: the columns of models.csv (the header of a table without a row; a row has more: the systematic
#: deviations per branch, the grid error and the decision's columns)
MODELS_COLUMNS = ("model", "combination", "max_rel_dev", "max_rel_dev_ci_low", "max_rel_dev_ci_high", "rms_rel_dev",
                  "n_loads", "force_min", "force_max", "paper_setting", "inside_band", "crossover_force", "rank")


def empty_reason(study) -> str:
    """Why models.csv has no row: no sphere in the sweep, or only adhesive spheres (the models are
    elastic), or no sphere combination with a resolved load a model predicts."""
    study = StudySettings.of(study)
    if not any(math.isfinite(r) for r in study.radius):
        return NO_SPHERE
    works = [w for w in study.work_of_adhesion if w is not None]
    if works and all(w > 0 for w in works):
        return "every sphere of the sweep is adhesive (work_of_adhesion > 0) and the scored models are elastic"
    return f"no sphere combination has a load with at least {study.fit.resolved_cells} contact cells that a model predicts"


def scorecard(groups: dict, zeta_df, study, grid_error=None, precomputed=None, *, not_measured: str = NOT_MEASURED):
    """``models.csv`` as a DataFrame (one row per model and sphere combination), and a Dataset of
    the relative deviations ``k_model/k_BEM − 1`` per load with the ensemble's 95 % band.

    *grid_error*: the table of :func:`roughcontact.study.analysis.grid_error.grid_error` of the study against
    its companion on ``grid.coarse`` (or ``None``): adds the grid-error columns (module docstring).
    *precomputed*: the groups of ``model_curves.nc`` (:mod:`roughcontact.study.analysis.model_curves`;
    ``None``: every model computed here), read where they were computed for the same surface and loads.
    *not_measured*: the ``grid_error_note`` of a combination without a grid error (the study's
    :class:`~roughcontact.study.analysis.grid_error.GridErrorStatement`'s sentence)."""
    from . import model_curves

    import pandas as pd
    import xarray as xr

    if "sphere" not in groups:
        return pd.DataFrame(columns=[MODELS_COLUMNS[0], *runs.AXES["sphere"], *MODELS_COLUMNS[1:]]), {}
    study = StudySettings.of(study)
    ds = groups["sphere"]
    L, E = study.grid.length, study.e_star
    min_cells = study.fit.resolved_cells
    level = study.fit.confidence
    indices = bootstrap_indices(ds.sizes["seed"], study.fit.bootstrap)
    zeta_of = dict(zip(zeta_df["hurst"], zeta_df["zeta"])) if len(zeta_df) else {}
    force_norm = ds["force"].values / (E * L**2)
    rows, curves = [], {}
    for combo, sub in _combinations(ds, study, zeta_of):
        if combo.get("work_of_adhesion", 0.0) > 0:   # the models are elastic
            continue
        k = sub["stiffness"].values
        k_mean = k.mean(0)
        k_boot = k[indices].mean(1)                               # (resample, force)
        use_load = resolved(sub["contact_cells"].values.mean(0), min_cells)
        band = np.percentile(k_boot / k_mean - 1, [50 * (1 - level), 50 * (1 + level)], axis=0)
        label = combo_label(combo)
        f_tr = _crossover(combo)
        g = _grid_errors(grid_error, combo, force_norm)
        dev_of, combo_rows, combo_boot = {}, [], []
        surface = combo.surface()
        known = model_curves.known(precomputed, label, sub["force"].values, surface)
        for name, k_model in registry.predict(sub["force"].values, surface, known).items():
            use = use_load & np.isfinite(k_model)
            dev = k_model / k_mean - 1
            dev_of[name] = dev
            if not use.any():
                continue
            low, high = interval(np.abs(k_model[use] / k_boot[:, use] - 1).max(-1), level)
            inside = (dev[use] >= band[0][use]) & (dev[use] <= band[1][use])
            branches = {"low": use & (force_norm < f_tr), "high": use & (force_norm >= f_tr)}
            systematic = {**_systematic(k_model, k_mean, k_boot, branches["low"], "low", level),
                          **_systematic(k_model, k_mean, k_boot, branches["high"], "high", level)}
            grid = _not_measured(not_measured) if g is None else _with_grid(dev, band, g, use, branches, k_boot,
                                                                            k_mean, systematic)
            combo_boot.append(decision.inputs(k_model, k_mean, k_boot, use, branches, g))
            combo_rows.append(unmodelled.unscored({
                "model": name, **{a: combo[a] for a in runs.AXES["sphere"]}, "combination": label,
                "max_rel_dev": float(np.abs(dev[use]).max()), "max_rel_dev_ci_low": low,
                "max_rel_dev_ci_high": high, "rms_rel_dev": float(np.sqrt(np.mean(dev[use] ** 2))),
                "n_loads": int(use.sum()), "force_min": float(force_norm[use].min()),
                "force_max": float(force_norm[use].max()), "paper_setting": combo.paper_setting,
                unmodelled.COLUMN: unmodelled.not_modelled(name, combo, L),
                decision.OUTSIDE: registry.models()[name].outside(combo),
                "inside_band": float(inside.mean()), "crossover_force": f_tr, **systematic, **grid,
            }))
        rows.extend(decision.decide(combo_rows, combo_boot, level))
        curves[label] = xr.Dataset(
            {**{name: ("force", dev, {"long_name": f"k_{name}/k_BEM - 1", "units": "1"})
                for name, dev in dev_of.items()},
             "band_low": ("force", band[0], {"long_name": f"{level:.0%} band of the ensemble mean, low", "units": "1"}),
             "band_high": ("force", band[1], {"long_name": f"{level:.0%} band of the ensemble mean, high", "units": "1"}),
             "resolved": ("force", use_load.astype("i1"), {"long_name": "resolved load (1) or not (0)", "units": "1"}),
             **({} if g is None else {"grid_error": ("force", g, {
                 "long_name": "grid error estimate |k_BEM/k_converged - 1| (grid.coarse)", "units": "1"})})},
            coords={"force_normalized": ("force", force_norm, {"long_name": "F/(E* L^2)", "units": "1"})},
            attrs={k: v for k, v in combo.items()})
    table = pd.DataFrame(rows) if rows else pd.DataFrame(columns=[MODELS_COLUMNS[0], *runs.AXES["sphere"],
                                                                   *MODELS_COLUMNS[1:]])
    if len(table):
        table["rank"] = unmodelled.rank(table, "combination")
        table = decision.sort(table)
    return table, curves


def _sphere_runs(study) -> list[tuple]:
    """``(where, seed-0 run)`` of every elastic sphere combination of *study*: *where* its axes as
    merged-file coordinates (:func:`roughcontact.study.runs.naming.coordinate`), as the scorecard
    reads them from ``stiffness.nc``."""
    study = StudySettings.of(study)
    L = study.grid.length
    out = []
    for c in runs.combinations(study):
        if c["kind"] != "sphere" or not runs.normal_representative(study, c) or c.get("work_of_adhesion", 0.0) > 0:
            continue
        where = {a: runs.coordinate(a, c[a], L) if a in runs.DEFAULTS else float(c[a]) for a in runs.AXES["sphere"]}
        out.append((where, {**c, "seed": study.seeds[0]}))
    return out


def precomputed_curves(study) -> dict:
    """``{run name: Dataset}`` of every elastic sphere combination of *study*: the curves of
    ``model_curves.nc`` (:mod:`roughcontact.study.analysis.model_curves`), from the configuration alone."""
    import xarray as xr

    from ...models.greenwood_tripp import self_affine_sphere_curve
    from ..runs import jobs
    from .model_curves import DECLINED, gt_key, surface_key

    study = StudySettings.of(study)
    L, E, n = study.grid.length, study.e_star, study.grid.n
    names = [name for name, model in registry.models().items() if model.precomputable]
    out = {}
    for where, run in _sphere_runs(study):
        combo = Combination(where)
        combo.update(n=n, length=L, e_star=E, zeta_fit=math.nan)
        surface = combo.surface()
        force = jobs.job_settings(study, run).forces()
        predicted, declined = {}, []
        for name in names:
            k = registry.models()[name].predict(force, surface)
            if k is None:
                declined.append(name)
            else:
                predicted[f"k_{name}"] = ("force", np.asarray(k, dtype=float),
                                          {"long_name": f"stiffness of model {name}", "units": "e_star * length"})
        attrs = {"surface": surface_key(surface), "models": " ".join(names), DECLINED: " ".join(declined)}
        if axes.paper_setting(combo, L):
            parameters = dict(hurst=combo["hurst"], h_rms=combo["h_rms"], n=n, length=L, radius=combo["radius"],
                              e_star=E)
            gt = self_affine_sphere_curve(**parameters)
            attrs["gt"] = gt_key(**parameters)
            predicted["gt_force"] = ("gt_point", gt.force, {"long_name": "Greenwood-Tripp force (Fig. 3)",
                                                            "units": "e_star * length^2"})
            predicted["gt_stiffness"] = ("gt_point", gt.stiffness, {"long_name": "Greenwood-Tripp stiffness (Fig. 3)",
                                                                    "units": "e_star * length"})
            attrs["gt_mu"] = float(gt.mu)
        out[combo_label(combo)] = xr.Dataset(
            predicted, coords={"force": ("force", force, {"long_name": "normal force", "units": "e_star * length^2"})},
            attrs=attrs)
    return out
