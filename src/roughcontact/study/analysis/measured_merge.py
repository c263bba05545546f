"""The runs of one measured surface merged into one NetCDF file (``measured_merge``, ``spectrum_merge``).

One group per kind (``sphere``: dims ``radius, tile|seed, force``; ``flat``: ``tile|seed, force``),
the runs read and placed by the one merge core (:func:`roughcontact.study.analysis.merge.gather` on a
:class:`~roughcontact.study.analysis.merge.KindLayout` whose ensemble is ``tile`` or ``seed``), with the
bootstrap interval of the mean stiffness over the tiles (or seeds), CF ``units`` and provenance.
"""
from __future__ import annotations

import os

import numpy as np

from .. import quantities
from ..files import provenance, runfile
from . import statistics
from ..runs.naming import kind_of
from ..config.settings import StudySettings, ZetaFitSettings
from ..config.units import to_pascals
from .conductance import conductance_variables
from ..runs.measured import job_of, read_surface, run_order, sha256

__all__ = ["merge_surface"]


def merge_surface(study, source: str, name: str, run_files, output, surface_file=None) -> None:
    """Merge the runs of one surface into *output* (NetCDF, one group per kind, atomic).

    *run_files*: paths whose order is :func:`run_order` of the same arguments, each read by
    :func:`roughcontact.study.files.io.read_run` against its :func:`job_of` (a
    :class:`~roughcontact.errors.MergeError` names a missing, foreign or stale one). Each group
    holds the per-run variables over ``(radius,) tile|seed, force`` and, over ``(radius,)
    force``, ``k_mean`` with the percentile bootstrap interval (``fit.bootstrap``
    resamples of the tiles or seeds, level ``fit.confidence``) as ``k_ci_low``,
    ``k_ci_high`` (N/m; NaN with one tile).
    """
    import xarray as xr

    from ..files.io import write_groups
    from .merge import gather

    study = StudySettings.of(study)
    order = run_order(study, source, name, len(run_files) // max(1, len(study.radius)))
    ens = "tile" if source == "topography" else "seed"
    kept = quantities.recorded(job_of(study, source, name, study.radius[0], 0)) if study.radius else ()
    variables = {"force": "f8", **{v: quantities.QUANTITIES[v].dtype for v in kept},
                 **{v: "f8" for v in _NORMALIZED}}
    groups, commits = {}, set()
    for layout in _layouts(study, ens, order, run_files):
        # the one reader: each file checked against its job (title, variables, config_hash, force grid)
        runs_of = gather(layout, lambda row: job_of(study, source, name, row["radius"], row[ens]), variables)
        commits.update(runs_of.commits)
        first = {v: values.reshape(-1, values.shape[-1])[0] for v, values in runs_of.data.items()}
        dims = (*layout.axes, ens, "force")
        coords = {**{a: (a, layout.coords[a], {"long_name": "sphere radius R", "units": study.units.length})
                     for a in layout.axes},
                  ens: (ens, layout.coords[ens], {"long_name": "tile of the scan (row by row)" if ens == "tile"
                                                  else "random seed", "units": "1"}),
                  "force": ("force", first["force"], runs_of.attrs["force"]),
                  "force_normalized": ("force", first["force_normalized"], runs_of.attrs["force_normalized"])}
        ds = xr.Dataset({v: (dims, runs_of.data[v], runs_of.attrs[v]) for v in variables if v not in coords},
                        coords=coords)
        _add_interval(ds, ens, study.fit)
        if study.conductance:   # k in N/m over E* in Pa: k/E* in m
            ds = ds.assign(conductance_variables(ds["stiffness"] / (study.e_star * to_pascals(study.units.e_star)),
                                                 metres_per_unit=1.0, settings=study.conductance))
        ds.attrs = {"surface_kind": layout.kind, "half_space": runs_of.run_attrs["half_space"]}
        groups[layout.kind] = ds
    for ds in groups.values():   # the commits of every run of the surface
        ds.attrs["run_git_commits"] = provenance.canonical_json(sorted(commits))
    extra = {}
    if surface_file is not None:
        _, _, attrs = read_surface(surface_file)
        extra = {k: v for k, v in attrs.items() if k.startswith(("scan_", "file", "tile", "length", "name"))}
    entry = study.topography_entry(name) if source == "topography" else study.spectrum_entry(name)
    recorded = {"file": os.path.basename(entry.file)} | extra
    if "file_sha256" not in recorded:  # the surface file records the scan's hash when there is one
        recorded["file_sha256"] = sha256(entry.file)
    attrs = provenance.provenance_attrs(
        config=study.config, title=f"roughcontact measured study: {source} {name}", source=source, **recorded,
        e_star=study.e_star, e_star_units=study.units.e_star, units_length=study.units.length)
    write_groups(output, groups, attrs)


#: per-load variables of a measured run file beside those of every run
_NORMALIZED = ("force_normalized", "stiffness_normalized", "contact_area_fraction")


def _layouts(study: StudySettings, ens: str, order: list, run_files) -> list:
    """The :class:`~roughcontact.study.analysis.merge.KindLayout` of each kind of the runs of one measured
    surface (*order*: :func:`run_order`, one path of *run_files* each): spheres over ``radius``
    and *ens* (``tile`` or ``seed``), flat ones over *ens*."""
    from .merge import KindLayout

    out = []
    for kind in ("sphere", "flat"):
        radii = [float(r) for r in study.radius if kind_of(r) == kind]
        rows = [({"radius": r, ens: i}, path) for (r, i), path in zip(order, run_files) if kind_of(r) == kind]
        if not radii or not rows:
            continue
        axes = ("radius",) if kind == "sphere" else ()
        out.append(KindLayout(kind=kind, rows=rows, axes=axes, ensemble=ens,
                              coords={**({"radius": radii} if axes else {}), ens: sorted({row[ens] for row, _ in rows})},
                              at={id(row): {"radius": row["radius"]} for row, _ in rows}))
    return out


def _add_interval(ds, ens: str, fit: ZetaFitSettings) -> None:
    k = ds["stiffness"]
    ds["k_mean"] = k.mean(ens).assign_attrs(long_name=f"mean stiffness over the {ens}s", units="N m-1")
    count = ds.sizes[ens]
    values = np.moveaxis(k.values, k.dims.index(ens), -1)
    low = np.full(values.shape[:-1], np.nan)
    high = np.full(values.shape[:-1], np.nan)
    if count > 1:
        idx = statistics.bootstrap_indices(count, fit.bootstrap)
        means = values[..., idx].mean(axis=-1)          # (..., resamples)
        for pos in np.ndindex(values.shape[:-1]):
            low[pos], high[pos] = statistics.interval(means[pos], fit.confidence)
    dims = [d for d in k.dims if d != ens]
    level = f"{100 * fit.confidence:g} %"
    ds["k_ci_low"] = (dims, low, {"long_name": f"{level} bootstrap interval of k_mean over the {ens}s, low",
                                  "units": "N m-1"})
    ds["k_ci_high"] = (dims, high, {"long_name": f"{level} bootstrap interval of k_mean over the {ens}s, high",
                                    "units": "N m-1"})
