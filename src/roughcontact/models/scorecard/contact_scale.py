"""This package's models: eqs. 10 and 12 joined by a p-norm, with the roughness seen at the
contact's scale (:mod:`roughcontact.models.superposition`); ``contact_scale`` with two constants,
``contact_scale_h`` with both linear in H, ``contact_scale_tail`` with a tail towards the body's
law of its own."""
from __future__ import annotations

from .. import superposition
from .registry import Model, Range, Surface, register


def _spectra(s: Surface) -> dict:
    """The grid's spectrum and the pure self-affine one, for a spectrum with a roll-off or cutoff."""
    if s.pure_self_affine:
        return {}
    return dict(spectrum=s.grid_spectrum(), reference=s.grid_spectrum(band=False))


def contact_scale(force, s: Surface):
    """:func:`roughcontact.models.superposition.calibrated_stiffness`: ζ = c_ζ · ζ_law(H) and the
    p-norm's p calibrated on the presets named in :data:`~roughcontact.models.superposition.CALIBRATED`;
    for a spectrum with a roll-off or a cutoff the roughness seen at the contact's scale (the
    grid's spectrum against the pure self-affine one)."""
    return superposition.calibrated_stiffness(
        force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length, e_star=s.e_star,
        exponent=s.exponent, **_spectra(s))


def contact_scale_h(force, s: Surface):
    """:func:`roughcontact.models.superposition.hurst_calibrated_stiffness`: as :func:`contact_scale`,
    with c_ζ and p linear in H, calibrated on the presets named in
    :data:`~roughcontact.models.superposition.CALIBRATED_HURST`."""
    return superposition.hurst_calibrated_stiffness(
        force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length, e_star=s.e_star,
        exponent=s.exponent, **_spectra(s))


def contact_scale_tail(force, s: Surface):
    """:func:`roughcontact.models.superposition.tail_calibrated_stiffness`: as :func:`contact_scale_h`,
    joined by ``F = F_body (1 + β x^s + x^p)^(1/p)``, whose approach to the body's law
    (``1 − k/k_body ∝ F^(−m/(m+1))``) no longer follows from the crossover's order; constants in
    :data:`~roughcontact.models.superposition.CALIBRATED_TAIL`."""
    return superposition.tail_calibrated_stiffness(
        force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length, e_star=s.e_star,
        exponent=s.exponent, **_spectra(s))


register(Model(
    "contact_scale",
    "contact_scale: this package's model, eqs. 10 and 12 joined by a p-norm with the roughness seen at the "
    "contact's scale, constants calibrated on named presets", contact_scale, "roughcontact.models.superposition",
    # reads the exponent, and the roll-off and cutoff through the grid's spectrum; elastic only
    axes=("exponent", "rolloff", "cutoff"),
    # the constants' calibration set (superposition.CALIBRATED): H 0.4, 0.7, 1.0
    ranges=(Range("hurst", 0.4, 1.0, "calibrated on H 0.4-1.0"),), precomputable=True))

_LOW, _HIGH = superposition.CALIBRATED_HURST["hurst"]
register(Model(
    "contact_scale_h",
    "contact_scale_h: as contact_scale, with the zeta factor and the p-norm's order linear in H, calibrated on "
    "presets/calibration-branches.yaml, calibration-branches-451.yaml and calibration-branches-447.yaml",
    contact_scale_h, "roughcontact.models.superposition",
    axes=("exponent", "rolloff", "cutoff"),
    ranges=(Range("hurst", _LOW, _HIGH, f"calibrated on H {_LOW:g}-{_HIGH:g}"),), precomputable=True))

_LOW, _HIGH = superposition.CALIBRATED_TAIL["hurst"]
register(Model(
    "contact_scale_tail",
    "contact_scale_tail: as contact_scale_h, with a tail towards Hertz of its own (an interfacial compliance, "
    "1 - k/k_Hertz ~ F^(-2/3)), calibrated on presets/calibration-branches.yaml, calibration-branches-451.yaml "
    "and calibration-branches-447.yaml", contact_scale_tail, "roughcontact.models.superposition",
    axes=("exponent", "rolloff", "cutoff"),
    ranges=(Range("hurst", _LOW, _HIGH, f"calibrated on H {_LOW:g}-{_HIGH:g}"),), precomputable=True))
