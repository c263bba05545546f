"""The sweep axes of a study: one :class:`Axis` per swept quantity, registered here once.

Everything that iterates over the axes reads :data:`AXES`: the configuration's schema (each
axis's entry, :func:`schema_properties`) and its normalisation, run names
(:mod:`roughcontact.study.runs`), job settings (:mod:`roughcontact.study.settings`), the
surface and solver arguments of the indent job, the merged files' coordinates, the
command line's flags and the claims' columns. Adding an axis is one :func:`register` call
in this module (its schema, tag, unit, paper value and where it acts) plus its test; see the
package guide (``docs/guide/package.md``) for a worked example.

Units: lengths in the unit of ``grid.length``, pressures in units of ``E*``. A run's axis
value is what the configuration lists (``None``: the paper's setting, for an optional axis);
its *coordinate* in the merged files is a number with the same meaning
(:meth:`Axis.coordinate`: a roll-off of ``None`` is the system size ``L``, a cutoff 0, a
hardness ``inf``).
"""
from __future__ import annotations

import dataclasses
import math
import re
from typing import Callable

from ..errors import ConfigError
from .units import ENERGY_PER_AREA_UNITS, to_joules_per_square_metre, to_metres, to_pascals

__all__ = ["Axis", "AXES", "register", "axis", "names", "optional_axes", "schema_properties", "ROLES", "kind_of",
           "paper_coordinates", "off_paper", "paper_setting", "paper_mask"]

#: where an axis acts on a run: the roughness of the surface (an argument of
#: :func:`roughcontact.surfaces.self_affine` and :func:`~roughcontact.surfaces.rough_sphere`),
#: the body it is superposed on (an argument of ``rough_sphere`` only), the contact solver
#: (an argument of :func:`roughcontact.bem.iter_load_path`), or the interaction of the surfaces
#: (adhesion: off its paper value the run is an adhesive one, :mod:`roughcontact.study.adhesive`)
ROLES = ("roughness", "body", "solver", "interaction")


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
    if axis_.name in AXES:
        raise ValueError(f"axis {axis_.name!r} is registered already")
    if axis_.role not in ROLES:
        raise ValueError(f"axis {axis_.name!r}: role {axis_.role!r} is none of {ROLES}")
    AXES[axis_.name] = axis_
    return axis_


def axis(name: str) -> Axis:
    """The registered axis *name*."""
    return AXES[name]


def names(kind: str | None = None) -> tuple[str, ...]:
    """The axes' names in order; those a *kind* of surface sweeps if given."""
    return tuple(a.name for a in AXES.values() if kind is None or kind in a.kinds)


def optional_axes() -> tuple[Axis, ...]:
    """The axes with a paper setting (off it, a run's name has their tag)."""
    return tuple(a for a in AXES.values() if a.optional)


def schema_properties() -> dict:
    """``{name: schema entry}`` of every axis, for :func:`roughcontact.study.schema.load_schema`."""
    return {a.name: a.schema() for a in AXES.values()}


def paper_coordinates(length: float) -> dict:
    """``{name: coordinate}`` of the paper's setting of every optional axis, as merged-file
    coordinates (:meth:`Axis.coordinate`; a roll-off of ``None`` is ``length``)."""
    return {a.name: a.coordinate(a.paper, length) for a in optional_axes()}


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
    columns) are at the paper's setting of every optional axis it has a column of."""
    import numpy as np

    keep = np.ones(len(frame), dtype=bool)
    for name, paper in paper_coordinates(length).items():
        if name in frame:
            keep &= frame[name].to_numpy(float) == paper
    return keep


def _number(**bounds) -> dict:
    return {"type": "number", **bounds}


def _nullable(**bounds) -> dict:
    return {"oneOf": [{"type": "null"}, {"type": "number", **bounds}]}


# --------------------------------------------------------------------------
# the axes of Pohrt & Popov (2013): H, R, h_rms
# --------------------------------------------------------------------------
register(Axis(
    "hurst", "H", "Hurst exponent H", "1",
    "Hurst exponents H of the generated surfaces (required, non-empty, unless topography or spectrum is given; "
    "then may be empty or missing)",
    _number(exclusiveMinimum=0, exclusiveMaximum=2), "roughness", optional=False, may_be_empty=True,
    flag_help="Hurst exponent H, 0 < H < 2"))
register(Axis(
    "radius", "R", "sphere radius R", "length", "sphere radii R (.inf = nominally flat, periodic)",
    _number(exclusiveMinimum=0, **{"x-allow-inf": True}), "body", kinds=("sphere",), optional=False,
    flag_help="sphere radius R; inf = nominally flat"))


# --------------------------------------------------------------------------
# beyond the paraboloid (the paper's Conclusions)
# --------------------------------------------------------------------------
def _check_exponent(cfg: dict, kinds: set) -> None:
    if "sphere" not in kinds:
        return
    for i, exponent in enumerate(cfg["exponent"]):
        if exponent in cfg["hurst"]:
            raise ConfigError(
                f"config key 'exponent[{i}]' = {exponent:g} equals a Hurst exponent: the body and the roughness "
                "then have parallel asymptotes and eqs. 16-17 no crossover; allowed: exponents other than every H",
                key=f"exponent[{i}]")


register(Axis(
    "exponent", "m", "exponent m of the body of revolution z = (R/m)(r/R)^m (2: paraboloid)", "1",
    "exponents m of the bodies of revolution z = (R/m)(r/R)^m pressed by the spheres (2 = the paper's "
    "paraboloid, 1 = a cone of slope 1); not used by flat surfaces",
    _number(exclusiveMinimum=0, maximum=8), "body", kinds=("sphere",), paper=2.0,
    flag_help="body of revolution z = (R/m)(r/R)^m of the sphere (default 2: the paraboloid)", check=_check_exponent))
register(Axis(
    "h_rms", "h", "rms roughness height", "length",
    "rms roughness heights h of the generated surfaces (required, non-empty, unless topography or spectrum is "
    "given; then may be empty or missing)",
    _number(exclusiveMinimum=0), "roughness", optional=False, may_be_empty=True,
    flag_help="rms roughness height"))


# --------------------------------------------------------------------------
# the spectrum: roll-off and cutoff
# --------------------------------------------------------------------------
def _check_spectrum(cfg: dict, kinds: set) -> None:
    from .limits import full_contact_slope

    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
    if None in cfg["rolloff"] and length in cfg["rolloff"]:
        raise ConfigError(f"config key 'rolloff' lists both null and grid.length = {length:g}, the same spectrum (a "
                          "roll-off at L is none); allowed: one of them", key="rolloff")
    rolloffs = [length if r is None else r for r in cfg["rolloff"]]
    cutoffs = [0.0 if c is None else c for c in cfg["cutoff"]]
    for i, rolloff in enumerate(cfg["rolloff"]):
        if rolloff is not None and rolloff > length:
            raise ConfigError(f"config key 'rolloff[{i}]' = {rolloff:g} is not allowed; allowed: null or a wavelength "
                              f"<= grid.length = {length:g} (the longest wavelength of the surface)",
                              key=f"rolloff[{i}]")
    for i, cutoff in enumerate(cfg["cutoff"]):
        if cutoff is not None and cutoff < 2 * length / n:
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: null or a wavelength "
                              f">= 2 cells = 2 grid.length/grid.n = {2 * length / n:.3g}", key=f"cutoff[{i}]")
        if cutoff is not None and cutoff >= min(rolloffs):
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: a wavelength below every "
                              f"roll-off ({min(rolloffs):g}), else no self-affine band is left", key=f"cutoff[{i}]")
    if max(cutoffs) > 0 and "flat" in kinds and cfg["forces"].get("flat"):
        slope = min(full_contact_slope(h, n, length, rolloff=r, cutoff=c or None)
                    for h in cfg["hurst"] for r in rolloffs for c in cutoffs) * min(cfg["h_rms"])
        if cfg["forces"]["flat"]["to"] >= 0.5 * slope:
            raise ConfigError(
                f"config key 'forces.flat.to' = {cfg['forces']['flat']['to']:g} would press the flat surfaces with "
                f"a cutoff close to full contact (rms slope ~ {slope:.3g}); allowed: to < {0.5 * slope:.3g}",
                key="forces.flat.to")


register(Axis(
    "rolloff", "rolloff", "roll-off wavelength of the spectrum (grid.length: none)", "length",
    "roll-off wavelengths of the roughness spectrum (length unit; C(q) is constant for q < 2 pi/rolloff); "
    "null = grid.length (no roll-off)",
    _nullable(exclusiveMinimum=0), "roughness", paper_coordinate=float,
    flag_help="roll-off wavelength of the spectrum (default: L)", claim="j"))
register(Axis(
    "cutoff", "cutoff", "short-wavelength cutoff of the spectrum (0: none)", "length",
    "short-wavelength cutoffs of the roughness spectrum (length unit; C(q) = 0 for q > 2 pi/cutoff); "
    "null = none (every grid mode)",
    _nullable(exclusiveMinimum=0), "roughness", paper_coordinate=lambda length: 0.0,
    flag_help="short-wavelength cutoff (default: none)", claim="i", check=_check_spectrum))


# --------------------------------------------------------------------------
# plasticity: a penetration hardness
# --------------------------------------------------------------------------
def _check_hardness(cfg: dict, kinds: set) -> None:
    for i, hardness in enumerate(cfg["hardness"]):
        if hardness is None:
            continue
        if cfg["solver"]["stiffness"] == "difference":
            raise ConfigError(f"config key 'solver.stiffness' = 'difference' is not allowed with 'hardness[{i}]' = "
                              f"{hardness:g}; allowed: punch (the unloading stiffness of a plastic contact)",
                              key="solver.stiffness")
        for kind in sorted(kinds):
            to = cfg["forces"][kind]["to"]
            # fully plastic: F = hardness * area; a sphere's contact must stay within L/4 of its apex
            limit = hardness if kind == "flat" else math.pi * hardness / 16
            if to >= limit:
                raise ConfigError(
                    f"config key 'hardness[{i}]' = {hardness:g} (units of E*) is too soft for forces.{kind}.to = "
                    f"{to:g}: a fully plastic contact would cover {'the whole grid' if kind == 'flat' else 'more than L/4'}"
                    f"; allowed: hardness > {to / (limit / hardness):.3g} or a smaller forces.{kind}.to",
                    key=f"hardness[{i}]")


register(Axis(
    "hardness", "hardness", "penetration hardness (inf: elastic)", "e_star",
    "penetration hardness of the half-space in units of E* (pressure is capped there, cells flow plastically); "
    "null = elastic",
    _nullable(exclusiveMinimum=0), "solver", paper_coordinate=lambda length: math.inf,
    flag_help="penetration hardness in units of E* (default: elastic)", claim="k",
    to_solver=lambda value, e_star: value * e_star, check=_check_hardness))


# --------------------------------------------------------------------------
# adhesion: a work of adhesion (Pohrt & Popov's detachment criterion)
# --------------------------------------------------------------------------
def _check_adhesion(cfg: dict, kinds: set) -> None:
    adhesive = [w for w in cfg["work_of_adhesion"] if w > 0]
    if not adhesive:
        return
    plastic = [h for h in cfg["hardness"] if h is not None]
    if plastic:
        raise ConfigError(f"config key 'work_of_adhesion' = {adhesive[0]:g} is not allowed with 'hardness' = "
                          f"{plastic[0]:g}; allowed: adhesion or a hardness (adhesive contact is elastic only)",
                          key="work_of_adhesion")
    if cfg["solver"]["stiffness"] == "difference":
        raise ConfigError("config key 'solver.stiffness' = 'difference' is not allowed with 'work_of_adhesion' > 0; "
                          "allowed: punch (the stiffness of the adhesive contact set)", key="solver.stiffness")


_WITH_UNIT = re.compile(r"^\s*(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)\s*(\S+)\s*$")


def _work_in_units(value, units: dict, key: str) -> float:
    """A work of adhesion of the configuration in units of ``e_star * length``: a number as it is
    (without the study's units, or 0), a string ``"<number> <unit>"`` converted with ``units``."""
    given = units.get("length") is not None and units.get("e_star") is not None
    allowed = ", ".join(ENERGY_PER_AREA_UNITS)
    if isinstance(value, str):
        match = _WITH_UNIT.match(value)
        if match is None or match.group(2) not in ENERGY_PER_AREA_UNITS:
            raise ConfigError(f"config key '{key}' = {value!r} is not allowed; allowed: a number >= 0 (units of "
                              f"e_star * length) or a number >= 0 with one of the units {allowed}, e.g. '50 mJ/m^2'",
                              key=key)
        if not given:
            raise ConfigError(f"config key '{key}' = {value!r} has a unit, but the study has none; allowed: a number "
                              "in units of e_star * length, or give units.length and units.e_star", key=key)
        joules = float(match.group(1)) * to_joules_per_square_metre(match.group(2))
        return joules / (to_pascals(units["e_star"]) * to_metres(units["length"]))
    if given and value != 0:
        raise ConfigError(f"config key '{key}' = {value!r} has no unit, but the study's numbers are in units "
                          f"(units.length = {units['length']}, units.e_star = {units['e_star']}); allowed: the value "
                          f"with its unit, one of {allowed}, e.g. '50 mJ/m^2' (0 needs none)", key=key)
    return value


register(Axis(
    "work_of_adhesion", "w", "work of adhesion", "e_star * length",
    "works of adhesion w of the surfaces (energy per area): numbers in units of e_star * length, or with "
    f"their unit ({', '.join(ENERGY_PER_AREA_UNITS)}, e.g. '50 mJ/m^2') where units.length and units.e_star are "
    "given; 0 = no adhesion (the elastic runs); w > 0: an adhesive run with Pohrt & Popov's detachment "
    "criterion, loaded to the forces and retracted to pull-off (roughcontact.study.adhesion)",
    {"oneOf": [_number(minimum=0), {"type": "string", "minLength": 1}]}, "interaction", paper=0.0,
    flag_help="work of adhesion in units of E* L (default 0: no adhesion)", claim="o", check=_check_adhesion,
    in_units=_work_in_units))
