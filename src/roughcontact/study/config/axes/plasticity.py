"""The plasticity axis: a penetration hardness of the half-space (the paper's Conclusions: is
elasticity on all scales crucial?)."""
from __future__ import annotations

import math

from ....errors import ConfigError
from . import Axis, nullable, register

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
    nullable(exclusiveMinimum=0), "solver", paper_coordinate=lambda length: math.inf,
    flag_help="penetration hardness in units of E* (default: elastic)", claim="k",
    to_solver=lambda value, e_star: value * e_star, check=_check_hardness))
