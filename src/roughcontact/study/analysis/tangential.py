"""The tangential runs of a study merged (``results/tangential/tangential.nc``) and their estimates.

A study with the axis ``poisson`` (and ``friction``) has, beside its normal merged files, one file
of two groups over the normal sphere axes, ``poisson`` (and ``friction``) and ``seed``:

* ``full_stick`` — per load (``force``): the normal stiffness ``k_n``, the depth, the contact cells
  and the full-stick tangential stiffness ``k_t`` (runs at the study's first ``friction``: the
  tangential axes do not change the normal path, nor ``μ`` the full-stick ``k_t``);
* ``partial_slip`` (``friction > 0``) — per normal load of ``tangential.at`` (``slip_load``, its
  coordinate ``F/(E* L²)``) and tangential load (``slip_step``, ``Q/(μP)``): the
  :data:`roughcontact.study.files.runfile.SLIP_VARIABLES`.

The estimates (:func:`stiffness_ratio`, :func:`slip_shape`, :func:`micro_slip`) are ensemble means
with percentile bootstrap intervals over seeds (:mod:`roughcontact.study.analysis.statistics`),
on the fractal branch (resolved loads below the crossover force ``F_tr``) or the Hertz branch
(above it), :func:`branches`. Models (:mod:`roughcontact.models.tangential`): Mindlin's
``k_t/k_n = 2(1 − ν)/(2 − ν)``; Cattaneo–Mindlin ``k_t(Q)/k_t(0) = (1 − Q/μP)^(1/3)``;
Ciavarella–Jäger ``k_t(Q)/k_t(0) = k_n(P − Q/μ)/k_n(P)`` from the run's own normal path
(log-log interpolation between its loads); Grzemba et al. (2014) ``δ_max = μ d E*/G*``.

Forces ``F/(E* L²)``, stiffnesses ``k/(E* L)``.
"""
from __future__ import annotations

import dataclasses
import logging
import math

import numpy as np

from ...models import tangential as theory
from ..config.axes import coordinate_attrs
from ..config.settings import StudySettings
from .. import quantities
from ..files import provenance, runfile
from ..runs import naming as runs
from ..runs.jobs import job_settings
from .ensemble import combinations, resolved
from ...errors import MergeError
from .merge import KindLayout, force_coords, gather, layout_of
from .statistics import bootstrap_indices, interval

__all__ = ["merge_tangential", "Branches", "branches", "Estimate", "stiffness_ratio",
           "ciavarella_jaeger", "crossover_row", "combination_branches", "slip_combinations", "slip_shape", "micro_slip", "per_load_table"]

log = logging.getLogger(__name__)


def _dataset(layout: KindLayout, gathered, variables: dict, inner: dict, attrs: dict):
    import xarray as xr

    dims = (*layout.axes, "seed")
    data = {}
    for name, meta in variables.items():
        data[name] = ((*dims, *meta.dims), gathered.data[name], {"long_name": meta.long_name, "units": meta.units})
    coords = {a: (a, layout.coords[a], coordinate_attrs(a)) for a in (*layout.axes, "seed")}
    return xr.Dataset(data, coords={**coords, **inner}, attrs=attrs)


def merge_tangential(study, paths) -> dict:
    """``{"full_stick": ds, "partial_slip": ds}`` (the second with ``friction > 0`` only) of the run
    files *paths*, one per run of :func:`roughcontact.study.runs.naming.runs` in its order (the
    ``merge`` rule's inputs; module docstring)."""
    study = StudySettings.of(study)
    table = runs.runs(study)
    if len(paths) != len(table):
        raise MergeError(f"the tangential merge got {len(paths)} run files for {len(table)} runs of the config")
    pairs = [(row, path) for row, path in zip(table, paths) if row["kind"] == "sphere" and row.get("poisson") is not None]
    if not pairs:
        return {}
    def expected(row):
        return job_settings(study, row)

    def group(layout, variables, inner):
        got = gather(layout, expected, {n: m.dtype for n, m in variables.items()})
        return _dataset(layout, got, variables, inner, {"surface_kind": "sphere", "half_space": layout.half_space,
                                                        "run_git_commits": provenance.canonical_json(got.commits)})

    normal = runs.AXES["sphere"]
    stick = [(r, p) for r, p in pairs if r.get("friction", 0.0) == study.friction[0]]
    groups = {"full_stick": group(
        layout_of(study, "sphere", stick, (*normal, "poisson")),
        {**quantities.variables(("stiffness", "depth", "contact_cells")), **runfile.TANGENTIAL_VARIABLES},
        force_coords(study, "sphere"))}
    slip = [(r, p) for r, p in pairs if r.get("friction", 0.0) > 0]
    if slip:
        first = expected(slip[0][0])
        loads = np.asarray(first.slip_loads)
        groups["partial_slip"] = group(
            layout_of(study, "sphere", slip, (*normal, "poisson", "friction")), runfile.SLIP_VARIABLES,
            {"slip_load": ("slip_load", study.forces["sphere"].normalized()[loads],
                           {"long_name": "normal force F/(E* L^2) of the partial-slip path", "units": "1"}),
             "slip_load_index": ("slip_load", loads, runfile.SLIP_COORDS["slip_load"][1]),
             "slip_step": ("slip_step", runfile.slip_fractions(first.slip_steps), runfile.SLIP_COORDS["slip_step"][1])})
    return groups


def crossover_row(cross, where: dict):
    """The row of ``crossover.csv`` (*cross*, a DataFrame) of the normal combination of *where*
    (its normal sphere axes, matched to a CSV round trip's digits); ``None`` where there is none."""
    if cross is None or not len(cross):
        return None
    keep = np.ones(len(cross), dtype=bool)
    for axis in runs.AXES["sphere"]:
        if axis in cross and axis in where:
            keep &= np.isclose(cross[axis].to_numpy(float), float(where[axis]), rtol=1e-12, atol=0.0, equal_nan=True)
    return cross[keep].iloc[0] if keep.any() else None


# --------------------------------------------------------------------------
# branches and estimates
# --------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class Branches:
    """The loads of one combination on each branch.

    Attributes
    ----------
    crossover : float
        ``F_tr/(E* L²)``: the measured crossover (``crossover.csv``'s ``Ftr_measured``), else eq. 17's
        (``Ftr_pred_estimate``); NaN without either.
    source : str
        ``"measured"``, ``"eq. 17"`` or ``""``.
    fractal, hertz : numpy.ndarray
        Boolean masks over the loads: resolved (``fit.resolved_cells``) and below / above ``F_tr``.
    """

    crossover: float
    source: str
    fractal: np.ndarray
    hertz: np.ndarray


def branches(force, contact_cells_mean, crossover_row, min_cells: int) -> Branches:
    """:class:`Branches` of the loads *force* (``F/(E* L²)``) with their ensemble-mean contact cells,
    from the combination's row of ``crossover.csv`` (``None``: no crossover, every load unassigned)."""
    force = np.asarray(force, dtype=float)
    ok = np.asarray(resolved(np.asarray(contact_cells_mean, dtype=float), min_cells))
    f_tr, source = math.nan, ""
    if crossover_row is not None:
        measured = float(crossover_row.get("Ftr_measured", math.nan))
        predicted = float(crossover_row.get("Ftr_pred_estimate", math.nan))
        f_tr, source = (measured, "measured") if math.isfinite(measured) else (predicted, "eq. 17")
        if not math.isfinite(f_tr):
            source = ""
    if not math.isfinite(f_tr):
        none = np.zeros(force.shape, dtype=bool)
        return Branches(math.nan, "", none, none)
    return Branches(f_tr, source, ok & (force < f_tr), ok & (force >= f_tr))


def combination_branches(stick, cross, where: dict, study) -> Branches:
    """:func:`branches` of one combination of the ``full_stick`` group (*stick*, dims ``(seed, force)``)
    with its row of ``crossover.csv`` (*cross*, :func:`crossover_row`)."""
    return branches(stick["force_normalized"].values, stick["contact_cells"].mean("seed").values,
                    crossover_row(cross, where), StudySettings.of(study).fit.resolved_cells)


def slip_combinations(groups: dict):
    """``(where, stick, slip)`` of every combination of the ``partial_slip`` group: its axes, its
    ``full_stick`` combination (the same normal axes and ``poisson``; dims ``(seed, force)``) and
    its slice (dims ``(seed, slip_load, slip_step)``)."""
    stick = groups["full_stick"]
    for where, slip in combinations(groups["partial_slip"], "slip_stiffness", ("seed", "slip_load", "slip_step")):
        yield where, stick.sel({k: v for k, v in where.items() if k != "friction"}).transpose("seed", "force"), slip


@dataclasses.dataclass(frozen=True)
class Estimate:
    """An ensemble estimate with its percentile bootstrap interval over seeds.

    Attributes
    ----------
    value, low, high : float
        The estimate and its interval (NaN where nothing is resolved).
    spread : tuple of float
        ``(min, max)`` of the per-load (per-step) values the estimate averages, for the note.
    count : int
        How many loads (steps) it averages.
    """

    value: float
    low: float
    high: float
    spread: tuple
    count: int


_NONE = Estimate(math.nan, math.nan, math.nan, (math.nan, math.nan), 0)


def _estimate(per_seed_fn, n_seeds: int, study: StudySettings) -> Estimate:
    """Evaluate ``per_seed_fn(indices) -> per-item values`` on all seeds and on the bootstrap
    resamples; the estimate is the mean over items."""
    items = per_seed_fn(np.arange(n_seeds))
    finite = np.isfinite(items)
    if not finite.any():
        return _NONE
    value = float(items[finite].mean())
    fit = study.fit
    reps = np.array([np.nanmean(np.where(finite, per_seed_fn(idx), np.nan))
                     for idx in bootstrap_indices(n_seeds, fit.bootstrap)])
    low, high = interval(reps, fit.confidence)
    return Estimate(value, low, high, (float(items[finite].min()), float(items[finite].max())), int(finite.sum()))


def stiffness_ratio(stick, mask, study) -> Estimate:
    """Claim (r): the ensemble's ``k_t/k_n`` (ratio of the ensemble means at each load) averaged over
    the loads of *mask*; *stick*: one combination of the ``full_stick`` group, dims ``(seed, force)``."""
    if not np.any(mask):
        return _NONE
    k_n, k_t = stick["stiffness"].values, stick["tangential_stiffness"].values

    def per_load(idx):
        return k_t[idx][:, mask].mean(0) / k_n[idx][:, mask].mean(0)

    return _estimate(per_load, k_n.shape[0], StudySettings.of(study))


def ciavarella_jaeger(stick, slip_force_index: int, fractions) -> np.ndarray:
    """``(seed, step)``: the normal stiffness ``k_n(P(1 − f))`` of Ciavarella–Jäger's stick zone
    (:func:`roughcontact.models.tangential.ciavarella_jaeger_stiffness_ratio`) on each seed's own
    normal path (log-log interpolation between its loads; NaN below its first load), ``P`` its load
    *slip_force_index*, *fractions* ``f = Q/(μP)``."""
    force = stick["force_normalized"].values
    k_n = stick["stiffness"].values
    target = np.log(force[slip_force_index] * (1 - np.asarray(fractions)))
    out = np.full((k_n.shape[0], len(fractions)), np.nan)
    inside = target >= np.log(force[0]) - 1e-12
    for s in range(k_n.shape[0]):
        out[s, inside] = np.exp(np.interp(target[inside], np.log(force), np.log(k_n[s])))
    return out


def slip_shape(stick, slip, loads, study, *, model: str) -> Estimate:
    """Claim (s): the ensemble's ``k_t(Q)/k_t(0)`` over *model*'s (``"cattaneo"``:
    ``(1 − Q/μP)^(1/3)``; ``"ciavarella-jaeger"``: ``k_n(P(1 − f))/k_n(P)``, :func:`ciavarella_jaeger`),
    averaged over the slip loads *loads* (indices of ``slip_load``) and their steps; *stick*, *slip*:
    one combination of each group, dims ``(seed, force)`` and ``(seed, slip_load, slip_step)``."""
    loads = list(loads)
    if not loads:
        return _NONE
    f = slip["slip_step"].values
    index = slip["slip_load_index"].values
    k_t0 = stick["tangential_stiffness"].values
    k_n = stick["stiffness"].values
    k_q = slip["slip_stiffness"].values
    if model == "cattaneo":
        models = [np.broadcast_to(theory.cattaneo_stiffness_ratio(f), (k_n.shape[0], f.size)) for _ in loads]
        normal = [np.ones(k_n.shape[0]) for _ in loads]
    else:
        models = [ciavarella_jaeger(stick, int(index[j]), f) for j in loads]
        normal = [k_n[:, int(index[j])] for j in loads]

    def per_step(idx):
        values = []
        for j, m, kp in zip(loads, models, normal):
            measured = k_q[idx][:, j, :].mean(0) / k_t0[idx][:, int(index[j])].mean()
            predicted = m[idx].mean(0) / kp[idx].mean()
            values.append(measured / predicted)
        return np.concatenate(values)

    return _estimate(per_step, k_n.shape[0], StudySettings.of(study))


def micro_slip(slip, loads, poisson: float, friction: float, study) -> Estimate:
    """Claim (t): the ensemble's ``δ_max G*/(μ E* d)`` (1 by Grzemba et al.'s law), averaged over
    the slip loads *loads*; ``d`` the approach from first touch, ``G*/E* = 2(1 − ν)/(2 − ν)``."""
    loads = list(loads)
    if not loads:
        return _NONE
    delta = slip["gross_slip_displacement"].values
    depth = slip["slip_depth"].values

    def per_load(idx):
        return delta[idx][:, loads].mean(0) / theory.largest_micro_slip(depth[idx][:, loads].mean(0),
                                                                       friction=friction, poisson=poisson)

    return _estimate(per_load, delta.shape[0], StudySettings.of(study))


def per_load_table(groups: dict, cross, study):
    """``tangential.csv``: per combination of the ``full_stick`` group and load, the ensemble's
    ``k_t/k_n`` with its interval against Mindlin's ratio, and the load's branch."""
    import pandas as pd

    study = StudySettings.of(study)
    ds = groups.get("full_stick")
    columns = [*runs.AXES["sphere"], "poisson", "force", "branch", "crossover_force", "kt_over_kn", "ci_low",
               "ci_high", "mindlin", "rel_dev"]
    if ds is None:
        return pd.DataFrame(columns=columns)
    rows = []
    for where, sub in combinations(ds, "tangential_stiffness"):
        split = combination_branches(sub, cross, where, study)
        mindlin = theory.stiffness_ratio(where["poisson"])
        for i, force in enumerate(sub["force_normalized"].values):
            mask = np.zeros(sub.sizes["force"], dtype=bool)
            mask[i] = True
            est = stiffness_ratio(sub, mask, study)
            branch = "fractal" if split.fractal[i] else "Hertz" if split.hertz[i] else "unresolved"
            rows.append({**where, "force": force, "branch": branch, "crossover_force": split.crossover,
                         "kt_over_kn": est.value, "ci_low": est.low, "ci_high": est.high, "mindlin": mindlin,
                         "rel_dev": est.value / mindlin - 1})
    return pd.DataFrame(rows) if rows else pd.DataFrame(columns=columns)
