"""The settings of one indentation job: a frozen, typed record from the configuration to the job.

:func:`job_settings` picks out of a resolved configuration everything one run depends on and
nothing else, so that adding a seed or a sweep value does not invalidate finished runs. The
Snakemake ``indent`` rule and ``roughcontact indent`` both build a :class:`JobSettings` this way;
:mod:`roughcontact.study.runs.indent` runs it.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import quantities
from ..config import axes
from ..files import runfile
from .naming import parse_combo
from ..config.axes import kind_of
from ..config.defaults import solver_maxiter
from ..config.records import ForcePathRecord
from ..config.settings import StudySettings

__all__ = ["SLIP_COMPONENTS", "JobSettings", "job_settings", "nearest_loads", "options_of", "run_settings",
           "settings_from_wildcards", "shared_settings", "slides", "slip_path"]


#: traction components of a run's partial-slip path (:func:`roughcontact.bem.partial_slip`,
#: :mod:`roughcontact.study.runs.tangential`): two, ``(q_x, q_y)`` on the isotropic Coulomb cone (the
#: one-component path's ``q_x`` differs by 6-11 % of ``μ max p`` on a rough sphere,
#: docs/guide/tangential.md); in a friction run's record, so a change reruns it
SLIP_COMPONENTS = 2


@dataclasses.dataclass(frozen=True, kw_only=True)
class JobSettings(ForcePathRecord):
    """Everything one generated run depends on: the job record
    (:class:`~roughcontact.study.config.records.RunRecord`) of the indent job, its coarse
    companion and an adhesive run.

    Lengths are in the unit of ``length``; forces are given normalised, ``F/(E* L²)``. The grid
    (``n``, ``length``), ``e_star``, the load path and the solver settings are the fields of
    :class:`~roughcontact.study.config.records.ForcePathRecord`; this kind adds its surface.

    Attributes
    ----------
    hurst, radius, h_rms, seed :
        The run: Hurst exponent, body radius (``inf``: a nominally flat surface on the
        periodic half-space), rms roughness height, seed of the surface.
    realization_of : int or None
        The finer grid whose surface this run presses, seen on its ``n × n`` grid
        (``grid.realization_of``; :func:`roughcontact.surfaces.self_affine`); ``None``: its own.
    options : tuple of (str, float)
        The optional axes of :data:`roughcontact.study.config.axes.AXES` off the paper's setting, in
        the registry's order, under their configuration names and units (``hardness`` in units
        of ``E*``); each is also an attribute (``settings.rolloff``), the paper's value where
        it is not listed.
    patches : bool
        Whether every load also counts its contact patches (``fields.patches``).
    quantities : tuple of str
        The opt-in per-load quantities the run keeps (``fields.quantities``,
        :mod:`roughcontact.study.quantities`).
    field_loads : tuple of int
        The loads (0-based, of the path) that keep their contact fields (``fields.at``).
    histogram_loads : tuple of int
        The loads (0-based, of the path) that keep their pressure and gap histograms
        (``fields.histograms.at``).
    histogram_bins : int
        Bins of each histogram (``fields.histograms.bins``; 0 without histograms).
    slip_loads : tuple of int
        With ``friction > 0``: the loads (0-based) that follow the partial-slip path
        (``tangential.at``); ``()`` otherwise.
    slip_steps : int
        With ``friction > 0``: tangential loads of each partial-slip path (``tangential.steps``); 0 otherwise.
    """

    hurst: float
    radius: float
    h_rms: float
    seed: int
    options: tuple = ()
    realization_of: int | None = None
    patches: bool = False
    quantities: tuple = ()
    field_loads: tuple = ()
    histogram_loads: tuple = ()
    histogram_bins: int = 0
    slip_loads: tuple = ()
    slip_steps: int = 0

    #: fields added after studies were run with this class: left out of :meth:`__repr__` at their
    #: default, so that the ``indent`` rule's params (Snakemake compares their repr) of a run made
    #: before them stay the same and an upgrade reruns no run
    _LATER_FIELDS = ("histogram_loads", "histogram_bins")

    def __repr__(self) -> str:
        shown = (f for f in dataclasses.fields(self)
                 if f.name not in self._LATER_FIELDS or getattr(self, f.name) != f.default)
        return f"{type(self).__name__}({', '.join(f'{f.name}={getattr(self, f.name)!r}' for f in shown)})"

    def __getattr__(self, name: str):
        """The value of an optional axis (its paper value where :attr:`options` does not list it)."""
        spec = axes.AXES.get(name)
        if spec is None or not spec.optional:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        return dict(self.options).get(name, spec.paper)

    @property
    def kind(self) -> str:
        """``"sphere"`` (finite radius, free half-space) or ``"flat"`` (periodic)."""
        return kind_of(self.radius)

    @property
    def periodic(self) -> bool:
        """Whether the half-space is periodic (the nominally flat surfaces)."""
        return self.kind == "flat"

    def value(self, name: str):
        """The run's value of the axis *name* (configuration units)."""
        return getattr(self, name)

    def arguments(self, role: str) -> dict:
        """Keyword arguments of the axes acting as *role* (:data:`roughcontact.study.config.axes.ROLES`):
        ``roughness`` for the surface generator, ``body`` for the body, ``solver`` for the
        contact solver (converted by :attr:`~roughcontact.study.config.axes.Axis.to_solver`, e.g. the
        hardness to a pressure), each under its :attr:`~roughcontact.study.config.axes.Axis.keyword`.
        An optional axis at its paper value is passed to nothing (the function's default is the
        paper's setting), nor is an axis that acts by a :meth:`transforms` of the heights."""
        out = {}
        for spec in axes.AXES.values():
            if spec.role != role or spec.name == "radius" or self.kind not in spec.kinds or spec.transform:
                continue
            value = self.value(spec.name)
            if spec.at_paper(value):
                continue
            out[spec.keyword] = spec.to_solver(value, self.e_star) if spec.to_solver and value is not None else value
        return out

    def transforms(self) -> list:
        """``[(transform, value)]`` of the roughness axes that act on the heights
        (:attr:`~roughcontact.study.config.axes.Axis.transform`) off their paper value, in the
        registry's order."""
        return [(spec.transform, self.value(spec.name)) for spec in axes.AXES.values()
                if spec.transform is not None and self.kind in spec.kinds
                and not spec.at_paper(self.value(spec.name))]

    def forces(self) -> np.ndarray:
        """The load path in force units, ``F = (F/(E* L²)) E* L²``."""
        return self.forces_normalized() * self.e_star * self.length**2

    def axes(self) -> dict:
        """The optional axes off the paper's setting, under their configuration names
        (``hardness`` in units of ``E*``)."""
        return dict(self.options)

    def record(self) -> dict:
        """The settings as a flat mapping of plain values: what a run file's ``config_hash``
        and attributes are made of. Optional axes at the paper's setting are left out."""
        out = {field.name: getattr(self, field.name) for field in dataclasses.fields(self)
               if field.name not in ("options", "realization_of", "patches", "quantities", "field_loads",
                                     "histogram_loads", "histogram_bins", "slip_loads", "slip_steps")}
        # each at its default is left out: runs of a grid's own surfaces, and runs that keep nothing
        # more than their per-load numbers, keep their hash
        if self.realization_of is not None:
            out["realization_of"] = self.realization_of
        if self.patches:
            out["patches"] = True
        if self.quantities:
            out["quantities"] = list(self.quantities)
        if self.field_loads:
            out["field_loads"] = list(self.field_loads)
        if self.histogram_loads:
            out["histogram_loads"] = list(self.histogram_loads)
            out["histogram_bins"] = self.histogram_bins
        if self.slip_loads:   # friction > 0: the partial-slip path
            out["slip_loads"] = list(self.slip_loads)
            out["slip_steps"] = self.slip_steps
            out["slip_components"] = SLIP_COMPONENTS
        return {**out, **self.axes(), "kind": self.kind, "periodic": self.periodic}

    def file_spec(self) -> runfile.RunFileSpec:
        """What this run's file must be (:func:`roughcontact.study.files.io.read_run`): the run file's
        variables and ``force`` dimension (an adhesive run's retract path and pull-off too), its
        H, R, h_rms and seed, the ``config_hash`` of :meth:`record` and the force grid."""
        variables = (*quantities.recorded(self), "force", *runfile.SCALARS,
                     *(runfile.TANGENTIAL_VARIABLES if self.poisson is not None else ()),
                     *(runfile.SLIP_VARIABLES if self.slip_loads else ()),
                     *((*runfile.HISTOGRAM_COORDS, *runfile.HISTOGRAM_VARIABLES) if self.histogram_loads else ()))
        dims = ("force", *(runfile.SLIP_COORDS if self.slip_loads else ()),
                *(runfile.HISTOGRAM_DIMS if self.histogram_loads else ()))
        if self.work_of_adhesion > 0:
            variables += (*runfile.RETRACT_VARIABLES, *runfile.PULL_OFF_VARIABLES)
            dims = ("force", "retract")
        return runfile.RunFileSpec(title=runfile.TITLE, variables=variables, dims=dims, config=self.record(),
                                   scalars={name: getattr(self, name) for name in runfile.SCALARS},
                                   force_variable="force", forces=self.forces())

    @classmethod
    def from_record(cls, record) -> "JobSettings":
        """The settings a run file declares: the inverse of :meth:`record` (its ``config``
        attribute, read back from JSON), so that ``JobSettings.from_record(s.record()) == s``.
        ``KeyError``/``TypeError``/``ValueError`` for a mapping that is no job record."""
        values = dict(record)
        values.pop("kind")
        values.pop("periodic")
        values.pop("slip_components", None)
        options = tuple((spec.name, float(values.pop(spec.name))) for spec in axes.optional_axes()
                        if spec.name in values)
        for name in ("quantities", "field_loads", "slip_loads"):
            if name in values:
                values[name] = tuple(values[name])
        for name in ("hurst", "radius", "h_rms", "length", "e_star", "force_from", "force_to", "tol", "rel_step"):
            values[name] = float(values[name])   # "inf": a flat run's radius as JSON records it
        return cls(**values, options=options)

    def describe(self) -> str:
        """One line naming the run, for logs and error messages."""
        r = "inf (flat, periodic)" if not math.isfinite(self.radius) else f"{self.radius:g}"
        extra = "".join(f", {axis} = {value:g}" for axis, value in self.axes().items())
        return f"H = {self.hurst:g}, R = {r}, h_rms = {self.h_rms:g}{extra}, seed = {self.seed}, n = {self.n}"


def options_of(run: dict) -> tuple:
    """:attr:`JobSettings.options` of a run (a dict with the axes' values, missing ones at the
    paper's setting)."""
    out = []
    for spec in axes.optional_axes():
        value = run.get(spec.name, spec.paper)
        if value != spec.paper:
            out.append((spec.name, float(value)))
    return tuple(out)


def job_settings(study, run: dict) -> JobSettings:
    """The :class:`JobSettings` of one run (a dict of :func:`roughcontact.study.runs.naming.runs`)
    of the study (:class:`~roughcontact.study.config.settings.StudySettings` or a resolved configuration)."""
    study = StudySettings.of(study)
    radius = float(run["radius"])
    kind = kind_of(radius)
    return JobSettings(**shared_settings(study, kind), **run_settings(study, kind, run, sliding=slides(run)))


def slides(run: dict) -> bool:
    """Whether the run *run* (a dict of :func:`roughcontact.study.runs.naming.runs`) has a
    partial-slip path: friction > 0."""
    return float(run.get("friction", 0.0) or 0.0) > 0


def shared_settings(study: StudySettings, kind: str) -> dict:
    """The fields of :class:`JobSettings` that every normal run of the surface *kind* (``sphere``,
    ``flat``) of the study has alike: its grid, ``E*``, load path, solver and what it keeps.
    :func:`job_settings` adds those of one run (:func:`run_settings`); the merge checks each run
    file's declaration against them (:func:`roughcontact.study.analysis.merge.read_declared`)."""
    rng = study.forces[kind]
    solver = study.solver
    shared = dict(n=study.grid.n, length=study.grid.length, e_star=study.e_star,
                  force_from=rng.start, force_to=rng.stop, force_count=rng.count,
                  tol=solver.tol, stiffness_method=solver.stiffness, rel_step=solver.rel_step,
                  maxiter=solver_maxiter(solver.maxiter), realization_of=study.grid.realization_of,
                  patches=study.fields.patches, quantities=study.fields.quantities,
                  field_loads=nearest_loads(rng.normalized(), study.fields.at), **_histograms(study, rng))
    # the opt-in quantities the kind's runs keep (one of a run kind only, e.g. a flat run's: that kind's
    # runs alone rerun when it is added), in the registry's order (the list's order changes nothing)
    probe = JobSettings(**shared, **run_settings(study, kind, {"hurst": 0.5, "h_rms": 1.0, "seed": 0,
                                                               "radius": math.inf if kind == "flat" else 1.0}))
    kept = quantities.recorded(probe)
    return {**shared, "quantities": tuple(q for q in quantities.optional() if q in kept)}


def _histograms(study: StudySettings, rng) -> dict:
    """``histogram_loads`` and ``histogram_bins`` of a load path *rng* (``fields.histograms``)."""
    histograms = study.fields.histograms
    loads = nearest_loads(rng.normalized(), histograms.at)
    return dict(histogram_loads=loads, histogram_bins=histograms.bins if loads else 0)


def run_settings(study: StudySettings, kind: str, run: dict, *, sliding: bool = False) -> dict:
    """The fields of :class:`JobSettings` of the one *run* (a dict of
    :func:`roughcontact.study.runs.naming.runs`): its surface, seed, optional axes and, where it
    slides (*sliding*: friction > 0), its partial-slip path."""
    return dict(hurst=float(run["hurst"]), radius=float(run["radius"]), h_rms=float(run["h_rms"]),
                seed=int(run["seed"]), options=options_of(run), **slip_path(study, kind, sliding))


def slip_path(study: StudySettings, kind: str, sliding: bool) -> dict:
    """``slip_loads`` and ``slip_steps`` of a run of the surface *kind* that slides (*sliding*,
    :func:`slides`): the loads of ``tangential.at`` (every load without it) and
    ``tangential.steps``; ``()`` and ``0`` for one that does not. The merge checks a run file's
    against them (:func:`roughcontact.study.analysis.merge.read_declared`)."""
    if not sliding:
        return dict(slip_loads=(), slip_steps=0)
    rng = study.forces[kind]
    loads = tuple(range(rng.count)) if study.tangential.at is None else nearest_loads(rng.normalized(),
                                                                                       study.tangential.at)
    return dict(slip_loads=loads, slip_steps=study.tangential.steps)


def nearest_loads(forces, at) -> tuple:
    """The indices (sorted, once each) of the loads of *forces* nearest, in ``log F``, to each of *at*."""
    if not at:
        return ()
    log_f = np.log(np.asarray(forces, dtype=float))
    return tuple(sorted({int(np.argmin(np.abs(log_f - np.log(f)))) for f in at}))


def settings_from_wildcards(study, wildcards) -> JobSettings:
    """:func:`job_settings` of the run named by the ``indent`` rule's wildcards ``combo`` and ``seed``."""
    return job_settings(study, {**parse_combo(wildcards.combo), "seed": int(wildcards.seed)})
