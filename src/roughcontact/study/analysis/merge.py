"""Merge the run files of a study into one file per study, and their ensemble statistics.

Imports xarray and pandas (the ``pipeline`` extra); ``import roughcontact``
does not import this module. Reading and writing files is :mod:`roughcontact.study.files.io`.

All forces in the tables are normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import dataclasses
import logging

import numpy as np

from ...errors import MergeError
from .. import quantities
from ..files import provenance, runfile
from ..config.axes import coordinate_attrs
from ..config.units import study_units, to_metres
from .conductance import conductance_variables
from ..runs import naming as runs
from .ensemble import ensemble
from ..files.io import read_run, write_groups
from ..runs.jobs import job_settings
from ..config.settings import StudySettings

__all__ = ["KindLayout", "Gathered", "gather", "kind_layouts", "layout_of", "force_coords", "merge_runs", "run_merge",
           "with_units"]


log = logging.getLogger(__name__)


# --------------------------------------------------------------------------
# merge and ensemble: one group per surface kind
# --------------------------------------------------------------------------
def force_coords(study: StudySettings, kind: str) -> dict:
    """The ``force`` (force units) and ``force_normalized`` (``F/(E* L²)``) coordinates of a kind's
    load path."""
    scale = study.force_scale()
    force = study.forces[kind].normalized() * scale
    return {
        "force": ("force", force, runfile.FORCE_ATTRS),
        "force_normalized": ("force", force / scale, {"long_name": "F/(E* L^2)", "units": "1"}),
    }


@dataclasses.dataclass(frozen=True)
class KindLayout:
    """Where the runs of one surface kind go in a merged Dataset: ``rows`` (run, path) of the
    kind, its sweep ``axes`` (:data:`runs.AXES`; a stickiness sweep: ``hurst, number``; a
    measured surface: ``radius``), the sorted merged-file ``coords`` of each axis and of the
    ``ensemble`` dimension (``seed``; a measured scan's ``tile``), and each run's coordinates
    (``at``, by ``id`` of its row; :meth:`index`). :func:`gather` reads its runs."""

    kind: str
    rows: list
    axes: tuple
    coords: dict
    at: dict
    ensemble: str = "seed"

    @property
    def shape(self) -> tuple:
        """The sizes of the axes and ``seed``."""
        return tuple(len(v) for v in self.coords.values())

    @property
    def half_space(self) -> str:
        """The ``half_space`` attribute of the kind's group."""
        return "periodic" if self.kind == "flat" else "free (non-periodic)"

    def index(self, row) -> tuple:
        """The position of the run *row* along the axes and the ensemble (``seed``)."""
        return (tuple(self.coords[a].index(self.at[id(row)][a]) for a in self.axes)
                + (self.coords[self.ensemble].index(row[self.ensemble]),))


def kind_layouts(study: StudySettings, table: list, paths) -> list[KindLayout]:
    """The :class:`KindLayout` of each surface kind that the runs *table* (dicts of
    :func:`runs.runs`, one path of *paths* each, in order) have, sphere first: the runs of the
    normal problem (:func:`runs.normal_representative`; the tangential axes' other values repeat
    the same normal path and are merged by :mod:`roughcontact.study.analysis.tangential`)."""
    out = []
    for kind in ("sphere", "flat"):
        rows = [(row, path) for row, path in zip(table, paths)
                if row["kind"] == kind and runs.normal_representative(study, row)]
        if rows:
            out.append(layout_of(study, kind, rows, runs.AXES[kind]))
    return out


def layout_of(study: StudySettings, kind: str, rows: list, axes: tuple) -> KindLayout:
    """The :class:`KindLayout` of *rows* (``(run, path)`` of one surface *kind*) over the sweep
    *axes* (merged-file coordinates of each run, :func:`runs.coordinate`) and the study's seeds."""
    length = study.grid.length
    at = {id(row): {axis: runs.coordinate(axis, row[axis], length) for axis in axes} for row, _ in rows}
    coords = {axis: sorted({at[id(row)][axis] for row, _ in rows}) for axis in axes}
    coords["seed"] = list(study.seeds)
    return KindLayout(kind=kind, rows=rows, axes=tuple(axes), coords=coords, at=at)


@dataclasses.dataclass(frozen=True)
class Gathered:
    """The runs of one :class:`KindLayout`, read and placed (:func:`gather`).

    Attributes
    ----------
    data : dict
        ``{name: numpy.ndarray}`` of shape ``layout.shape + the variable's own shape`` (its
        dimensions in the run file: ``force``, ``retract``, none for a scalar).
    attrs : dict
        ``{name: attributes}`` of each variable as the first run holding it has them (without
        ``coordinates``).
    commits : list of str
        The sorted ``git_commit`` of the runs (``unknown`` where one has none).
    run_attrs : dict
        The global attributes of the layout's first run.
    """

    data: dict
    attrs: dict
    commits: list
    run_attrs: dict


def gather(layout: KindLayout, expected_of, variables: dict, value=None) -> Gathered:
    """Read every run of *layout* with :func:`roughcontact.study.files.io.read_run` against its job record
    ``expected_of(row)`` and place the *variables* (``{name: NetCDF dtype}``) of each at its
    coordinates (:meth:`KindLayout.index`): the shared part of every merge (generated runs, the
    adhesive runs' pull-off, the stickiness runs).

    *value*: ``value(ds, name)`` the values of *name* in the run *ds* (default ``ds[name].values``),
    e.g. a generated elastic run's loading stiffness where it has none. Raises
    :class:`~roughcontact.errors.MergeError` (from :func:`~roughcontact.study.files.io.read_run`) naming a
    missing, foreign or stale run file."""
    data, attrs, commits, first = {}, {}, set(), None
    for row, path in layout.rows:
        ds = read_run(path, expected_of(row))
        first = dict(ds.attrs) if first is None else first
        at = layout.index(row)
        for name, dtype in variables.items():
            values = np.asarray(value(ds, name) if value is not None else ds[name].values)
            if name not in data:
                data[name] = np.zeros(layout.shape + values.shape, dtype=dtype)
            data[name][at] = values
            if name in ds and name not in attrs:
                attrs[name] = {k: v for k, v in ds[name].attrs.items() if k != "coordinates"}
        commits.add(ds.attrs.get("git_commit", "unknown"))
    return Gathered(data=data, attrs=attrs, commits=sorted(commits), run_attrs=first or {})


def _generated_value(ds, name):
    """A generated run's values of *name*: an elastic run's loading tangent is its stiffness,
    and nothing flows."""
    if name in ds:
        return ds[name].values
    return ds["stiffness"].values if name == "loading_stiffness" else np.zeros(ds.sizes["force"])


def merge_runs(study, paths) -> dict:
    """Merge the run files *paths* (one per run of :func:`runs.runs`, in its order) of the
    study (:class:`~roughcontact.study.config.settings.StudySettings` or a resolved
    configuration), one Dataset per surface kind.

    Returns ``{"sphere": ds, "flat": ds}`` (the kinds the sweep has): the sphere
    Dataset has dims (hurst, radius, h_rms, seed, force), the flat one (hurst,
    h_rms, seed, force) (:data:`runs.AXES`); each kind has its own force grid,
    so no variable is padded, and counts are integers.
    """
    import xarray as xr

    study = StudySettings.of(study)
    table = runs.runs(study)
    if len(paths) != len(table):
        raise MergeError(f"merge got {len(paths)} run files for {len(table)} runs of the config")
    groups = {}
    for layout in kind_layouts(study, table, paths):
        kind, axes, coords = layout.kind, layout.axes, layout.coords
        # the quantities any run of the kind keeps (a hardness on some runs: their plastic ones too)
        jobs = [job_settings(study, row) for row, _ in layout.rows]
        kept = [quantities.recorded(job) for job in jobs]
        names = tuple(name for name in quantities.names() if any(name in k for k in kept))
        # fields.histograms: every run of the kind keeps them at the same loads
        histograms = {n: v for n, v in runfile.HISTOGRAM_VARIABLES.items() if n != "histogram_force"}
        loads = list(jobs[0].histogram_loads)
        runs_of = gather(layout, lambda row: job_settings(study, row),
                         {**{n: quantities.QUANTITIES[n].dtype for n in names},
                          **({n: v.dtype for n, v in histograms.items()} if loads else {})},
                         value=_generated_value)
        dims = (*axes, "seed", "force")
        forces = force_coords(study, kind)
        variables = {name: (dims, runs_of.data[name], runs_of.attrs.get(name, {})) for name in names}
        extra = {}
        if loads:
            variables.update({name: ((*axes, "seed", *meta.dims), runs_of.data[name], runs_of.attrs.get(name, {}))
                              for name, meta in histograms.items()})
            dtype, attrs = runfile.HISTOGRAM_COORDS["histogram_load"]
            extra = {"histogram_load": ("histogram_load", np.asarray(loads, dtype=dtype), attrs),
                     "histogram_force": ("histogram_load", forces["force"][1][loads],
                                         {**runfile.FORCE_ATTRS, "long_name": "normal force F of the histograms"}),
                     "histogram_force_normalized": ("histogram_load", forces["force_normalized"][1][loads],
                                                    {"long_name": "F/(E* L^2) of the histograms", "units": "1"})}
        groups[kind] = xr.Dataset(
            variables,
            coords={**{axis: (axis, coords[axis], coordinate_attrs(axis)) for axis in (*axes, "seed")},
                    **forces, **extra},
            attrs={"surface_kind": kind, "half_space": layout.half_space,
                   "run_git_commits": provenance.canonical_json(runs_of.commits)},
        )
        if study.conductance:   # k/E* = (k/(E* L)) L in the length unit
            groups[kind] = groups[kind].assign(conductance_variables(
                groups[kind]["stiffness"] / study.e_star, metres_per_unit=to_metres(study.units.length),
                settings=study.conductance))
    return groups


def with_units(ds, study: StudySettings):
    """*ds* (a merged or ensemble group) with ``units.length`` and ``units.e_star`` in the ``units``
    attribute of every variable and coordinate (:func:`~roughcontact.study.config.units.study_units`),
    where ``units.length`` is set; as it is otherwise."""
    length, pressure = study.units.length, study.units.e_star
    if length is None:
        return ds
    ds = ds.copy()
    for name in (*ds.data_vars, *ds.coords):
        if "units" in ds[name].attrs:
            ds[name].attrs = {**ds[name].attrs, "units": study_units(str(ds[name].attrs["units"]), length, pressure)}
    return ds


# --------------------------------------------------------------------------
# entry points used by workflow/scripts
# --------------------------------------------------------------------------
def run_merge(study, run_files, out_stiffness, out_ensemble):
    """``merge`` rule: run files -> stiffness.nc and ensemble.nc (one group per kind)."""
    study = StudySettings.of(study)
    groups = merge_runs(study, list(run_files))
    attrs = provenance.provenance_attrs(
        config=study.config, title="roughcontact parameter study: all runs",
        layout="one group per surface kind (sphere, flat)", grid_n=study.grid.n, grid_length=study.grid.length,
        e_star=study.e_star, solver_tol=study.solver.tol, stiffness_method=study.solver.stiffness,
        seeds=list(study.seeds))
    write_groups(out_stiffness, {kind: with_units(ds, study) for kind, ds in groups.items()}, attrs)
    attrs["title"] = "roughcontact parameter study: ensemble statistics over seeds"
    write_groups(out_ensemble, {kind: with_units(ensemble(ds), study) for kind, ds in groups.items()}, attrs)
    log.info("merged %d runs (%s) into %s and %s", len(run_files), ", ".join(groups), out_stiffness, out_ensemble)
