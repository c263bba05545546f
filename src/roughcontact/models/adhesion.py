"""Closed forms of the adhesive contact of a smooth sphere: JKR, DMT and Maugis–Dugdale.

A rigid sphere of radius ``R`` (the paraboloid ``r²/2R``) on an elastic half-space of effective
modulus ``E*`` with work of adhesion ``w`` (energy per area). Units are the caller's,
consistent: lengths, ``E*`` and ``w`` (force/length) give forces and stiffnesses in force and
force/length. Forces are compressive positive, so the pull-off force is negative.

* JKR (K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324, 301 (1971),
  doi:10.1098/rspa.1971.0141): ``F = 4E*a³/(3R) − √(8πwE*a³)``, ``d = a²/R − √(2πwa/E*)``;
  the load-controlled pull-off ``F = −(3/2)πwR`` at ``a³ = 9πwR²/(8E*)``, the
  displacement-controlled instability at ``dd/da = 0``, ``a³ = πwR²/(8E*)`` (a ninth of the
  former's cube), where ``F = −(5/6)πwR``.
* DMT (B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, J. Colloid Interface Sci. 53, 314 (1975),
  doi:10.1016/0021-9797(75)90018-1): Hertz under ``F + 2πwR``; pull-off ``−2πwR``.
* Maugis–Dugdale (D. Maugis, J. Colloid Interface Sci. 150, 243 (1992),
  doi:10.1016/0021-9797(92)90285-T): a constant tensile stress ``σ₀`` where the gap is below
  ``δ_t = w/σ₀``, out to the radius ``c = m a``; with ``K = 4E*/3`` and Maugis' units
  ``ā = a (K/(πwR²))^(1/3)``, ``P̄ = F/(πwR)``, ``δ̄ = d (K²/(π²w²R))^(1/3)`` and the parameter
  ``λ = 2σ₀ (R/(πwK²))^(1/3) = σ₀ (9R/(2πwE*²))^(1/3)`` (Johnson & Greenwood, J. Colloid
  Interface Sci. 192, 326 (1997)), ``m`` solves

      (λā²/2)[√(m²−1) + (m²−2) arctan√(m²−1)] + (4λ²ā/3)[√(m²−1) arctan√(m²−1) − m + 1] = 1,

  and ``P̄ = ā³ − λā²[√(m²−1) + m² arctan√(m²−1)]``, ``δ̄ = ā² − (4/3)λā√(m²−1)``. The pull-off
  goes from DMT's ``P̄ = −2`` (λ → 0) to JKR's ``−3/2`` (λ → ∞). (``shared/literature.md`` writes
  λ with ``E*`` where Maugis has ``K``: its λ is ``(16/9)^(1/3)`` = 1.21 times Maugis'.)
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from .._validate import check_finite_positive

__all__ = ["JKRState", "MaugisDugdaleState", "dmt_contact_radius", "dmt_pull_off", "jkr", "jkr_fixed_grips_pull_off",
           "jkr_pull_off", "maugis_cohesive_stress", "maugis_dugdale", "maugis_dugdale_pull_off", "maugis_parameter",
           "maugis_work_of_adhesion"]


def _check(radius, e_star, work):
    check_finite_positive("radius", radius)
    check_finite_positive("e_star", e_star)
    check_finite_positive("work_of_adhesion", work)


@dataclasses.dataclass(frozen=True)
class JKRState:
    """The JKR contact at given contact radii (arrays of the shape of ``contact_radius``).

    Attributes
    ----------
    contact_radius : numpy.ndarray
        ``a`` (length).
    force : numpy.ndarray
        ``F = 4E*a³/(3R) − √(8πwE*a³)`` (force; negative: tensile).
    depth : numpy.ndarray
        Approach ``d = a²/R − √(2πwa/E*)`` (length; zero where the undeformed sphere touches).
    stiffness : numpy.ndarray
        ``k = dF/dd = (dF/da)/(dd/da)`` along the equilibrium branch (force/length): a pole at
        the fixed-grips instability ``a³ = πwR²/(8E*)`` (``dd/da = 0``), negative between it and
        the load-controlled pull-off ``a³ = 9πwR²/(8E*)``, where the contact is stable under
        displacement control only.
    """

    contact_radius: np.ndarray
    force: np.ndarray
    depth: np.ndarray
    stiffness: np.ndarray


def jkr(contact_radius, *, radius: float, e_star: float, work_of_adhesion: float) -> JKRState:
    """The JKR sphere at contact radii ``a > 0`` (both branches: the whole equilibrium curve)."""
    _check(radius, e_star, work_of_adhesion)
    a = np.asarray(contact_radius, dtype=float)
    if not np.all(np.isfinite(a)) or np.any(a <= 0):
        raise ValueError("contact_radius must be finite and > 0")
    w, R, E = work_of_adhesion, radius, e_star
    force = 4 * E * a**3 / (3 * R) - np.sqrt(8 * math.pi * w * E * a**3)
    depth = a**2 / R - np.sqrt(2 * math.pi * w * a / E)
    dforce = 4 * E * a**2 / R - 1.5 * np.sqrt(8 * math.pi * w * E * a)
    ddepth = 2 * a / R - 0.5 * np.sqrt(2 * math.pi * w / (E * a))
    with np.errstate(divide="ignore", invalid="ignore"):
        stiffness = dforce / ddepth
    return JKRState(contact_radius=a, force=force, depth=depth, stiffness=stiffness)


def jkr_pull_off(*, radius: float, e_star: float, work_of_adhesion: float) -> tuple[float, float]:
    """``(F, a)`` of the load-controlled JKR pull-off: ``F = −(3/2)πwR`` at ``a³ = 9πwR²/(8E*)``."""
    _check(radius, e_star, work_of_adhesion)
    return (-1.5 * math.pi * work_of_adhesion * radius,
            (9 * math.pi * work_of_adhesion * radius**2 / (8 * e_star)) ** (1 / 3))


def jkr_fixed_grips_pull_off(*, radius: float, e_star: float, work_of_adhesion: float) -> tuple[float, float, float]:
    """``(F, a, d)`` where a displacement-controlled JKR contact jumps off: ``dd/da = 0``,
    ``a³ = πwR²/(8E*)``, ``F = −(5/6)πwR``."""
    _check(radius, e_star, work_of_adhesion)
    a = (math.pi * work_of_adhesion * radius**2 / (8 * e_star)) ** (1 / 3)
    state = jkr(a, radius=radius, e_star=e_star, work_of_adhesion=work_of_adhesion)
    return float(state.force), a, float(state.depth)


def dmt_pull_off(*, radius: float, work_of_adhesion: float) -> float:
    """The DMT pull-off force ``−2πwR``."""
    check_finite_positive("radius", radius)
    check_finite_positive("work_of_adhesion", work_of_adhesion)
    return -2 * math.pi * work_of_adhesion * radius


def dmt_contact_radius(force, *, radius: float, e_star: float, work_of_adhesion: float) -> np.ndarray:
    """DMT's contact radius: Hertz under ``F + 2πwR``, ``a³ = 3R(F + 2πwR)/(4E*)`` (0 below pull-off)."""
    _check(radius, e_star, work_of_adhesion)
    load = np.asarray(force, dtype=float) + 2 * math.pi * work_of_adhesion * radius
    return np.cbrt(np.maximum(load, 0.0) * 3 * radius / (4 * e_star))


def maugis_parameter(cohesive_stress: float, *, radius: float, e_star: float, work_of_adhesion: float) -> float:
    """Maugis' ``λ = 2σ₀ (R/(πwK²))^(1/3)``, ``K = 4E*/3``, i.e. ``σ₀ (9R/(2πwE*²))^(1/3)``."""
    _check(radius, e_star, work_of_adhesion)
    check_finite_positive("cohesive_stress", cohesive_stress)
    k = 4 * e_star / 3
    return 2 * cohesive_stress * (radius / (math.pi * work_of_adhesion * k**2)) ** (1 / 3)


def maugis_cohesive_stress(lam: float, *, radius: float, e_star: float, work_of_adhesion: float) -> float:
    """The inverse of :func:`maugis_parameter`: ``σ₀ = (λ/2)(πwK²/R)^(1/3)`` (pressure), ``K = 4E*/3``."""
    _check(radius, e_star, work_of_adhesion)
    check_finite_positive("lam", lam)
    k = 4 * e_star / 3
    return lam / 2 * (math.pi * work_of_adhesion * k**2 / radius) ** (1 / 3)


def maugis_work_of_adhesion(length_unit: float, *, radius: float, e_star: float) -> float:
    """The work of adhesion ``w = Kℓ³/(πR²)``, ``K = 4E*/3``, whose Maugis length unit
    ``ℓ = (πwR²/K)^(1/3)`` (the unit of ``ā``: ``a = ā ℓ``) is *length_unit*: a sweep in cells of
    the contact radius."""
    check_finite_positive("length_unit", length_unit)
    check_finite_positive("radius", radius)
    check_finite_positive("e_star", e_star)
    return 4 * e_star / 3 * length_unit**3 / (math.pi * radius**2)


@dataclasses.dataclass(frozen=True)
class MaugisDugdaleState:
    """One Maugis–Dugdale equilibrium in Maugis' units (module docstring).

    Attributes
    ----------
    a, m, force, depth : float
        ``ā``, the ratio ``m = c/a`` of the cohesive zone's outer radius to the contact radius,
        ``P̄ = F/(πwR)`` and ``δ̄``.
    """

    a: float
    m: float
    force: float
    depth: float


def _terms(m: float) -> tuple[float, float]:
    root = math.sqrt(max(m * m - 1.0, 0.0))
    return root, math.atan(root)


def maugis_dugdale(a_bar: float, lam: float) -> MaugisDugdaleState:
    """The Maugis–Dugdale equilibrium at ``ā`` for the parameter ``λ`` (Maugis 1992, eqs. in the
    module docstring): ``m`` by Brent's method on ``[1, m_max]``, the bracket doubled until the
    left side exceeds 1 (it rises monotonically from 0 at ``m = 1``)."""
    check_finite_positive("a_bar", a_bar)
    check_finite_positive("lam", lam)

    def excess(m):
        root, angle = _terms(m)
        return (lam * a_bar**2 / 2 * (root + (m * m - 2) * angle)
                + 4 * lam**2 * a_bar / 3 * (root * angle - m + 1) - 1.0)

    top = 2.0
    while excess(top) < 0:
        top *= 2.0
        if top > 1e12:
            raise ValueError(f"no Maugis-Dugdale equilibrium at a_bar = {a_bar!r}, lambda = {lam!r}")
    m = brentq(excess, 1.0, top, xtol=1e-14, rtol=1e-14)
    root, angle = _terms(m)
    force = a_bar**3 - lam * a_bar**2 * (root + m * m * angle)
    depth = a_bar**2 - 4 / 3 * lam * a_bar * root
    return MaugisDugdaleState(a=a_bar, m=m, force=force, depth=depth)


def maugis_dugdale_pull_off(lam: float) -> MaugisDugdaleState:
    """The load-controlled pull-off of the Maugis–Dugdale sphere: the least ``P̄(ā)`` (bounded
    scalar minimisation in ``ln ā`` to a relative 1e-10), between DMT's −2 and JKR's −3/2."""
    check_finite_positive("lam", lam)
    result = minimize_scalar(lambda log_a: maugis_dugdale(math.exp(log_a), lam).force, bounds=(math.log(1e-4),
                             math.log(10.0)), method="bounded", options={"xatol": 1e-10})
    return maugis_dugdale(math.exp(result.x), lam)
