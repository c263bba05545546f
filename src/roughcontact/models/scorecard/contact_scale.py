"""This package's model: eqs. 10 and 12 joined by a p-norm, with the roughness seen at the
contact's scale (:mod:`roughcontact.models.superposition`)."""
from __future__ import annotations

from .. import superposition
from .registry import Model, Range, Surface, register


def contact_scale(force, s: Surface):
    """:func:`roughcontact.models.superposition.calibrated_stiffness`: ζ = c_ζ · ζ_law(H) and the
    p-norm's p calibrated on the presets named in :data:`~roughcontact.models.superposition.CALIBRATED`;
    for a spectrum with a roll-off or a cutoff the roughness seen at the contact's scale (the
    grid's spectrum against the pure self-affine one)."""
    spectra = {}
    if not s.pure_self_affine:
        spectra = dict(spectrum=s.grid_spectrum(), reference=s.grid_spectrum(band=False))
    return superposition.calibrated_stiffness(
        force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length, e_star=s.e_star,
        exponent=s.exponent, **spectra)


register(Model(
    "contact_scale",
    "contact_scale: this package's model, eqs. 10 and 12 joined by a p-norm with the roughness seen at the "
    "contact's scale, constants calibrated on named presets", contact_scale, "roughcontact.models.superposition",
    # reads the exponent, and the roll-off and cutoff through the grid's spectrum; elastic only
    axes=("exponent", "rolloff", "cutoff"),
    # the constants' calibration set (superposition.CALIBRATED): H 0.4, 0.7, 1.0
    ranges=(Range("hurst", 0.4, 1.0, "calibrated on H 0.4-1.0"),)))
