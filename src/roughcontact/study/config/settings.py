"""The study-wide settings: a resolved configuration as one frozen, typed record.

:func:`roughcontact.study.config.resolve.resolve_config` validates a raw configuration and fills its
defaults (the schema, ``config.schema.yaml``, is the one home of every default); it returns a
plain mapping because that is what Snakemake's ``config`` and the run files' provenance hold.
:meth:`StudySettings.of` turns that mapping into a :class:`StudySettings` once, and everything
after resolution reads typed attributes (``study.grid.n``, ``study.forces["sphere"].count``,
``study.fit.zeta.min_cells``), never string keys. :func:`roughcontact.study.config.resolve.study_settings`
does both steps.

The sweep axes of :data:`roughcontact.study.config.axes.AXES` are attributes too
(``study.hurst``, ``study.rolloff``: the sorted tuple of the sweep's values, ``None`` first for
an optional axis at the paper's setting), read from the registry, so a registered axis needs
no field here. :class:`roughcontact.study.runs.jobs.JobSettings` is the record of one run.

Units: lengths in the unit of ``grid.length`` (``units.length`` where measured inputs give
one), ``e_star`` in ``units.e_star``; forces normalised, ``F/(E* L²)``.
"""
from __future__ import annotations

import dataclasses
import types
from typing import Mapping

import numpy as np

from . import axes
from .records import force_grid

__all__ = [
    "force_grid",
    "ForceRange",
    "GridSettings",
    "SolverSettings",
    "HistogramsSettings",
    "FieldsSettings",
    "TangentialSettings",
    "ConductanceSettings",
    "ZetaFitSettings",
    "SlopeFitSettings",
    "FitSettings",
    "UnitSettings",
    "JobsSettings",
    "TopographyInput",
    "SpectrumInput",
    "StudySettings",
]


@dataclasses.dataclass(frozen=True)
class ForceRange:
    """A log-spaced load path ``F/(E* L²)`` (``forces.sphere``, ``forces.flat``)."""

    start: float   #: smallest load (config ``from``)
    stop: float    #: largest load (config ``to``)
    count: int     #: number of loads

    def normalized(self) -> np.ndarray:
        """The loads ``F/(E* L²)``, log-spaced from :attr:`start` to :attr:`stop`."""
        return force_grid(self.start, self.stop, self.count)


@dataclasses.dataclass(frozen=True)
class GridSettings:
    """The ``n × n`` grid of side ``length`` (``grid``)."""

    n: int                          #: grid points per side
    length: float                   #: side ``L`` of the periodic cell (length unit)
    realization_of: int | None = None   #: finer grid whose surfaces are pressed (``None``: own)
    coarse: int | None = None       #: coarser grid of the grid error (``None``: none)
    fine: int | None = None         #: finer grid of the small loads' reference (``None``: none)
    fine_to: float | None = None    #: ``F/(E* L²)``: the largest load pressed on ``fine``

    @property
    def spacing(self) -> float:
        """Cell side ``Δx = L/n``."""
        return self.length / self.n


@dataclasses.dataclass(frozen=True)
class SolverSettings:
    """The contact solver (``solver``; :func:`roughcontact.bem.solve`)."""

    tol: float               #: relative tolerance of every contact solve
    stiffness: str           #: ``punch`` (exact ``dF/dd``) or ``difference``
    rel_step: float          #: relative step of the ``difference`` stiffness
    maxiter: int | None = None   #: iteration limit per load (``None``: the solver's default)


@dataclasses.dataclass(frozen=True)
class HistogramsSettings:
    """The pressure and gap histograms each generated run keeps at chosen loads (``fields.histograms``;
    :mod:`roughcontact.study.quantities.histograms`)."""

    at: tuple = ()   #: ``F/(E* L²)``: the loads nearest these keep them (empty: none)
    bins: int = 50   #: equal bins of each histogram, from 0 to the largest value of the load


@dataclasses.dataclass(frozen=True)
class FieldsSettings:
    """What each generated run keeps beyond its per-load numbers (``fields``)."""

    patches: bool = False   #: per load, the number of contact patches and the largest one's cells
    at: tuple = ()          #: ``F/(E* L²)``: the loads nearest these keep their contact fields
    quantities: tuple = ()  #: the opt-in per-load quantities every run keeps (:mod:`roughcontact.study.quantities`)
    histograms: HistogramsSettings = HistogramsSettings()   #: pressure and gap histograms at chosen loads


@dataclasses.dataclass(frozen=True)
class TangentialSettings:
    """The partial-slip path of the runs with ``friction > 0`` (``tangential``)."""

    at: tuple | None = None   #: ``F/(E* L²)``: the loads nearest these follow it (``None``: every load)
    steps: int = 20           #: tangential loads ``Q/(μP) = 1/(steps+1) … steps/(steps+1)``


@dataclasses.dataclass(frozen=True)
class ConductanceSettings:
    """The bodies' resistivities and conductivities of the contact conductance (``conductance``)."""

    resistivity: tuple | None = None    #: ``(ρ₁, ρ₂)`` in Ω·m (``None``: no electrical conductance)
    conductivity: tuple | None = None   #: ``(K₁, K₂)`` in W/(m·K) (``None``: no thermal conductance)

    def __bool__(self) -> bool:
        return self.resistivity is not None or self.conductivity is not None


@dataclasses.dataclass(frozen=True)
class ZetaFitSettings:
    """The ``ζ(H)`` fit of eq. 11 (``fit.zeta``)."""

    min_cells: int                  #: fewest contact cells a load needs to enter any fit
    max_area_fraction: float        #: largest ``A/L²`` of a flat load in the fit
    sphere_max_force_ratio: float   #: sphere loads below this multiple of eq. 17's crossover
    bootstrap: int                  #: bootstrap resamples over seeds
    confidence: float               #: level of the interval (0.95)


@dataclasses.dataclass(frozen=True)
class SlopeFitSettings:
    """The low- and high-force slopes of the sphere curves (``fit.slopes``)."""

    low_max_ratio: float    #: the low-force slope over ``F/F_tr`` at most this
    high_min_ratio: float   #: the high-force slope over ``F/F_tr`` at least this
    window: int             #: odd number of loads of the local slope ``d ln k/d ln F``


@dataclasses.dataclass(frozen=True)
class FitSettings:
    """The fit windows of the analysis (``fit``)."""

    zeta: ZetaFitSettings
    slopes: SlopeFitSettings
    spectrum_band: tuple[float, float] | None = None   #: ``fit.spectrum.band`` (longest, shortest)


@dataclasses.dataclass(frozen=True)
class UnitSettings:
    """Physical units of the configuration's numbers (``units``; ``None``: none)."""

    length: str | None = None   #: unit of ``grid.length``, ``radius``, ``h_rms``
    e_star: str | None = None   #: pressure unit of ``e_star``


@dataclasses.dataclass(frozen=True)
class JobsSettings:
    """How the runs are grouped into Snakemake jobs (``jobs``); no result depends on it."""

    batch: int   #: seeds per ``indent`` job (:func:`roughcontact.study.runs.naming.seed_blocks`); 1: a job per run

    @classmethod
    def of(cls, cfg) -> "JobsSettings":
        """The ``jobs`` section of a resolved configuration; the schema's default where it has none
        (a file's configuration from before the section existed)."""
        section = cfg.get("jobs") or {}
        if "batch" not in section:
            from .schema import default_of, load_schema

            section = {**section, "batch": default_of(load_schema(None), ("jobs", "batch"))}
        return cls(batch=int(section["batch"]))


@dataclasses.dataclass(frozen=True)
class TopographyInput:
    """One measured scan (an entry of ``topography``, resolved: ``file`` absolute, ``name`` set)."""

    file: str
    name: str
    unit: str | None = None
    size: float | None = None
    detrend: str = "height"
    interpolate: bool = False

    @classmethod
    def of(cls, entry) -> "TopographyInput":
        """*entry* typed: a :class:`TopographyInput` as it is, a resolved ``topography`` entry read."""
        return entry if isinstance(entry, cls) else cls(**entry)


@dataclasses.dataclass(frozen=True)
class SpectrumInput:
    """One measured power spectrum (an entry of ``spectrum``, resolved)."""

    file: str
    name: str
    convention: str = "c2d"


@dataclasses.dataclass(frozen=True)
class StudySettings:
    """A resolved configuration, typed.

    Attributes
    ----------
    grid, solver, fit, units :
        :class:`GridSettings`, :class:`SolverSettings`, :class:`FitSettings`, :class:`UnitSettings`.
    e_star : float
        Effective modulus ``E*`` (in ``units.e_star`` where given).
    sweep : tuple of (str, tuple)
        Every registered axis's name and sorted values (empty where measured inputs only);
        each is an attribute as well (``study.hurst``).
    seeds : tuple of int
        The seeds of every generated surface (empty with measured scans only).
    forces : mapping of str to ForceRange
        The load path of each surface kind (``sphere``, ``flat``).
    topography, spectrum : tuple
        The measured inputs, :class:`TopographyInput` and :class:`SpectrumInput`.
    tile : int or None
        Tile side of a measured scan in cells (``None``: the whole square).
    stickiness : roughcontact.study.config.stickiness.StickinessSettings or None
        The stickiness sweep (claim (q); ``None``: the config has no ``stickiness`` section).
    jobs : JobsSettings or None
        How the runs are grouped into jobs (``None``: the schema's default, :meth:`JobsSettings.of`).
    fields : FieldsSettings
        What each generated run keeps beyond its per-load numbers (contact patches, fields).
    tangential : TangentialSettings
        The partial-slip path of the runs with ``friction > 0``.
    conductance : ConductanceSettings
        The bodies' resistivities and conductivities of the contact conductance (false: none).
    config : mapping
        The resolved configuration itself, read-only: provenance and run files record it.
    """

    grid: GridSettings
    e_star: float
    sweep: tuple
    seeds: tuple
    forces: Mapping[str, ForceRange]
    solver: SolverSettings
    fit: FitSettings
    units: UnitSettings
    topography: tuple = ()
    spectrum: tuple = ()
    tile: int | None = None
    stickiness: object = None
    jobs: JobsSettings | None = None
    fields: FieldsSettings = FieldsSettings()
    tangential: TangentialSettings = TangentialSettings()
    conductance: ConductanceSettings = ConductanceSettings()
    config: Mapping = dataclasses.field(default_factory=lambda: types.MappingProxyType({}), repr=False,
                                        compare=False)

    def __reduce__(self):
        """Pickled (Snakemake's params, worker processes) with its mappings as plain dicts."""
        fields = {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}
        return _rebuild, ({**fields, "forces": dict(self.forces), "config": dict(self.config)},)

    def __getattr__(self, name: str):
        """The sweep's values of the registered axis *name* (a tuple)."""
        if name.startswith("_") or name not in axes.AXES:
            raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")
        return dict(self.sweep).get(name, ())

    @classmethod
    def of(cls, cfg) -> "StudySettings":
        """*cfg* typed: a :class:`StudySettings` is returned as it is, a mapping from
        :func:`~roughcontact.study.config.resolve.resolve_config` (defaults filled; also as a file's
        ``config`` attribute records it, :func:`roughcontact.study.files.provenance.canonical_json`) is
        read once."""
        if isinstance(cfg, cls):
            return cfg
        from .stickiness import StickinessSettings

        grid, solver, fit = cfg["grid"], cfg["solver"], cfg["fit"]
        zeta, slopes = fit["zeta"], fit["slopes"]
        band = (fit.get("spectrum") or {}).get("band")
        units = cfg.get("units") or {}
        return cls(
            grid=GridSettings(n=int(grid["n"]), length=float(grid["length"]),
                              realization_of=None if grid.get("realization_of") is None
                              else int(grid["realization_of"]),
                              coarse=None if grid.get("coarse") is None else int(grid["coarse"]),
                              fine=None if grid.get("fine") is None else int(grid["fine"]),
                              fine_to=None if grid.get("fine_to") is None else float(grid["fine_to"])),
            e_star=float(cfg["e_star"]),
            # floats: a configuration read back from JSON has "inf"; an optional axis the mapping lacks
            # (a file's configuration from before the axis was registered) at its paper value
            sweep=tuple((name, tuple(None if v is None else float(v)
                                     for v in cfg.get(name, [spec.paper] if spec.optional else [])))
                        for name, spec in axes.AXES.items()),
            seeds=tuple(int(s) for s in cfg.get("seeds", ())),
            forces=types.MappingProxyType({kind: ForceRange(float(r["from"]), float(r["to"]), int(r["count"]))
                                           for kind, r in cfg["forces"].items()}),
            solver=SolverSettings(tol=float(solver["tol"]), stiffness=str(solver["stiffness"]),
                                  rel_step=float(solver["rel_step"]),
                                  maxiter=None if solver.get("maxiter") is None else int(solver["maxiter"])),
            fit=FitSettings(
                zeta=ZetaFitSettings(min_cells=int(zeta["min_cells"]),
                                     max_area_fraction=float(zeta["max_area_fraction"]),
                                     sphere_max_force_ratio=float(zeta["sphere_max_force_ratio"]),
                                     bootstrap=int(zeta["bootstrap"]), confidence=float(zeta["confidence"])),
                slopes=SlopeFitSettings(low_max_ratio=float(slopes["low_max_ratio"]),
                                        high_min_ratio=float(slopes["high_min_ratio"]),
                                        window=int(slopes["window"])),
                spectrum_band=None if band is None else (float(band[0]), float(band[1]))),
            units=UnitSettings(length=units.get("length"), e_star=units.get("e_star")),
            topography=tuple(TopographyInput(**entry) for entry in cfg.get("topography") or ()),
            spectrum=tuple(SpectrumInput(**entry) for entry in cfg.get("spectrum") or ()),
            tile=None if cfg.get("tile") is None else int(cfg["tile"]),
            stickiness=StickinessSettings.of(cfg),
            jobs=JobsSettings.of(cfg),
            fields=_fields(cfg.get("fields") or {}),
            tangential=_tangential(cfg.get("tangential") or {}),
            conductance=ConductanceSettings(**{key: None if value is None else tuple(float(v) for v in value)
                                               for key, value in (cfg.get("conductance") or {}).items()}),
            config=types.MappingProxyType(dict(cfg)),
        )

    @property
    def generated(self) -> bool:
        """Whether the study generates surfaces (``hurst`` and ``h_rms`` given)."""
        return bool(self.hurst)

    @property
    def measured(self) -> bool:
        """Whether the study presses a measured scan or surfaces of a measured spectrum."""
        return bool(self.topography) or bool(self.spectrum)

    def force_scale(self) -> float:
        """``E* L²``: the force of a normalised load of 1 (force units)."""
        return self.e_star * self.grid.length ** 2

    def coarse_study(self) -> "StudySettings":
        """The companion study of the grid error (``grid.coarse``): the same sphere runs and
        surfaces on the coarse grid (``grid.realization_of`` = this study's surfaces' grid);
        ``ValueError`` without ``grid.coarse`` or without a sphere
        (:func:`~roughcontact.study.config.companions.coarse_config`)."""
        from .companions import coarse_config

        return StudySettings.of(coarse_config(self.config))

    def topography_entry(self, name: str) -> TopographyInput:
        """The scan called *name*; ``KeyError`` naming the scans if there is none."""
        for entry in self.topography:
            if entry.name == name:
                return entry
        raise KeyError(f"no scan named {name!r}; the config lists {[e.name for e in self.topography]}")

    def spectrum_entry(self, name: str) -> SpectrumInput:
        """The spectrum called *name*; ``KeyError`` naming the spectra if there is none."""
        for entry in self.spectrum:
            if entry.name == name:
                return entry
        raise KeyError(f"no spectrum named {name!r}; the config lists {[e.name for e in self.spectrum]}")


def _fields(section: dict) -> FieldsSettings:
    histograms = section.get("histograms") or {}
    return FieldsSettings(patches=bool(section.get("patches", False)),
                          at=tuple(sorted(float(f) for f in section.get("at", ()))),
                          quantities=tuple(section.get("quantities", ())),
                          histograms=HistogramsSettings(at=tuple(sorted(float(f) for f in histograms.get("at", ()))),
                                                        bins=int(histograms.get("bins", 50))))


def _tangential(section: dict) -> TangentialSettings:
    at = section.get("at")
    return TangentialSettings(at=None if at is None else tuple(sorted(float(f) for f in at)),
                              steps=int(section.get("steps", 20)))


def _rebuild(fields: dict) -> StudySettings:
    """:class:`StudySettings` from its pickled fields (:meth:`StudySettings.__reduce__`)."""
    return StudySettings(**{**fields, "forces": types.MappingProxyType(fields["forces"]),
                            "config": types.MappingProxyType(fields["config"])})
