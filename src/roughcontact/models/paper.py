"""The analytic model of Pohrt & Popov (2013), eqs. 7–18.

Every function is vectorized over its first argument and returns the quantity
it is named after. ``h`` is the rms height of the whole rough surface, ``L``
the system size, ``E*`` the effective modulus, ``R`` the sphere radius
(``inf`` for a nominally flat surface); units are the caller's, forces in
``E*·L²``-consistent units.

``exponent`` (``m``, default 2) generalises the sphere to the smooth body of
revolution ``z = (R/m)(r/R)^m = Q r^m``, ``Q = R^(1−m)/m`` (eq. 6 with ``H``
replaced by ``m``; ``m = 2`` is the paraboloid of Sec. 2, ``m = 1`` a cone of
slope 1), as the paper's Conclusions suggest. With ``m = 2`` every function
returns the same numbers as before ``exponent`` existed.

References
----------
R. Pohrt, V. L. Popov, Adv. Tribol. 2013, 974178 (2013).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._validate import check_finite_positive, check_hurst
from ..surfaces.bodies import body_height, radial_distance

__all__ = [
    "kappa",
    "zeta_estimate",
    "hertz_stiffness",
    "hertz_contact_radius",
    "hertz_approach",
    "body_prefactor",
    "body_stiffness",
    "fractal_stiffness",
    "profile_prefactor",
    "profile_stiffness",
    "Indentation",
    "profile_indentation",
    "body_indentation",
    "force_from_stiffness",
    "stiffness_from_force",
    "crossover_force",
    "crossover_slope",
    "equivalent_height",
    "equivalent_profile",
]


def kappa(hurst):
    """κ(H) = H ∫₀¹ ξ^(H−1)/√(1−ξ²) dξ = (√π/2) H Γ(H/2)/Γ(H/2 + 1/2) (eq. 8)."""
    from scipy.special import gamma   # here: a job that only reads runs does not load scipy.special

    hurst = np.asarray(hurst, dtype=float)
    return np.sqrt(np.pi) / 2.0 * hurst * gamma(hurst / 2.0) / gamma(hurst / 2.0 + 0.5)


def zeta_estimate(hurst):
    """ζ(H) ≈ 1.7/(H + 1), the literature estimate of the prefactor of eq. 11 (eq. 13)."""
    return 1.7 / (np.asarray(hurst, dtype=float) + 1.0)


def hertz_stiffness(force, *, radius, e_star):
    """Hertzian stiffness k = E* (6 R F/E*)^(1/3) (eq. 9); :func:`body_stiffness` with m = 2."""
    return body_stiffness(force, radius=radius, e_star=e_star)


def hertz_contact_radius(force, *, radius, e_star):
    """Hertz's contact radius ``a = (3FR/(4E*))^(1/3)`` of a paraboloid of radius *radius*
    (Johnson 1985, eq. 4.22; eq. 9's ``k = 2E*a``). Same units as *radius*."""
    return np.cbrt(3.0 * np.asarray(force, dtype=float) * radius / (4.0 * e_star))


def hertz_approach(force, *, radius, e_star):
    """Hertz's approach ``d = a²/R`` (Johnson 1985, eq. 4.23), ``a`` of :func:`hertz_contact_radius`."""
    a = hertz_contact_radius(force, radius=radius, e_star=e_star)
    return a * a / radius


def body_prefactor(radius, *, exponent=2.0):
    """Q = R^(1−m)/m of the body of revolution z = Q r^m = (R/m)(r/R)^m (eq. 6 with H → m).

    Unit length^(1−m). m = 2 gives 1/(2R), the Q3D of the paraboloid in eq. 9;
    m = 1 gives 1, a cone of slope 1.
    """
    return np.asarray(radius, dtype=float) ** (1.0 - exponent) / exponent


def _body_coefficient(radius, exponent):
    """c_m = (m+1) 2^m R^(m−1)/κ(m), with F = E* (k/E*)^(m+1)/c_m for the body z = Q r^m.

    From eq. 7 with H → m and Q3D = R^(1−m)/m; c_2 = 6R exactly (κ(2) = 2), as in eq. 10.
    """
    radius = np.asarray(radius, dtype=float)
    return (exponent + 1.0) * 2.0**exponent * radius ** (exponent - 1.0) / kappa(exponent)


def body_stiffness(force, *, radius, e_star, exponent=2.0):
    """Stiffness of a rigid smooth body of revolution z = (R/m)(r/R)^m at force F.

    Eq. 7 with H → m and Q3D = R^(1−m)/m (:func:`body_prefactor`), written as
    k = E* (c_m F/E*)^(1/(m+1)) with c_m = (m+1) 2^m R^(m−1)/κ(m) (κ of eq. 8).
    For m = 2, c_2 = 6R and this is eq. 9, k = E* (6 R F/E*)^(1/3); for m = 1
    (cone of slope 1), c_1 = 8/π and k = E* (8 F/(π E*))^(1/2).

    Parameters
    ----------
    force : array_like
        Normal force F (force unit), ≥ 0.
    radius : float
        R (length unit).
    e_star : float
        Effective modulus E* (force/length²).
    exponent : float
        m > 0, keyword-only; 2 is the paraboloid.

    Returns
    -------
    numpy.ndarray
        k (force/length).
    """
    scaled = _body_coefficient(radius, exponent) * np.asarray(force, dtype=float) / e_star
    root = np.cbrt(scaled) if exponent == 2.0 else scaled ** (1.0 / (exponent + 1.0))
    return e_star * root


def fractal_stiffness(force, *, hurst, h_rms, length, e_star, zeta):
    """Stiffness of a nominally flat self-affine surface (eq. 11).

    k/(E* L) = ζ(H) (F/(E* h L))^(1/(H+1)).

    Notes
    -----
    **Spectra with a roll-off or a cutoff** (``surfaces.self_affine(rolloff=λ_r,
    cutoff=λ_c)``). Eq. 11, and ζ(H) of eq. 13, belong to the paper's spectrum:
    self-affine from the system size L down to the grid (λ_r = L, no cutoff).
    There h, the rms of the whole surface, is also the rms of the self-affine
    band, and eq. 11 reads k = ζ E* (F L^H/(E* h))^(1/(H+1)): L enters only
    through h/L^H, the amplitude of the power law of eq. 1 (for a given
    C2D(q) = A q^(−2H−2), h² ∝ A L^(2H)); the system size itself drops out.

    * Roll-off, λ_r < L. Neither the paper nor this package establishes
      eq. 11 here. The reading that keeps the amplitude of the power law is
      eq. 11 with (h, L) → (h_r, λ_r), h_r the rms of the self-affine band
      ``q_r ≤ |q| ≤ q_c`` alone (not of the whole surface, whose plateau adds
      long-wavelength height); it is a conjecture, and can at most apply
      while the load is carried within about one roll-off wavelength. Once
      the contact spreads over many roll-off patches, a nominally flat
      surface stiffens linearly with the load, k ∝ F: Pastewka et al.
      (Phys. Rev. E 87, 062809 (2013)) find the interfacial stiffness
      proportional to the pressure over a wide range, and the sublinear
      power law only at small pressures, as a finite-size effect. Eq. 11,
      and the superposition of eq. 16 built on it, do not describe that
      regime.
    * Cutoff, λ_c ≥ 2 cells. The stiffness is set by the long wavelengths
      (the paper's Conclusions), so eq. 11 with h the rms of the whole surface
      may still hold while contact patches are larger than λ_c (untested
      here); at loads so small that a single asperity, smooth below λ_c,
      carries the load, the contact is Hertz-like (k ∝ F^(1/3)).
    * ζ(H) ≈ 1.7/(H+1) (eq. 13) and the pipeline's fitted ζ belong to
      spectra without roll-off or cutoff; for others, fit ζ on flat surfaces
      generated with the same λ_r and λ_c.
    """
    force = np.asarray(force, dtype=float)
    return e_star * length * zeta * (force / (e_star * h_rms * length)) ** (1.0 / (hurst + 1.0))


def profile_prefactor(hurst, *, h_rms, length, zeta):
    """Q3D of the axisymmetric profile ``z_s = Q3D |r|^H`` equivalent to the roughness (eq. 14).

    Q3D = (2/(ζ L))^(H+1) (H+1) L h / (2 H κ(H)); unit length^(1−H).
    """
    return ((2.0 / (zeta * length)) ** (hurst + 1.0) * (hurst + 1.0) * length * h_rms
            / (2.0 * hurst * kappa(hurst)))


class Indentation(NamedTuple):
    """Force (force unit), depth (length unit) and stiffness (force/length) of an indentation."""

    force: np.ndarray
    depth: np.ndarray
    stiffness: np.ndarray


def profile_indentation(contact_radius, *, q3d, hurst, e_star):
    """Rigid axisymmetric indenter ``z = Q3D |r|^H`` at contact radius a (the law behind eq. 7).

    With the method of dimensionality reduction (the paper's refs. 15, 17) or
    Sneddon's solution, an axisymmetric indenter f(r) pressed to contact radius
    a has depth d = a ∫₀^a f'(r)/√(a² − r²) dr and stiffness k = 2 E* a; for
    f = Q3D r^H the integral is κ(H) of eq. 8:

    d = κ(H) Q3D a^H,   k = 2 E* a,
    F = ∫₀^a k(a') (dd/da') da' = 2 E* H κ(H) Q3D a^(H+1)/(H+1).

    Eliminating a between F and k gives eq. 7. H may be any exponent > 0, e.g.
    the m of a body of revolution (:func:`body_indentation`).

    Parameters
    ----------
    contact_radius : array_like
        a (length unit).
    q3d : float
        Q3D (length^(1−H)).
    hurst : float
        Exponent H of the profile, > 0.
    e_star : float
        Effective modulus E* (force/length²).

    Returns
    -------
    Indentation
        ``(force, depth, stiffness)`` at each a.
    """
    a = np.asarray(contact_radius, dtype=float)
    k_h = kappa(hurst)
    return Indentation(force=2.0 * e_star * hurst * k_h * q3d * a ** (hurst + 1.0) / (hurst + 1.0),
                       depth=k_h * q3d * a**hurst,
                       stiffness=2.0 * e_star * a)


def body_indentation(contact_radius, *, radius, e_star, exponent=2.0):
    """Smooth body of revolution z = (R/m)(r/R)^m at contact radius a (eq. 7 with H → m).

    :func:`profile_indentation` with Q3D = R^(1−m)/m (:func:`body_prefactor`):
    d = κ(m) R^(1−m) a^m/m, F = 2 E* κ(m) R^(1−m) a^(m+1)/(m+1), k = 2 E* a.
    m = 2 is Hertz (d = a²/R, F = 4 E* a³/(3R)); m = 1 is the cone of slope 1
    (κ(1) = π/2: d = π a/2, F = π E* a²/2).

    Parameters
    ----------
    contact_radius : array_like
        a (length unit).
    radius : float
        R (length unit).
    e_star : float
        Effective modulus E* (force/length²).
    exponent : float
        m > 0, keyword-only.

    Returns
    -------
    Indentation
        ``(force, depth, stiffness)`` at each a.
    """
    return profile_indentation(contact_radius, q3d=body_prefactor(radius, exponent=exponent), hurst=exponent, e_star=e_star)


def profile_stiffness(force, *, q3d, hurst, e_star):
    """Stiffness of a rigid axisymmetric indenter ``z = Q3D |r|^H`` (eq. 7).

    k = 2 E* ((H+1) F / (2 Q3D E* H κ(H)))^(1/(H+1)).
    """
    force = np.asarray(force, dtype=float)
    return 2.0 * e_star * ((hurst + 1.0) * force
                           / (2.0 * q3d * e_star * hurst * kappa(hurst))) ** (1.0 / (hurst + 1.0))


def force_from_stiffness(stiffness, *, radius, hurst, h_rms, length, e_star, zeta,
                         exponent=2.0):
    """Force of the rough body at a given stiffness, superposing eqs. 10 and 12 (eq. 16).

    F = E* [ (k/E*)³/(6R) + L h (k/(ζ E* L))^(H+1) ]; ``radius = inf`` drops the Hertz term.

    With ``exponent = m`` the first term is that of the smooth body of
    revolution z = (R/m)(r/R)^m, F_body = E* (k/E*)^(m+1)/c_m with
    c_m = (m+1) 2^m R^(m−1)/κ(m) (eq. 7 with H → m, Q3D = R^(1−m)/m; c_2 = 6R).
    The superposition rests on the same argument as for the sphere: at a given
    stiffness, i.e. contact radius, the forces of the two equivalent profiles
    (eq. 15 with the body term) add.
    """
    k = np.asarray(stiffness, dtype=float)
    body = (0.0 if math.isinf(radius)
            else (k / e_star) ** (exponent + 1.0) / _body_coefficient(radius, exponent))
    return e_star * (body + length * h_rms * (k / (zeta * e_star * length)) ** (hurst + 1.0))


def stiffness_from_force(force, *, radius, hurst, h_rms, length, e_star, zeta, exponent=2.0):
    """Invert eq. 16 for k at given force(s) (bisection in log k to machine precision).

    The root lies between min(k_9, k_11) at F/2 and at F, where k_9 and k_11 are
    the two asymptotes (eqs. 9 and 11), because eq. 16 is a sum of two
    increasing terms. ``exponent = m`` replaces the sphere by the body of
    revolution z = (R/m)(r/R)^m (:func:`force_from_stiffness`), and eq. 9 by
    :func:`body_stiffness`.
    """
    force = np.asarray(force, dtype=float)
    if math.isinf(radius):
        return fractal_stiffness(force, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta)

    def asymptote_min(f):
        return np.minimum(body_stiffness(f, radius=radius, e_star=e_star, exponent=exponent),
                          fractal_stiffness(f, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta))

    lo = np.log(asymptote_min(force / 2.0))
    hi = np.log(asymptote_min(force))
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        too_stiff = force_from_stiffness(np.exp(mid), radius=radius, hurst=hurst, h_rms=h_rms, length=length,
                                         e_star=e_star, zeta=zeta, exponent=exponent) > force
        hi = np.where(too_stiff, mid, hi)
        lo = np.where(too_stiff, lo, mid)
    return np.exp(0.5 * (lo + hi))


def crossover_force(radius, *, hurst, h_rms, length, e_star, zeta, exponent=2.0):
    """Force where the asymptotes of eq. 16 intersect (eq. 17).

    F_tr/E* = [ζ^(3H+3) h^(−3) L^(3H) (6R)^(−H−1)]^(1/(H−2)).

    With ``exponent = m`` (body of revolution z = (R/m)(r/R)^m), equating
    E* (k/E*)^(m+1)/c_m (:func:`force_from_stiffness`) and eq. 12 gives
    F_tr/E* = [ζ^((m+1)(H+1)) h^(−(m+1)) L^((m+1)H) c_m^(−H−1)]^(1/(H−m)),
    c_m = (m+1) 2^m R^(m−1)/κ(m); c_2 = 6R gives eq. 17. For m = H the
    asymptotes are parallel and there is no crossover (``ValueError``).
    """
    if np.any(np.asarray(hurst) == exponent):
        raise ValueError(f"exponent must differ from hurst (parallel asymptotes, no crossover), "
                         f"got exponent={exponent!r}, hurst={hurst!r}")
    power = exponent + 1.0
    base = zeta ** (power * hurst + power) * h_rms ** -power * length ** (power * hurst) \
        * _body_coefficient(radius, exponent) ** (-hurst - 1.0)
    return e_star * base ** (1.0 / (hurst - exponent))


def crossover_slope(hurst, *, exponent=2.0):
    """Local slope d ln k/d ln F of eq. 16 where its two terms are equal: 2/(H+4).

    With F = a k³ + b k^(H+1) and a k³ = b k^(H+1): d ln F/d ln k = (3 + H + 1)/2.
    The terms are equal at the stiffness where the asymptotes (eqs. 9, 11)
    intersect, i.e. on the eq. 16 curve at F = 2 F_tr (F_tr of eq. 17): a force
    read off a measured curve where its slope crosses 2/(H+4) is 2 F_tr.
    With ``exponent = m`` the body term is a k^(m+1) and the slope 2/(H+m+2).
    """
    return 2.0 / (np.asarray(hurst, dtype=float) + (exponent + 2.0))


def equivalent_height(r, *, radius, hurst, h_rms, length, zeta=None, exponent=2.0):
    """Height ``z_c(r)`` of the axisymmetric profile equivalent to a rough body (eq. 15).

    ``z_c(r) = (R/m)(r/R)^m + Q3D |r|^H`` with ``Q3D`` from eq. 14 (``m = 2``: the parabola
    ``r²/(2R)``); ``radius = inf`` gives the roughness-equivalent profile ``z_s`` of eq. 6
    alone. ``zeta`` defaults to the estimate 1.7/(H+1) (eq. 13). Vectorised over ``r``
    (length unit, any sign).
    """
    check_hurst(hurst)
    if not (radius > 0):
        raise ValueError(f"radius must be > 0 (inf allowed), got {radius!r}")
    check_finite_positive("exponent", exponent)
    if zeta is None:
        zeta = zeta_estimate(hurst)
    check_finite_positive("zeta", zeta)
    r = np.abs(np.asarray(r, dtype=float))
    profile = profile_prefactor(hurst, h_rms=h_rms, length=length, zeta=zeta) * r**hurst
    if math.isfinite(radius):
        profile = profile + body_height(r, radius, exponent)
    return profile


def equivalent_profile(n: int, *, radius: float, hurst: float, h_rms: float,
                       length: float = 1.0, zeta: float | None = None,
                       exponent: float = 2.0) -> np.ndarray:
    """:func:`equivalent_height` (eq. 15) on the ``n × n`` grid, ``r`` measured from the
    node ``(n//2, n//2)`` (:func:`roughcontact.surfaces.radial_distance`)."""
    return equivalent_height(radial_distance(n, length), radius=radius, hurst=hurst, h_rms=h_rms,
                             length=length, zeta=zeta, exponent=exponent)
