"""The analytic model of Pohrt & Popov (2013), eqs. 7–18.

Every function is vectorized over its first argument and returns the quantity
it is named after. ``h`` is the rms height of the whole rough surface, ``L``
the system size, ``E*`` the effective modulus, ``R`` the sphere radius
(``inf`` for a nominally flat surface); units are the caller's, forces in
``E*·L²``-consistent units.

References
----------
R. Pohrt, V. L. Popov, Adv. Tribol. 2013, 974178 (2013).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import gamma

__all__ = [
    "kappa",
    "zeta_estimate",
    "hertz_stiffness",
    "fractal_stiffness",
    "profile_prefactor",
    "profile_stiffness",
    "force_from_stiffness",
    "stiffness_from_force",
    "crossover_force",
    "crossover_slope",
]


def kappa(hurst):
    """κ(H) = H ∫₀¹ ξ^(H−1)/√(1−ξ²) dξ = (√π/2) H Γ(H/2)/Γ(H/2 + 1/2) (eq. 8)."""
    hurst = np.asarray(hurst, dtype=float)
    return np.sqrt(np.pi) / 2.0 * hurst * gamma(hurst / 2.0) / gamma(hurst / 2.0 + 0.5)


def zeta_estimate(hurst):
    """ζ(H) ≈ 1.7/(H + 1), the literature estimate of the prefactor of eq. 11 (eq. 13)."""
    return 1.7 / (np.asarray(hurst, dtype=float) + 1.0)


def hertz_stiffness(force, radius, e_star):
    """Hertzian stiffness k = E* (6 R F/E*)^(1/3) (eq. 9)."""
    force = np.asarray(force, dtype=float)
    return e_star * np.cbrt(6.0 * radius * force / e_star)


def fractal_stiffness(force, hurst, h_rms, length, e_star, zeta):
    """Stiffness of a nominally flat self-affine surface (eq. 11).

    k/(E* L) = ζ(H) (F/(E* h L))^(1/(H+1)).
    """
    force = np.asarray(force, dtype=float)
    return e_star * length * zeta * (force / (e_star * h_rms * length)) ** (1.0 / (hurst + 1.0))


def profile_prefactor(hurst, h_rms, length, zeta):
    """Q3D of the axisymmetric profile z_s = Q3D |r|^H equivalent to the roughness (eq. 14).

    Q3D = (2/(ζ L))^(H+1) (H+1) L h / (2 H κ(H)); unit length^(1−H).
    """
    return ((2.0 / (zeta * length)) ** (hurst + 1.0) * (hurst + 1.0) * length * h_rms
            / (2.0 * hurst * kappa(hurst)))


def profile_stiffness(force, q3d, hurst, e_star):
    """Stiffness of a rigid axisymmetric indenter z = Q3D |r|^H (eq. 7).

    k = 2 E* ((H+1) F / (2 Q3D E* H κ(H)))^(1/(H+1)).
    """
    force = np.asarray(force, dtype=float)
    return 2.0 * e_star * ((hurst + 1.0) * force
                           / (2.0 * q3d * e_star * hurst * kappa(hurst))) ** (1.0 / (hurst + 1.0))


def force_from_stiffness(stiffness, radius, hurst, h_rms, length, e_star, zeta):
    """Force of the rough sphere at a given stiffness, superposing eqs. 10 and 12 (eq. 16).

    F = E* [ (k/E*)³/(6R) + L h (k/(ζ E* L))^(H+1) ]; ``radius = inf`` drops the Hertz term.
    """
    k = np.asarray(stiffness, dtype=float)
    hertz = 0.0 if math.isinf(radius) else (k / e_star) ** 3 / (6.0 * radius)
    return e_star * (hertz + length * h_rms * (k / (zeta * e_star * length)) ** (hurst + 1.0))


def stiffness_from_force(force, radius, hurst, h_rms, length, e_star, zeta):
    """Invert eq. 16 for k at given force(s) (bisection in log k to machine precision).

    The root lies between min(k_9, k_11) at F/2 and at F, where k_9 and k_11 are
    the two asymptotes (eqs. 9 and 11), because eq. 16 is a sum of two
    increasing terms.
    """
    force = np.asarray(force, dtype=float)
    if math.isinf(radius):
        return fractal_stiffness(force, hurst, h_rms, length, e_star, zeta)

    def asymptote_min(f):
        return np.minimum(hertz_stiffness(f, radius, e_star),
                          fractal_stiffness(f, hurst, h_rms, length, e_star, zeta))

    lo = np.log(asymptote_min(force / 2.0))
    hi = np.log(asymptote_min(force))
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        too_stiff = force_from_stiffness(np.exp(mid), radius, hurst, h_rms, length,
                                         e_star, zeta) > force
        hi = np.where(too_stiff, mid, hi)
        lo = np.where(too_stiff, lo, mid)
    return np.exp(0.5 * (lo + hi))


def crossover_force(radius, hurst, h_rms, length, e_star, zeta):
    """Force where the asymptotes of eq. 16 intersect (eq. 17).

    F_tr/E* = [ζ^(3H+3) h^(−3) L^(3H) (6R)^(−H−1)]^(1/(H−2)).
    """
    base = zeta ** (3.0 * hurst + 3.0) * h_rms ** -3.0 * length ** (3.0 * hurst) \
        * (6.0 * radius) ** (-hurst - 1.0)
    return e_star * base ** (1.0 / (hurst - 2.0))


def crossover_slope(hurst):
    """Local slope d ln k/d ln F of eq. 16 where its two terms are equal: 2/(H+4).

    With F = a k³ + b k^(H+1) and a k³ = b k^(H+1): d ln F/d ln k = (3 + H + 1)/2.
    The terms are equal at the stiffness where the asymptotes (eqs. 9, 11)
    intersect, i.e. on the eq. 16 curve at F = 2 F_tr (F_tr of eq. 17): a force
    read off a measured curve where its slope crosses 2/(H+4) is 2 F_tr.
    """
    return 2.0 / (np.asarray(hurst, dtype=float) + 4.0)
