"""Merge the run files of a study into one file per study, and their ensemble statistics.

Imports xarray and pandas (the ``pipeline`` extra); ``import roughcontact``
does not import this module. Reading and writing files is :mod:`roughcontact.study.files.io`.

All forces in the tables are normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import dataclasses

import numpy as np

from ...errors import MergeError
from .. import quantities
from ..files import provenance, runfile
from ..config.axes import coordinate_attrs
from ..config.units import study_units, to_metres
from .conductance import conductance_variables
from ..runs import naming as runs
from ..files.io import check_run, declaration, open_run, read_run, rerun_hint, stale
from ..runs.jobs import JobSettings, options_of, shared_settings, slides, slip_path
from ..config.settings import StudySettings

__all__ = ["KindLayout", "Gathered", "gather", "kind_layouts", "layout_of", "force_coords", "merge_runs", "place",
           "read_declared", "with_units"]


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
    coordinates (:func:`place`): the shared part of the merges of the adhesive runs' pull-off, the
    tangential, stickiness and measured runs.

    *value*: ``value(ds, name)`` the values of *name* in the run *ds* (default ``ds[name].values``).
    Raises :class:`~roughcontact.errors.MergeError` (from :func:`~roughcontact.study.files.io.read_run`)
    naming a missing, foreign or stale run file."""
    return place(layout, [read_run(path, expected_of(row)) for row, path in layout.rows], variables, value)


def place(layout: KindLayout, datasets: list, variables: dict, value=None) -> Gathered:
    """Place the *variables* (``{name: NetCDF dtype}``) of the runs *datasets* (read, one per row of
    *layout*, in its order) at their coordinates (:meth:`KindLayout.index`); *value* as for
    :func:`gather`."""
    data, attrs, commits, first = {}, {}, set(), None
    for (row, _), ds in zip(layout.rows, datasets):
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


def read_declared(path, row: dict, shared: dict, slip: dict | None = None):
    """Read the run file *path* of the run *row* (a dict of :func:`runs.runs`) and check it against
    its own declaration, then the declaration against the study: the merge's reader.

    The file's ``config`` attribute is the job record it was computed from
    (:func:`roughcontact.study.files.io.declaration`, checked against its ``config_hash``); typed
    (:meth:`~roughcontact.study.runs.jobs.JobSettings.from_record`), it says what the file holds
    (its quantities, the retract path of an adhesive run, the partial-slip path of a sliding
    one: :func:`roughcontact.study.files.io.check_run`). Its surface and seed must be those of
    its name (*row*), and its other settings the study's for its surface kind, *shared*
    (:func:`~roughcontact.study.runs.jobs.shared_settings`, computed once per kind), and its
    partial-slip path the run's, *slip* (:func:`~roughcontact.study.runs.jobs.slip_path`; ``None``:
    a run that does not slide).

    Returns ``(ds, kept)``: the run, loaded, and the names of the per-load quantities it keeps.
    Raises :class:`~roughcontact.errors.MergeError` naming *path*, what is wrong and what to do."""
    ds = open_run(path)
    try:
        job = JobSettings.from_record(declaration(path, ds))
    except (KeyError, TypeError, ValueError) as exc:
        raise MergeError(f"{path}: foreign NetCDF file (its 'config' attribute is no job record of an indent run: "
                         f"{type(exc).__name__}: {exc}); {rerun_hint(path)}") from exc
    for name in runfile.SCALARS:   # the run its name says
        got, want = getattr(job, name), row[name]
        if not float(got) == float(want):
            raise MergeError(f"{path}: holds {name} = {float(got):g}, expected {float(want):g} from its name; "
                             f"{rerun_hint(path)}")
    check_run(path, ds, job.file_spec())
    expected = {**shared, "options": options_of(row), **(slip or {"slip_loads": (), "slip_steps": 0})}
    stale(path, {key: getattr(job, key) for key in expected}, expected)
    return ds, quantities.recorded(job)


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
        shared = shared_settings(study, kind)
        declared = [read_declared(path, row, shared, slip_path(study, kind, slides(row)))
                    for row, path in layout.rows]
        # the quantities any run of the kind declares (a hardness on some runs: their plastic ones too)
        names = tuple(name for name in quantities.names() if any(name in kept for _, kept in declared))
        # fields.histograms: every run of the kind keeps them at the same loads
        histograms = {n: v for n, v in runfile.HISTOGRAM_VARIABLES.items() if n != "histogram_force"}
        loads = list(shared["histogram_loads"])
        runs_of = place(layout, [ds for ds, _ in declared],
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
