# module: roughcontact.models.scorecard.smooth_body
"""The smooth body as a model of the rough one: eq. 7 (eq. 9 for the paraboloid), no roughness.

The limit every rough sphere approaches at large loads, scored beside the rough models so that a
reader sees how far below it the roughness keeps the stiffness. It takes the body's exponent into
account (eq. 7 for ``z = (R/m)(r/R)^m``) and declares so; every other optional axis (a roll-off, a
cutoff, a hardness, ...) it does not model, and the scorecard says so on those rows.
"""
from __future__ import annotations

from .. import paper
from .registry import Model, Surface, register


def smooth_body(force, s: Surface):
    """``k(F)`` of the smooth body of revolution (eq. 7; eq. 9, ``k = (6 R E*² F)^(1/3)``, for
    ``m = 2``); no answer for a nominally flat surface (``None``)."""
    if s.flat:
        return None
    return paper.body_stiffness(force, radius=s.radius, e_star=s.e_star, exponent=s.exponent)


register(Model(
    "smooth_body",                                                # its name in models.csv and the figures
    "smooth_body: the smooth body of revolution, eq. 7 (eq. 9 for the paraboloid)",   # the report's sentence
    smooth_body,                                                  # predict(force, surface) -> k or None
    "eq. 7 and eq. 9 of Pohrt & Popov (2013), doi:10.1155/2013/974178",              # where it comes from
    axes=("exponent",),                                           # the optional axes it models
))
