"""The sweep axes of a study: the registry (:class:`Axis`, :func:`register`, :data:`AXES`) and
one module of this package per family of axes, each registering its axes when imported.

Everything that iterates over the axes reads :data:`AXES`: the configuration's schema (each
axis's entry, :func:`schema_properties`) and its normalisation, run names
(:mod:`roughcontact.study.runs.naming`), job settings (:mod:`roughcontact.study.runs.jobs`), the
surface and solver arguments of the indent job (:attr:`Axis.role`, :attr:`Axis.keyword`,
:attr:`Axis.transform`), the merged files' coordinates, the command line's flags, the claims'
columns and the one test of the paper's setting (:func:`paper_setting`). Adding an axis is one
new module in this package that calls :func:`register` (every module here is imported with the
package: :data:`_ORDER` first, then the others by name); the worked example is
``docs/guide/extending/axis_example.py``. An axis at its paper value is passed to nothing, so
adding one leaves every earlier run's name, settings and hash unchanged.

Units: lengths in the unit of ``grid.length``, pressures in units of ``E*``. A run's axis
value is what the configuration lists (``None``: the paper's setting, for an optional axis);
its *coordinate* in the merged files is a number with the same meaning
(:meth:`Axis.coordinate`: a roll-off of ``None`` is the system size ``L``, a cutoff 0, a
hardness ``inf``).
"""
from __future__ import annotations

import dataclasses
import math
from typing import Callable

from ...._registry import add, import_modules

__all__ = ["Axis", "AXES", "register", "axis", "names", "optional_axes", "schema_properties", "ROLES", "kind_of",
           "coordinate_attrs",
           "paper_coordinates", "off_paper", "paper_setting", "paper_mask", "number", "nullable"]

#: where an axis acts on a run: the roughness of the surface (a keyword of
#: :func:`roughcontact.surfaces.self_affine` and :func:`~roughcontact.surfaces.rough_sphere`, or a
#: :attr:`Axis.transform` of the roughness heights before the body is added), the body it is
#: superposed on (a keyword of ``rough_sphere`` only), the contact solver (a keyword of
#: :func:`roughcontact.bem.iter_load_path`), or the interaction of the surfaces (passed nowhere:
#: adhesion, off its paper value the run is an adhesive one, :mod:`roughcontact.study.runs.adhesive`),
#: or the tangential problem solved at each load of the normal path (passed to it:
#: :class:`roughcontact.study.runs.indent.PathSettings`, :mod:`roughcontact.study.runs.tangential`)
ROLES = ("roughness", "body", "solver", "interaction", "tangential")


def kind_of(radius) -> str:
    """The surface kind of a radius: ``"sphere"`` for a finite radius (free half-space),
    ``"flat"`` for ``inf`` (a nominally flat surface on the periodic half-space)."""
    return "sphere" if math.isfinite(radius) else "flat"


@dataclasses.dataclass(frozen=True)
class Axis:
    """One sweep axis.

    Attributes
    ----------
    name : str
        Configuration key (a list of values), merged-file dimension, settings key and the
        keyword of the surface or solver function it is passed to.
    tag : str
        Its tag in a run's name (``H`` in ``H0.7_R0.5_h0.009``, ``m`` in ``..._m4``).
    long_name, unit : str
        Attributes of the merged files' coordinate (CF ``units`` in the study's units).
    description : str
        The configuration reference's sentence (the schema's ``description``).
    item_schema : dict
        JSON schema of one value of the list (``null`` allowed where ``optional``).
    role : str
        One of :data:`ROLES`.
    kinds : tuple of str
        The surface kinds (``sphere``, ``flat``) whose runs sweep it; the others take the
        paper's value.
    optional : bool
        Whether the axis has a paper setting (``paper``) and may be left out of a config; a
        run at the paper's setting has no tag in its name and no key in its settings' record,
        so adding an optional axis leaves every earlier run's name and hash unchanged.
    paper : float or None
        The paper's setting (optional axes only): the config's default is ``[paper]``.
    paper_coordinate : callable
        ``L -> coordinate`` of a ``None`` value (optional axes whose paper setting is ``None``).
    may_be_empty : bool
        Whether the config's list may be empty (the generated surfaces' axes, with measured
        inputs only).
    flag_help : str
        Help of its ``roughcontact indent`` flag ``--<name with dashes>``.
    claim : str
        The claim that tests the axis off the paper's setting (claims (a)-(f) say
        ``untested`` there and name it), or ``""``.
    to_solver : callable
        ``(value, e_star) -> argument`` of the solver (``role == "solver"``).
    keyword : str
        The keyword the axis feeds to the function of its role (default: :attr:`name`); an
        axis at its paper value is not passed at all.
    normal : bool
        Whether the axis changes the normal contact problem (the load path ``F(d)``, ``k``).
        ``False`` (``poisson``, ``friction``: the tangential problem, its coupling to the normal
        one neglected): runs that differ only in such axes have the same normal path, so the
        normal merged files (``stiffness.nc``) and every table of the normal problem hold the
        runs at the first of its values, without it as a dimension or a column (a study that
        leaves it out has every output it had before); only the files of its own path kind
        (``tangential/tangential.nc``) have it as a dimension. Not part of :func:`paper_coordinates`.
    transform : callable or None
        ``transform(heights, value, run) -> heights``: how a ``roughness`` axis acts when no
        generator takes it as a keyword: applied to the roughness heights (mean 0, rms
        ``run.h_rms``) before the body is added, *run* being the job's
        :class:`~roughcontact.study.runs.jobs.JobSettings`; such an axis is passed as no keyword.
    check : callable or None
        ``check(cfg, kinds)``: the cross-key checks a JSON schema cannot express; raises
        :class:`~roughcontact.errors.ConfigError`.
    in_units : callable or None
        ``in_units(value, units, key) -> float``: a value of the configuration's list in the
        configuration's own units, where the axis may be written with a unit (a string such as
        ``"50 mJ/m^2"``, against ``units``); raises :class:`~roughcontact.errors.ConfigError`
        naming *key*.
    """

    name: str
    tag: str
    long_name: str
    unit: str
    description: str
    item_schema: dict
    role: str
    kinds: tuple = ("sphere", "flat")
    optional: bool = True
    paper: float | None = None
    paper_coordinate: Callable[[float], float] | None = None
    may_be_empty: bool = False
    flag_help: str = ""
    claim: str = ""
    to_solver: Callable | None = None
    check: Callable | None = None
    in_units: Callable | None = None
    keyword: str = ""
    transform: Callable | None = None
    normal: bool = True

    def __post_init__(self):
        if not self.keyword:
            object.__setattr__(self, "keyword", self.name)
        if self.transform is not None and self.role != "roughness":
            raise ValueError(f"axis {self.name!r}: a transform acts on the roughness heights (role 'roughness'), "
                             f"not {self.role!r}")

    def at_paper(self, value) -> bool:
        """Whether *value* (a run's value, configuration units) is the paper's setting."""
        return self.optional and value == self.paper

    @property
    def flag(self) -> str:
        """The ``roughcontact indent`` flag of the axis."""
        return "--" + self.name.replace("_", "-")

    def coordinate(self, value, length: float) -> float:
        """The value of a run as a coordinate of the merged files (module docstring)."""
        if value is None:
            return float(self.paper_coordinate(length))
        return float(value)

    def value_of(self, coordinate: float, length: float):
        """The inverse of :meth:`coordinate`: ``None`` at the paper's setting of a nullable axis."""
        if self.optional and self.paper is None and coordinate == self.coordinate(None, length):
            return None
        return float(coordinate)

    def normalise(self, values) -> list:
        """The config's list sorted, as floats, ``None`` (the paper's setting) first."""
        return sorted((None if v is None else float(v) for v in values), key=lambda v: (v is not None, v))

    def schema(self) -> dict:
        """The axis's entry in the configuration schema."""
        entry = {"description": self.description, "type": "array", "minItems": 0 if self.may_be_empty else 1,
                 "uniqueItems": True, "items": self.item_schema}
        if self.optional:
            entry["default"] = [self.paper]
        return entry


#: every axis, in the order of the merged files' dimensions (then ``seed`` and ``force``)
AXES: dict[str, Axis] = {}


def register(axis_: Axis) -> Axis:
    """Add *axis_* to :data:`AXES` (after the ones registered before it)."""
    if axis_.role not in ROLES:
        raise ValueError(f"axis {axis_.name!r}: role {axis_.role!r} is none of {ROLES}")
    return add(AXES, axis_.name, axis_, "axis")


def axis(name: str) -> Axis:
    """The registered axis *name*."""
    return AXES[name]


def names(kind: str | None = None, *, normal: bool | None = None) -> tuple[str, ...]:
    """The axes' names in order; those a *kind* of surface sweeps if given; with *normal*, only
    those whose :attr:`Axis.normal` is it (``True``: the dimensions of the normal merged files)."""
    return tuple(a.name for a in AXES.values() if (kind is None or kind in a.kinds)
                 and (normal is None or a.normal == normal))


def optional_axes(*, normal: bool | None = None) -> tuple[Axis, ...]:
    """The axes with a paper setting (off it, a run's name has their tag); with *normal*, only
    those whose :attr:`Axis.normal` is it."""
    return tuple(a for a in AXES.values() if a.optional and (normal is None or a.normal == normal))


def schema_properties() -> dict:
    """``{name: schema entry}`` of every axis, for :func:`roughcontact.study.config.schema.load_schema`."""
    return {a.name: a.schema() for a in AXES.values()}


def coordinate_attrs(name: str) -> dict:
    """The NetCDF attributes (``long_name``, ``units``) of the coordinate *name* of a merged file:
    a registered axis, or ``seed``; ``KeyError`` for any other."""
    if name == "seed":
        return {"long_name": "random seed of the surface", "units": "1"}
    spec = axis(name)
    return {"long_name": spec.long_name, "units": spec.unit}


def paper_coordinates(length: float) -> dict:
    """``{name: coordinate}`` of the paper's setting of every optional axis, as merged-file
    coordinates (:meth:`Axis.coordinate`; a roll-off of ``None`` is ``length``); the axes of the
    normal problem only (:attr:`Axis.normal`: the tangential axes leave the normal one as the
    paper has it)."""
    return {a.name: a.coordinate(a.paper, length) for a in optional_axes(normal=True)}


def off_paper(combination, length: float) -> dict:
    """``{name: coordinate}`` of the optional axes at which *combination* (a mapping of axis name to
    merged-file coordinate, e.g. a row of a table) is off the paper's setting; an axis the mapping
    lacks (a table made before the axis existed) counts as at the paper's setting."""
    out = {}
    for name, paper in paper_coordinates(length).items():
        value = combination.get(name, paper) if hasattr(combination, "get") else paper
        if value is None or (isinstance(value, float) and math.isnan(value)):
            continue
        if float(value) != paper:
            out[name] = float(value)
    return out


def paper_setting(combination, length: float) -> bool:
    """Whether *combination* (axis name -> merged-file coordinate) is at the paper's setting of every
    optional axis: the one test the scorecard, every claim, the ζ fit and the exponents use."""
    return not off_paper(combination, length)


def paper_mask(frame, length: float):
    """A boolean array: which rows of the table *frame* (a pandas DataFrame with the axes as
    columns) are at the paper's setting of every optional axis, by the rule of :func:`off_paper`
    (a missing column or an empty cell, e.g. a flat row's body exponent, counts as the paper's)."""
    import numpy as np

    keep = np.ones(len(frame), dtype=bool)
    for name, paper in paper_coordinates(length).items():
        if name in frame:
            values = frame[name].to_numpy(float)
            keep &= (values == paper) | np.isnan(values)
    return keep


def number(**bounds) -> dict:
    """JSON schema of one number with *bounds* (``minimum``, ``exclusiveMaximum``, ...)."""
    return {"type": "number", **bounds}


def nullable(**bounds) -> dict:
    """JSON schema of ``null`` (the paper's setting) or one number with *bounds*."""
    return {"oneOf": [{"type": "null"}, {"type": "number", **bounds}]}


#: the modules of the registry's own axes, in the order of the merged files' dimensions; further
#: modules of this package follow by name (their axes after these)
_ORDER = ("rough_body", "spectrum", "plasticity", "adhesion", "tangential")


def _load() -> None:
    """Import every module of this package once (each registers its axes)."""
    import_modules(__name__, __path__, _ORDER)


_load()


