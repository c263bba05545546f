"""Adhesion of rough surfaces: Fuller & Tabor's asperity model, Johnson's rough-sphere parameter and
Pastewka & Robbins' stickiness criterion.

Units are the caller's, consistent (lengths, ``E*`` and the work of adhesion ``w`` in
force/length); forces are compressive positive, so pull-off forces are negative. ``E*`` is the
effective modulus (:func:`roughcontact.models.effective_modulus`).

* K. N. G. Fuller, D. Tabor, "The effect of surface roughness on the adhesion of elastic solids",
  Proc. R. Soc. A 345, 327-342 (1975), doi:10.1098/rspa.1975.0138: a rigid flat against ``N``
  asperities of one radius ``β`` whose heights ``z`` (above their mean plane) are Gaussian with
  deviation ``σ`` (Greenwood & Williamson's model), each a JKR sphere
  (:mod:`roughcontact.models.adhesion`), no interaction between them. At the separation ``d`` of
  the flat from the asperities' mean plane an asperity of height ``z`` is compressed by
  ``δ = z − d``. On unloading, every asperity that touched follows JKR's branch of larger contact
  radius until it comes off at ``δ = −δ_c``, the displacement-controlled instability
  (``dδ/da = 0``), with

      δ_c = (3/4) (π² w² β / E*²)^(1/3).

  The force is

      F(d) = N ∫_{d − δ_c}^{∞} P_JKR(z − d) φ(z) dz,   φ(z) = exp(−z²/2σ²)/(σ√(2π)),

  and the pull-off is its least value over ``d``. Scaled by the pull-off of one asperity,
  ``P_c = (3/2)πwβ``, and ``δ_c``, the JKR branch is ``P/P_c = â³ − 2â^(3/2)``,
  ``δ/δ_c = 3^(1/3)(â² − (4/3)â^(1/2))``, ``â = a/a_c ≥ 3^(−2/3)`` (``a_c³ = 9πwβ²/(8E*)``), and
  the one parameter left is ``σ/δ_c = (4/3) π^(−2/3) θ^(2/3)`` with Fuller & Tabor's adhesion
  parameter

      θ = E* σ^(3/2) / (β^(1/2) w).

  ``F/(N P_c)`` is −1 for ``θ → 0`` (every asperity at one height: JKR's pull-off per asperity)
  and falls with ``θ``. Assumed as in Fuller & Tabor: every asperity within ``δ_c`` of the flat
  has touched it (a load high enough before the unloading).
* Johnson's form for a rough sphere (K. L. Johnson, Contact Mechanics, Cambridge University Press,
  1985, ch. 5 and 13; as used by Li, Pohrt & Popov, Front. Mech. Eng. 5:7 (2019),
  doi:10.3389/fmech.2019.00007): the roughness ``h_rms`` over the JKR sphere's ``δ_c`` (the
  same expression with the sphere's radius ``R`` in place of ``β``), ``h_rms/δ_c``.
* L. Pastewka, M. O. Robbins, "Contact between rough surfaces and a criterion for macroscopic
  adhesion", PNAS 111, 3298-3303 (2014), doi:10.1073/pnas.1320846111: nominally flat surfaces of
  rms slope ``h′`` and rms curvature ``h″`` with an interaction of range ``Δr`` are sticky when

      (h′ E* Δr / (2w)) · (h′² / (h″ Δr))^(2/3) < 1,

  valid where ``Δr/g₀ < 0.1``, ``g₀ = (16/3) h′²/h″``.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar

from .._validate import check_finite_positive

__all__ = ["FullerTaborPullOff", "StickinessCriterion", "fuller_tabor_force", "fuller_tabor_parameter",
           "fuller_tabor_pull_off", "jkr_critical_approach", "johnson_rough_sphere_parameter",
           "pastewka_robbins_gap", "pastewka_robbins_stickiness", "pastewka_robbins_work_of_adhesion",
           "STICKINESS_RANGE_LIMIT"]

_CBRT3 = 3.0 ** (1 / 3)
#: ``â`` where JKR's displacement-controlled branch ends (``dδ/da = 0``): ``â³ = 1/9``
_A_END = 3.0 ** (-2 / 3)
#: Gaussian tails left out of the integral (weight < 1e-32): ``z`` beyond 12σ (above the larger of
#: the lower limit and 0; below −12σ)
_TAIL = 12.0
#: separations scanned for the least force before the bounded minimisation
_SCAN = 121
#: the largest ``Δr/g₀`` of Pastewka & Robbins' derivation (an interaction range short against the
#: gaps that open at the edge of a contact)
STICKINESS_RANGE_LIMIT = 0.1


def _check_material(e_star, work_of_adhesion):
    check_finite_positive("e_star", e_star)
    check_finite_positive("work_of_adhesion", work_of_adhesion)


def jkr_critical_approach(*, radius: float, e_star: float, work_of_adhesion: float) -> float:
    """``δ_c = (3/4)(π²w²R/E*²)^(1/3)`` (length): how far a JKR sphere of radius ``R`` is pulled
    beyond first touch when it comes off under displacement control."""
    check_finite_positive("radius", radius)
    _check_material(e_star, work_of_adhesion)
    return 0.75 * (math.pi**2 * work_of_adhesion**2 * radius / e_star**2) ** (1 / 3)


def johnson_rough_sphere_parameter(h_rms: float, *, radius: float, e_star: float, work_of_adhesion: float) -> float:
    """Johnson's adhesion parameter of a rough sphere, ``h_rms/δ_c`` (module docstring)."""
    check_finite_positive("h_rms", h_rms)
    return h_rms / jkr_critical_approach(radius=radius, e_star=e_star, work_of_adhesion=work_of_adhesion)


def fuller_tabor_parameter(*, sigma: float, asperity_radius: float, e_star: float, work_of_adhesion: float) -> float:
    """Fuller & Tabor's ``θ = E*σ^(3/2)/(β^(1/2) w)``: ``σ`` the deviation of the asperity heights,
    ``β`` the asperity radius (lengths)."""
    check_finite_positive("sigma", sigma)
    check_finite_positive("asperity_radius", asperity_radius)
    _check_material(e_star, work_of_adhesion)
    return e_star * sigma**1.5 / (math.sqrt(asperity_radius) * work_of_adhesion)


def _height_ratio(theta: float) -> float:
    """``σ/δ_c = (4/3) π^(−2/3) θ^(2/3)``."""
    return 4 / 3 * math.pi ** (-2 / 3) * theta ** (2 / 3)


def _jkr_depth(a: float) -> float:
    return _CBRT3 * (a * a - 4 / 3 * math.sqrt(a))


def _jkr_force_at(depth: float) -> float:
    """``P/P_c`` of JKR's branch ``â ≥ 3^(−2/3)`` at ``δ/δ_c = depth ≥ −1`` (Brent's method in ``â``)."""
    if depth <= -1.0:
        a = _A_END
    else:
        top = max(2.0, math.sqrt(abs(depth) / _CBRT3) + 2.0)     # δ(top) > depth
        a = brentq(lambda x: _jkr_depth(x) - depth, _A_END, top, xtol=1e-15, rtol=1e-15)
    return a**3 - 2 * a**1.5


def _force(separation: float, ratio: float, tol: float) -> float:
    """``F/(N P_c)`` at ``d/δ_c = separation`` for ``σ/δ_c = ratio``: the integral in the standard
    normal variable ``x = z/σ`` from ``x = (d − δ_c)/σ``."""
    low = (separation - 1.0) / ratio
    if low > 40.0:                               # no asperity within reach (φ < 1e-347)
        return 0.0

    def integrand(x):
        return _jkr_force_at(ratio * x - separation) * math.exp(-0.5 * x * x)

    value, _ = quad(integrand, max(low, -_TAIL), max(low, 0.0) + _TAIL, limit=200, epsabs=tol * 1e-3, epsrel=tol)
    return value / math.sqrt(2 * math.pi)


def fuller_tabor_force(separation, theta: float, *, tol: float = 1e-10) -> np.ndarray:
    """``F/(N P_c)``, ``P_c = (3/2)πwβ``, at the separations ``d/δ_c`` (array_like) for the adhesion
    parameter ``θ > 0`` (module docstring); *tol*, keyword-only, is the quadrature's relative
    tolerance."""
    check_finite_positive("theta", theta)
    check_finite_positive("tol", tol)
    ratio = _height_ratio(theta)
    d = np.asarray(separation, dtype=float)
    if not np.all(np.isfinite(d)):
        raise ValueError("separation must be finite")
    return np.vectorize(lambda s: _force(float(s), ratio, tol), otypes=[float])(d)


@dataclasses.dataclass(frozen=True)
class FullerTaborPullOff:
    """The pull-off of Fuller & Tabor's rough surface (module docstring).

    Attributes
    ----------
    theta : float
        Adhesion parameter ``θ = E*σ^(3/2)/(β^(1/2) w)``.
    height_ratio : float
        ``σ/δ_c = (4/3) π^(−2/3) θ^(2/3)``.
    force : float
        Pull-off force over ``N P_c = N (3/2)πwβ`` (``−1 ≤ force ≤ 0``; −1 for ``θ = 0``).
    separation : float
        Separation ``d/δ_c`` of the flat from the asperities' mean plane at the pull-off.
    """

    theta: float
    height_ratio: float
    force: float
    separation: float


def fuller_tabor_pull_off(theta: float, *, tol: float = 1e-10) -> FullerTaborPullOff:
    """The least ``F(d)/(N P_c)`` over the separation for the adhesion parameter ``θ ≥ 0``: scanned on
    121 separations from ``−δ_c`` to ``δ_c + 8σ``, then bounded minimisation between the neighbours
    of the least (to ``tol`` in ``d/δ_c``; *tol*, keyword-only, also the quadrature's relative
    tolerance). ``θ = 0`` is JKR's sphere: −1 at ``d/δ_c = 3^(−2/3)``."""
    if theta == 0:
        return FullerTaborPullOff(theta=0.0, height_ratio=0.0, force=-1.0, separation=-_jkr_depth(1.0))
    check_finite_positive("theta", theta)
    check_finite_positive("tol", tol)
    ratio = _height_ratio(theta)
    grid = np.linspace(-1.0, 1.0 + 8 * ratio, _SCAN)
    forces = [_force(float(d), ratio, tol) for d in grid]
    i = int(np.argmin(forces))
    low, high = grid[max(i - 1, 0)], grid[min(i + 1, _SCAN - 1)]
    best = minimize_scalar(lambda d: _force(d, ratio, tol), bounds=(low, high), method="bounded",
                           options={"xatol": tol})
    force, separation = (best.fun, best.x) if best.fun <= forces[i] else (forces[i], grid[i])
    return FullerTaborPullOff(theta=float(theta), height_ratio=ratio, force=float(force),
                              separation=float(separation))


@dataclasses.dataclass(frozen=True)
class StickinessCriterion:
    """Pastewka & Robbins' stickiness criterion (module docstring).

    Attributes
    ----------
    number : float
        ``(h′E*Δr/(2w)) (h′²/(h″Δr))^(2/3)`` (dimensionless).
    sticky : bool
        ``number < 1``.
    g0 : float
        ``g₀ = (16/3) h′²/h″`` (length).
    range_ratio : float
        ``Δr/g₀``.
    valid : bool
        ``Δr/g₀ <`` :data:`STICKINESS_RANGE_LIMIT`, where the criterion was derived.
    """

    number: float
    sticky: bool
    g0: float
    range_ratio: float
    valid: bool


def pastewka_robbins_stickiness(*, rms_slope: float, rms_curvature: float, interaction_range: float,
                                e_star: float, work_of_adhesion: float) -> StickinessCriterion:
    """Whether a nominally flat rough surface is sticky after Pastewka & Robbins (2014): ``rms_slope``
    ``h′`` (dimensionless), ``rms_curvature`` ``h″`` (1/length), ``interaction_range`` ``Δr``
    (length)."""
    check_finite_positive("rms_slope", rms_slope)
    check_finite_positive("rms_curvature", rms_curvature)
    check_finite_positive("interaction_range", interaction_range)
    _check_material(e_star, work_of_adhesion)
    number = _stickiness_scale(rms_slope, rms_curvature, interaction_range, e_star) / work_of_adhesion
    g0 = pastewka_robbins_gap(rms_slope=rms_slope, rms_curvature=rms_curvature)
    return StickinessCriterion(number=number, sticky=number < 1, g0=g0, range_ratio=interaction_range / g0,
                               valid=interaction_range / g0 < STICKINESS_RANGE_LIMIT)


def _stickiness_scale(slope, curvature, reach, e_star) -> float:
    """``N w = (h′E*Δr/2) (h′²/(h″Δr))^(2/3)``: Pastewka & Robbins' number times the work."""
    return slope * e_star * reach / 2 * (slope**2 / (curvature * reach)) ** (2 / 3)


def pastewka_robbins_gap(*, rms_slope: float, rms_curvature: float) -> float:
    """``g₀ = (16/3) h′²/h″`` (length), the gap scale of Pastewka & Robbins (2014) against which
    the interaction range is short (``Δr/g₀ <`` :data:`STICKINESS_RANGE_LIMIT`)."""
    check_finite_positive("rms_slope", rms_slope)
    check_finite_positive("rms_curvature", rms_curvature)
    return 16 / 3 * rms_slope**2 / rms_curvature


def pastewka_robbins_work_of_adhesion(number: float, *, rms_slope: float, rms_curvature: float,
                                      interaction_range: float, e_star: float) -> float:
    """The work of adhesion ``w`` (``E*`` times length) that gives a surface of rms gradient
    ``h′``, rms curvature ``h″`` and an interaction of range ``Δr`` Pastewka & Robbins' *number*
    ``N``: the inverse of :func:`pastewka_robbins_stickiness`,
    ``w = (h′E*Δr/(2N)) (h′²/(h″Δr))^(2/3)``."""
    check_finite_positive("number", number)
    check_finite_positive("rms_slope", rms_slope)
    check_finite_positive("rms_curvature", rms_curvature)
    check_finite_positive("interaction_range", interaction_range)
    check_finite_positive("e_star", e_star)
    return _stickiness_scale(rms_slope, rms_curvature, interaction_range, e_star) / number
