"""The adhesion axis: a work of adhesion (Pohrt & Popov's detachment criterion), written as a number
in the study's units or with a physical unit."""
from __future__ import annotations

import re

from ....errors import ConfigError
from ..units import ENERGY_PER_AREA_UNITS, to_joules_per_square_metre, to_metres, to_pascals
from . import Axis, number, register

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
    "criterion, loaded to the forces and retracted to pull-off (roughcontact.study.runs.adhesive)",
    {"oneOf": [number(minimum=0), {"type": "string", "minLength": 1}]}, "interaction", paper=0.0,
    flag_help="work of adhesion in units of E* L (default 0: no adhesion)", claim="o", check=_check_adhesion,
    in_units=_work_in_units))
