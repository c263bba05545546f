"""The adhesive runs of a study merged (``results/adhesion/adhesion.nc``) and their pull-off table.

One group per surface kind over the sweep's axes (``work_of_adhesion`` > 0 only), ``seed`` and
``retract``: the retract paths and the pull-off of every run. The table (``pull_off.csv``) has one
row per adhesive combination:

* ``pull_off`` — the ensemble mean of the pull-off force ``F/(E* L²)`` (negative: tensile), with
  its percentile bootstrap interval over seeds (``fit.zeta.bootstrap``, ``fit.zeta.confidence``);
* ``pull_off_jkr`` — the smooth sphere's ``−(3/2)πwR`` (Johnson, Kendall & Roberts 1971), and
  ``pull_off_ratio = pull_off/pull_off_jkr`` with its interval (spheres);
* ``johnson_parameter`` — ``h_rms/δ_c``, ``δ_c = (3/4)(π²w²R/E*²)^(1/3)`` (Johnson's sphere form
  of Fuller & Tabor's parameter, :func:`roughcontact.models.rough_adhesion.johnson_rough_sphere_parameter`);
* ``jkr_radius_cells`` — JKR's contact radius at pull-off, ``a³ = 9πwR²/(8E*)``, in cells: how well
  the grid resolves the detachment (the method converges to JKR as it grows,
  :mod:`roughcontact.bem.adhesion`);
* ``preload_radius_ratio`` — the contact radius ``√(A/π)`` at the largest load (the start of the
  retract path, mean over seeds) over JKR's pull-off radius: below 1 the preload caps the pull-off
  (:mod:`roughcontact.study.runs.adhesive`);
* ``sticky_fraction`` — the fraction of seeds whose pull-off is tensile.
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import MergeError
from ...models.adhesion import jkr_pull_off
from ...models.rough_adhesion import johnson_rough_sphere_parameter
from ..files import provenance, runfile
from ..config.axes import coordinate_attrs
from ..runs import naming as runs
from .ensemble import combinations
from .merge import gather, kind_layouts
from ..runs.jobs import job_settings
from .statistics import bootstrap_indices, interval
from ..config.settings import StudySettings

__all__ = ["adhesive_runs", "merge_adhesion", "pull_off_table", "run_adhesion"]


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

    study = StudySettings.of(study)
    E, L, n = study.e_star, study.grid.length, study.grid.n
    zeta = study.fit.zeta
    rows = []
    for kind, ds in groups.items():
        indices = bootstrap_indices(ds.sizes["seed"], zeta.bootstrap)
        for combo, sub in combinations(ds, "pull_off_force", ("seed",)):
            force = sub["pull_off_force"].values / (E * L**2)   # (seed,)
            mean = float(force.mean())
            low, high = interval(force[indices].mean(1), zeta.confidence) if force.size > 1 else (math.nan, math.nan)
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
            rows.append(row)
    return pd.DataFrame(rows)


def run_adhesion(study, run_files, out_nc, out_csv) -> None:
    """``adhesion`` rule: the adhesive run files -> ``adhesion.nc`` (one group per kind) and
    ``pull_off.csv``."""
    from ..files.io import write_csv, write_groups

    study = StudySettings.of(study)
    groups = merge_adhesion(study, list(run_files))
    write_groups(out_nc, groups, provenance.provenance_attrs(
        config=study.config, title="roughcontact adhesive runs: retract paths and pull-off",
        forces="e_star * length**2 (pull_off.csv: F/(E* L^2))"))
    write_csv(pull_off_table(groups, study), out_csv)
