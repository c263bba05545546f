"""Physical units of a study: the one home of the unit tables and their conversions.

A configuration's numbers are in its own units (``units.length`` for lengths, ``units.e_star`` for
pressures; none: normalised); these tables turn the names a user writes into SI factors.
"""
from __future__ import annotations

__all__ = ["LENGTH_UNITS", "PRESSURE_UNITS", "FORCE_UNITS", "ENERGY_PER_AREA_UNITS", "plain_unit", "to_metres",
           "to_pascals", "to_newtons", "to_joules_per_square_metre", "study_units"]

#: metres per length unit of ``units.length`` (and of a topography entry's ``unit``)
LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}
#: pascals per pressure unit of ``units.e_star``
PRESSURE_UNITS = {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9}
#: newtons per force unit of the command line's ``--force-unit`` and of progress lines
FORCE_UNITS = {"N": 1.0, "mN": 1e-3, "uN": 1e-6, "nN": 1e-9}
#: J/m² per unit of a work of adhesion (energy per area, or the same as a line tension)
ENERGY_PER_AREA_UNITS = {"J/m^2": 1.0, "J/m2": 1.0, "mJ/m^2": 1e-3, "mJ/m2": 1e-3, "N/m": 1.0, "mN/m": 1e-3}


def plain_unit(unit) -> str | None:
    """A length unit spelt in ASCII: ``µm`` (micro sign or Greek mu) as ``um``; None stays None."""
    return None if unit is None else str(unit).replace("µ", "u").replace("μ", "u")


def to_metres(unit: str) -> float:
    """Metres per ``unit`` (one of :data:`LENGTH_UNITS`)."""
    return LENGTH_UNITS[unit]


def to_pascals(unit: str) -> float:
    """Pascals per ``unit`` (one of :data:`PRESSURE_UNITS`)."""
    return PRESSURE_UNITS[unit]


def to_newtons(unit: str) -> float:
    """Newtons per ``unit`` (one of :data:`FORCE_UNITS`; µN spelt with µ or u)."""
    return FORCE_UNITS[plain_unit(unit)]


def to_joules_per_square_metre(unit: str) -> float:
    """J/m² per ``unit`` (one of :data:`ENERGY_PER_AREA_UNITS`)."""
    return ENERGY_PER_AREA_UNITS[unit]


def study_units(units: str, length: str | None, pressure: str | None = None) -> str:
    """The CF ``units`` string *units* of a run file (in the study's normalised words ``length`` and
    ``e_star``, e.g. ``e_star * length**2``) with the configuration's units put in: ``length`` ->
    ``units.length`` (*length*), ``e_star`` -> ``units.e_star`` (*pressure*) where given, e.g.
    ``e_star * um**2`` or ``MPa * um**2``. The numbers need no conversion: a configuration's
    lengths are in ``units.length`` and its ``e_star`` in ``units.e_star``, and so are the results."""
    import re

    if length is not None:
        units = re.sub(r"\blength\b", length, units)
    if pressure is not None:
        units = re.sub(r"\be_star\b", pressure, units)
    return units
