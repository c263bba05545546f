"""Eq. 16 of Pohrt & Popov (2013) with three choices of ζ: eq. 13, the study's fit, the ζ(H) law."""
from __future__ import annotations

import math

from .. import paper
from ..zeta_law import zeta_law
from .registry import SELF_AFFINE, Model, Range, Surface, register

REFERENCE = "R. Pohrt, V. L. Popov, Adv. Tribol. 2013, 974178, doi:10.1155/2013/974178"
#: the optional axes eq. 16 models: the body exponent m (eq. 7's κ and eq. 16's profile); it is
#: written for the pure self-affine spectrum and an elastic half-space, so roll-off, cutoff and
#: hardness are not read (ζ, fitted or from a law, is the paper setting's)
AXES = ("exponent",)
#: eq. 13's stated range (ζ ≈ 1.7/(H+1) for H ≤ 1)
PAPER_RANGE = (Range("hurst", 0.0, 1.0, "eq. 13: H <= 1"),)
#: the ζ(H) law's calibration: presets/zeta-law.yaml, H 0.1-1.9
LAW_RANGE = (Range("hurst", 0.1, 1.9, "zeta(H) law calibrated on H 0.1-1.9"),)


def _eq16(force, s: Surface, zeta: float):
    if not math.isfinite(zeta):
        return None
    return paper.stiffness_from_force(force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length,
                                      e_star=s.e_star, zeta=zeta, exponent=s.exponent)


def eq16_paper(force, s: Surface):
    """Eq. 16 with ζ = 1.7/(H+1) (eq. 13)."""
    return _eq16(force, s, float(paper.zeta_estimate(s.hurst)))


def eq16_fitted(force, s: Surface):
    """Eq. 16 with the ζ(H) fitted on the same study (eq. 11; flat runs, else the sphere's branch)."""
    return _eq16(force, s, s.zeta_fit)


def eq16_law(force, s: Surface):
    """Eq. 16 with ζ from the ζ(H) law calibrated on the flat surfaces of ``presets/zeta-law.yaml``
    (:func:`roughcontact.models.zeta_law.zeta_law`, claim c')."""
    return _eq16(force, s, float(zeta_law(s.hurst)))


register(Model("eq16_paper", "eq16_paper: eq. 16 with zeta = 1.7/(H+1)", eq16_paper, REFERENCE, axes=AXES,
               ranges=PAPER_RANGE))
register(Model("eq16_fitted", "eq16_fitted: with the zeta fitted on this study", eq16_fitted, REFERENCE, axes=AXES,
               ranges=SELF_AFFINE))
register(Model("eq16_law", "eq16_law: with the zeta(H) law calibrated on presets/zeta-law.yaml", eq16_law,
               "roughcontact.models.zeta_law (claim c')", axes=AXES, ranges=LAW_RANGE))
