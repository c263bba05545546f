"""The run file's data model: every variable of a run and of the merged files, once.

Names, NetCDF types, long names and units of what one indentation run writes
(:mod:`roughcontact.study.indent`) and what the merge reads back and stacks
(:mod:`roughcontact.study.merge`). Units are CF-style strings in the study's own units:
lengths in the unit of ``grid.length``, forces in ``e_star * length**2``.
"""
from __future__ import annotations

import dataclasses

from .axes import AXES

__all__ = ["Variable", "VARIABLES", "RUN_VARIABLES", "PLASTIC_VARIABLES", "SCALARS", "AXIS_ATTRS",
           "FORCE_ATTRS", "TITLE"]

#: the ``title`` attribute that marks a run file
TITLE = "roughcontact indentation run"


@dataclasses.dataclass(frozen=True)
class Variable:
    """One per-load variable of a run file (dimension ``force``)."""

    dtype: str
    long_name: str
    units: str


#: every per-load variable a run file can hold
VARIABLES = {
    "depth": Variable("f8", "indentation depth from first touch", "length"),
    "stiffness": Variable("f8", "normal contact stiffness dF/dd", "e_star * length"),
    "contact_area": Variable("f8", "contact area (contact cells * (L/n)^2)", "length**2"),
    "contact_cells": Variable("i8", "number of grid cells in contact", "1"),
    "iterations": Variable("i8", "solver iterations (warm-started from the previous load)", "1"),
    "converged": Variable("i1", "solver converged (1) or not (0)", "1"),
    "loading_stiffness": Variable("f8", "loading tangent dF/dd along the plastic path (forward quotient, "
                                        "solver.rel_step); stiffness is the unloading one", "e_star * length"),
    "plastic_cells": Variable("i8", "number of grid cells that flowed (pressure at the hardness)", "1"),
}
#: variables of every run file
RUN_VARIABLES = ("depth", "stiffness", "contact_area", "contact_cells", "iterations", "converged")
#: further variables of a run with a hardness (elastic runs: loading stiffness = stiffness, no plastic cell)
PLASTIC_VARIABLES = ("loading_stiffness", "plastic_cells")

#: the force coordinate
FORCE_ATTRS = {"long_name": "normal force F", "units": "e_star * length**2"}

#: scalar variables of a run file: (NetCDF type, long name, units)
SCALARS = {
    "hurst": ("f8", "Hurst exponent H", "1"),
    "radius": ("f8", "sphere radius R (inf: nominally flat, periodic)", "length"),
    "h_rms": ("f8", "rms roughness height", "length"),
    "seed": ("i8", "random seed of the surface", "1"),
}

#: attributes of the sweep axes (:data:`roughcontact.study.axes.AXES`) and of ``seed`` as
#: coordinates of the merged files
AXIS_ATTRS = {**{a.name: {"long_name": a.long_name, "units": a.unit} for a in AXES.values()},
              "seed": {"long_name": "random seed of the surface", "units": "1"}}
