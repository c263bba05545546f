"""The adhesive runs of a study merged (``results/adhesion/adhesion.nc``) and their pull-off table.

One group per surface kind over the sweep's axes (``work_of_adhesion`` > 0 only), ``seed`` and
``retract``: the retract paths and the pull-off of every run. The table (``pull_off.csv``) has one
row per adhesive combination:

* ``pull_off`` — the ensemble mean of the pull-off force ``F/(E* L²)`` (negative: tensile), with
  its percentile bootstrap interval over seeds (``fit.bootstrap``, ``fit.confidence``);
* ``pull_off_jkr`` — the smooth sphere's ``−(3/2)πwR`` (Johnson, Kendall & Roberts 1971), and
  ``pull_off_ratio = pull_off/pull_off_jkr`` with its interval (spheres);
* ``johnson_parameter`` — ``h_rms/δ_c``, ``δ_c = (3/4)(π²w²R/E*²)^(1/3)`` (Johnson's sphere form
  of Fuller & Tabor's parameter, :func:`roughcontact.models.rough_adhesion.johnson_rough_sphere_parameter`);
* ``jkr_radius_cells`` — JKR's contact radius at pull-off, ``a³ = 9πwR²/(8E*)``, in cells: how well
  the grid resolves the detachment (the method converges to JKR as it grows,
  :mod:`roughcontact.bem.adhesion`);
* ``method_error`` — the method's own relative pull-off error at that resolution,
  :func:`method_error` (the detachment criterion's pull-off over JKR's minus 1, measured on the
  smooth sphere; NaN below 10 cells, where it was not measured, and for a flat surface, which has
  no JKR radius); ``resolved`` — whether that error is at most :data:`RESOLVED_ERROR` (3 %, i.e.
  JKR's pull-off radius of about 46 cells or more): a run below resolution keeps its row and is
  marked, and the claims (n)–(p) do not judge it (:mod:`roughcontact.study.claims.adhesion`). For a
  rough sphere the error is that of the smooth sphere at the same grid: its contact detaches in
  patches smaller than JKR's radius, so the estimate is a lower bound there;
* ``preload_radius_ratio`` — the contact radius ``√(A/π)`` at the largest load (the start of the
  retract path, mean over seeds) over JKR's pull-off radius: below 1 the preload caps the pull-off
  (:mod:`roughcontact.study.runs.adhesive`);
* ``sticky_fraction`` — the fraction of seeds whose pull-off is tensile.
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import MergeError
from ..files import runfile
from ..config.axes import coordinate_attrs
from ..runs import naming as runs
from .ensemble import combinations
from .merge import gather, kind_layouts
from ..runs.jobs import job_settings
from .statistics import bootstrap_indices, interval
from ..config.settings import StudySettings

__all__ = ["adhesive_runs", "merge_adhesion", "pull_off_table", "method_error", "resolved",
           "RESOLVED_ERROR", "RESOLVED_CELLS", "ERROR_CELLS", "METHOD_ERRORS"]

#: the detachment criterion's pull-off over JKR's minus 1 at JKR's pull-off radius of 10, 20, 40 and 80
#: cells (c = 2.1; measured 2026-11-25 on the smooth sphere on the free half-space,
#: tests/test_adhesion_jkr_convergence.py and docs/guide/adhesion.md; 80 cells on 200², measured, not
#: tested): the force just before each detachment, i.e. the method's own pull-off without the sampling of
#: a retract path. The study's retract refines its least force by sub-steps of about 0.003 a_c²/R, so
#: its pull-off is that: the adhesion preset's smooth spheres, 1.111 at 12.4 cells and 1.079 at 17.9,
#: against 1.113 and 1.076 from this table.
ERROR_CELLS, METHOD_ERRORS = (10.0, 20.0, 40.0, 80.0), (0.135, 0.064, 0.035, 0.009)
#: the largest method error of a resolved adhesive run (issue #30: above it the method's own error is as
#: large as the effects the claims test)
RESOLVED_ERROR = 0.03
#: JKR's pull-off radius in cells at which :func:`method_error` falls to :data:`RESOLVED_ERROR` (≈ 45.7)
RESOLVED_CELLS = float(np.exp(np.interp(-RESOLVED_ERROR, -np.asarray(METHOD_ERRORS), np.log(ERROR_CELLS))))


def method_error(cells: float) -> float:
    """The detachment criterion's relative pull-off error (pull-off over JKR's minus 1) at JKR's
    pull-off radius of *cells* cells: the measured values :data:`ERROR_CELLS`, :data:`METHOD_ERRORS`
    interpolated linearly in ``ln cells``, held beyond 80 cells; NaN below 10 cells (not measured)
    or for a NaN *cells*."""
    if not cells >= ERROR_CELLS[0]:
        return math.nan
    return float(np.interp(math.log(cells), np.log(ERROR_CELLS), METHOD_ERRORS))


def resolved(table) -> np.ndarray:
    """Whether each row of a pull-off table is resolved: its ``resolved`` column, or for a table
    without one (written before it) the same rule from ``jkr_radius_cells``: :func:`method_error`
    at most :data:`RESOLVED_ERROR` (a NaN error, below 10 cells or without a JKR radius, is not)."""
    if not len(table):
        return np.zeros(0, dtype=bool)
    if "resolved" in table:
        return table["resolved"].to_numpy().astype(bool)
    cells = table["jkr_radius_cells"].to_numpy(float) if "jkr_radius_cells" in table else np.full(len(table), np.nan)
    return np.array([method_error(c) <= RESOLVED_ERROR for c in cells], dtype=bool)


def adhesive_runs(study) -> list[dict]:
    """The runs of :func:`roughcontact.study.runs.naming.runs` with a work of adhesion, in its order."""
    return [r for r in runs.runs(study) if r["work_of_adhesion"] > 0]


def merge_adhesion(study, paths) -> dict:
    """``{kind: Dataset}`` of the adhesive run files *paths* (one per run of :func:`adhesive_runs`,
    in its order; module docstring)."""
    import xarray as xr

    study = StudySettings.of(study)
    table = adhesive_runs(study)
    if len(paths) != len(table):
        raise MergeError(f"the adhesion merge got {len(paths)} run files for {len(table)} adhesive runs")
    variables_of = {**runfile.RETRACT_VARIABLES, **runfile.PULL_OFF_VARIABLES}
    groups = {}
    for layout in kind_layouts(study, table, paths):
        # each an adhesive run: read_run checks its retract path and pull-off
        data = gather(layout, lambda row: job_settings(study, row),
                      {name: meta.dtype for name, meta in variables_of.items()}).data
        count = data["retract_force"].shape[-1]
        dims = (*layout.axes, "seed")
        variables = {name: ((*dims, "retract") if name in runfile.RETRACT_VARIABLES else dims, values,
                            {"long_name": variables_of[name].long_name, "units": variables_of[name].units})
                     for name, values in data.items()}
        groups[layout.kind] = xr.Dataset(
            variables,
            coords={**{a: (a, layout.coords[a], coordinate_attrs(a)) for a in dims},
                    "retract": ("retract", np.arange(count), runfile.RETRACT_ATTRS)},
            attrs={"surface_kind": layout.kind, "half_space": layout.half_space})
    return groups


def pull_off_table(groups: dict, study):
    """``pull_off.csv`` (module docstring) of the merged adhesive groups."""
    import pandas as pd

    # here, not at the top: the workflow imports this module for adhesive_runs (scipy.optimize, .integrate)
    from ...models.adhesion import jkr_pull_off
    from ...models.rough_adhesion import johnson_rough_sphere_parameter

    study = StudySettings.of(study)
    E, L, n = study.e_star, study.grid.length, study.grid.n
    fit = study.fit
    rows = []
    for kind, ds in groups.items():
        indices = bootstrap_indices(ds.sizes["seed"], fit.bootstrap)
        for combo, sub in combinations(ds, "pull_off_force", ("seed",)):
            force = sub["pull_off_force"].values / (E * L**2)   # (seed,)
            mean = float(force.mean())
            low, high = interval(force[indices].mean(1), fit.confidence) if force.size > 1 else (math.nan, math.nan)
            w, radius = combo["work_of_adhesion"], combo.get("radius", math.inf)
            row = {"kind": kind, **combo, "pull_off": mean, "pull_off_ci_low": low, "pull_off_ci_high": high,
                   "sticky_fraction": float(np.mean(force < 0)), "n_seeds": int(force.size)}
            if math.isfinite(radius):
                jkr, a_jkr = jkr_pull_off(radius=radius, e_star=E, work_of_adhesion=w)
                jkr /= E * L**2
                cells = sub["retract_contact_cells"].isel(retract=0).values
                preload = float(np.mean(np.sqrt(cells / math.pi))) * (L / n)
                row.update(pull_off_jkr=jkr, pull_off_ratio=mean / jkr, pull_off_ratio_ci_low=high / jkr,
                           pull_off_ratio_ci_high=low / jkr, preload_radius_ratio=preload / a_jkr,
                           johnson_parameter=johnson_rough_sphere_parameter(combo["h_rms"], radius=radius, e_star=E,
                                                                            work_of_adhesion=w),
                           jkr_radius_cells=a_jkr / (L / n))
            # the method's own error at the run's resolution, and whether it is resolved (module docstring)
            row["method_error"] = method_error(row.get("jkr_radius_cells", math.nan))
            row["resolved"] = bool(row["method_error"] <= RESOLVED_ERROR)
            rows.append(row)
    return pd.DataFrame(rows)
