"""Eq. 16 generalised: the forces of the body and of the roughness joined by a power mean.

Pohrt & Popov add, at a given stiffness k = 2 E* a, the forces of the two equivalent
axisymmetric profiles (eq. 16): ``F = F_body(k) + F_rough(k)``, with
``F_body = E* (k/E*)^(m+1)/c_m`` (eq. 10; ``c_2 = 6R``) and
``F_rough = E* L h (k/(ζ E* L))^(H+1)`` (eq. 12). The sum is exact only for one profile that
is the sum of the two, ``z = r²/2R + Q3D r^H`` (eq. 15), and eq. 15 itself is a model: the
rough surface is not axisymmetric and its equivalent profile's prefactor ζ is fitted on flat
surfaces. This module joins the two forces by the power mean

    F = (F_body(k)^p + F_rough(k)^p)^(1/p),        p ≥ 1,

which keeps both asymptotes (eqs. 9 and 11), is eq. 16 for ``p = 1`` and tends to
``max(F_body, F_rough)`` (``k = min(k_9, k_11)``) as ``p → ∞``. At the crossover stiffness
(``F_body = F_rough``) the force is ``2^(1/p)`` times either term instead of twice it: a
``p > 1`` makes the transition sharper. ``p`` and a factor on ζ are calibrated on the BEM
ensembles of the presets (:mod:`roughcontact.models.calibrated`); the derivation and the
calibration are in the documentation (guide, "Models").

Units are the caller's, consistent as in :mod:`roughcontact.models.paper`.
"""
from __future__ import annotations

import math

import numpy as np

from .paper import _body_coefficient, body_stiffness, fractal_stiffness

__all__ = ["force_from_stiffness", "stiffness_from_force"]


def force_from_stiffness(stiffness, *, radius, hurst, h_rms, length, e_star, zeta, power, exponent=2.0):
    """Force at stiffness k: the power mean of order ``power`` of eqs. 10 and 12 (module docstring).

    Parameters
    ----------
    stiffness : array_like
        k (force/length), > 0.
    radius : float
        R (length); ``inf`` leaves the roughness term alone (eq. 11).
    hurst, h_rms, length, e_star, zeta : float
        H, h (length), L (length), E* (force/length²) and ζ of eq. 12.
    power : float
        p ≥ 1; 1 is eq. 16.
    exponent : float
        m of the body of revolution z = (R/m)(r/R)^m; 2 is the paraboloid.

    Returns
    -------
    numpy.ndarray
        F (force).
    """
    if not power >= 1.0:
        raise ValueError(f"power must be >= 1, got {power!r}")
    k = np.asarray(stiffness, dtype=float)
    rough = length * h_rms * (k / (zeta * e_star * length)) ** (hurst + 1.0)
    if math.isinf(radius):
        return e_star * rough
    body = (k / e_star) ** (exponent + 1.0) / _body_coefficient(radius, exponent)
    top = np.maximum(body, rough)
    # the power mean scaled by its larger term (no overflow for large p)
    return e_star * top * ((body / top) ** power + (rough / top) ** power) ** (1.0 / power)


def stiffness_from_force(force, *, radius, hurst, h_rms, length, e_star, zeta, power, exponent=2.0):
    """Invert :func:`force_from_stiffness` for k at given force(s) (bisection in log k).

    The root lies between ``min(k_9, k_11)`` at ``F/2`` and at ``F`` (the power mean lies between
    the larger term and twice it), as for :func:`roughcontact.models.paper.stiffness_from_force`;
    100 halvings of that bracket reach machine precision.
    """
    force = np.asarray(force, dtype=float)
    if math.isinf(radius):
        return fractal_stiffness(force, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta)

    def asymptote_min(f):
        return np.minimum(body_stiffness(f, radius=radius, e_star=e_star, exponent=exponent),
                          fractal_stiffness(f, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta))

    lo, hi = np.log(asymptote_min(force / 2.0)), np.log(asymptote_min(force))
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        too_stiff = force_from_stiffness(np.exp(mid), radius=radius, hurst=hurst, h_rms=h_rms, length=length,
                                         e_star=e_star, zeta=zeta, power=power, exponent=exponent) > force
        hi = np.where(too_stiff, mid, hi)
        lo = np.where(too_stiff, lo, mid)
    return np.exp(0.5 * (lo + hi))
