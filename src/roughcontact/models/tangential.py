"""Tangential stiffness in closed form: Mindlin, Cattaneo–Mindlin and the MDR's rough sphere.

A rigid indenter on an elastic half-space of effective modulus ``E* = E/(1 − ν²)`` and shear
modulus ``G = E/(2(1 + ν)) = E*(1 − ν)/2`` (the relation used throughout), Coulomb friction
``μ``, normal force ``P``, tangential force ``0 ≤ Q < μP``, the normal–tangential coupling
neglected (Goodman's approximation; exact for elastically similar bodies):

* Mindlin (1949), full stick on a circle of radius ``a``: ``k_t = 8Ga/(2 − ν)``; with
  ``k_n = 2E*a``, ``k_t/k_n = 2(1 − ν)/(2 − ν)`` (Johnson 1985, §7.2);
* Cattaneo (1938)–Mindlin (1949) partial slip (Johnson 1985, §7.2): stick radius
  ``c = a(1 − Q/μP)^(1/3)``, displacement ``δ_x = 3μP(2 − ν)/(16Ga) [1 − (1 − Q/μP)^(2/3)]``,
  tangent stiffness ``k_t(Q) = k_t(0)(1 − Q/μP)^(1/3)``;
* the MDR (Popov & Heß 2015, §6): tangential springs ``G* Δx``, ``G* = 4G/(2 − ν)``, beside the
  normal ``E* Δx``, so ``k_t/k_n = 2(1 − ν)/(2 − ν)`` for any profile, the rough sphere's
  included: :func:`mdr_sphere_stiffness`;
* Ciavarella (1998)–Jäger (1998): ``k_t(Q)/k_t(0) = k_n(P − Q/μ)/k_n(P)`` for any normal path
  (:func:`ciavarella_jaeger_stiffness_ratio`); Grzemba et al. (2014): the largest micro-slip
  ``δ_max = μ d E*/G*`` (:func:`largest_micro_slip`).

References: R. D. Mindlin, J. Appl. Mech. 16, 259 (1949); C. Cattaneo, Rend. Accad. Naz. Lincei
27, 342 (1938); K. L. Johnson, *Contact Mechanics*, Cambridge University Press 1985,
doi:10.1017/CBO9781139171731; V. L. Popov, M. Heß, *Method of Dimensionality Reduction in
Contact Mechanics and Friction*, Springer 2015, doi:10.1007/978-3-642-53876-6.
"""

from __future__ import annotations

import numpy as np

from .._validate import check_finite_positive, is_finite_number
from . import mdr

__all__ = ["shear_modulus", "stiffness_ratio", "tangential_from_normal", "mindlin_stiffness",
           "stick_radius", "cattaneo_displacement", "cattaneo_stiffness", "cattaneo_stiffness_ratio",
           "ciavarella_jaeger_stiffness_ratio", "largest_micro_slip", "mdr_sphere_stiffness"]


def _poisson(poisson) -> float:
    if not is_finite_number(poisson) or not -1.0 < poisson <= 0.5:
        raise ValueError(f"poisson must be a Poisson ratio with -1 < poisson <= 0.5, got {poisson!r}")
    return float(poisson)


def _ratio(load_ratio) -> np.ndarray:
    """``Q/μP`` as an array, each ``0 ≤ Q/μP ≤ 1``."""
    value = np.asarray(load_ratio, dtype=float)
    if not np.all(np.isfinite(value)) or np.any(value < 0) or np.any(value > 1):
        raise ValueError(f"load_ratio Q/(mu P) must be within [0, 1], got {load_ratio!r}")
    return value


def shear_modulus(e_star: float, poisson: float) -> float:
    """``G = E*(1 − ν)/2`` (force/length²) of a half-space under a rigid indenter."""
    check_finite_positive("e_star", e_star)
    return 0.5 * e_star * (1.0 - _poisson(poisson))


def stiffness_ratio(poisson: float) -> float:
    """Mindlin's ``k_t/k_n = 2(1 − ν)/(2 − ν)`` (Mindlin's ``8Ga/(2 − ν)`` over ``2E*a``)."""
    poisson = _poisson(poisson)
    return 2.0 * (1.0 - poisson) / (2.0 - poisson)


def tangential_from_normal(normal_stiffness, *, poisson: float):
    """``k_t = k_n · 2(1 − ν)/(2 − ν)``: the tangential stiffness of any model whose normal one is
    a sum of Mindlin/MDR contacts (force/length, the unit of *normal_stiffness*)."""
    return np.asarray(normal_stiffness, dtype=float) * stiffness_ratio(poisson)


def mindlin_stiffness(contact_radius, *, e_star: float, poisson: float):
    """Full-stick ``k_t = 8Ga/(2 − ν)`` of a circle of radius ``a`` (Mindlin 1949; force/length).

    ``contact_radius`` in the length unit, ``e_star`` in force/length².
    """
    a = np.asarray(contact_radius, dtype=float)
    return 8.0 * shear_modulus(e_star, poisson) * a / (2.0 - poisson)


def stick_radius(contact_radius, load_ratio):
    """Cattaneo–Mindlin stick radius ``c = a(1 − Q/μP)^(1/3)`` (Johnson 1985, §7.2; length)."""
    return np.asarray(contact_radius, dtype=float) * np.cbrt(1.0 - _ratio(load_ratio))


def cattaneo_displacement(load_ratio, *, normal_force: float, friction: float, contact_radius: float,
                          e_star: float, poisson: float):
    """``δ_x = 3μP(2 − ν)/(16Ga) [1 − (1 − Q/μP)^(2/3)]`` (Johnson 1985, §7.2; length).

    ``normal_force`` ``P`` (force), ``friction`` ``μ``, ``contact_radius`` ``a`` (length),
    ``e_star`` (force/length²), ``load_ratio`` ``Q/μP``.
    """
    check_finite_positive("normal_force", normal_force)
    check_finite_positive("friction", friction)
    check_finite_positive("contact_radius", contact_radius)
    g = shear_modulus(e_star, poisson)
    scale = 3.0 * friction * normal_force * (2.0 - poisson) / (16.0 * g * contact_radius)
    return scale * (1.0 - (1.0 - _ratio(load_ratio)) ** (2.0 / 3.0))


def cattaneo_stiffness(load_ratio, *, contact_radius, e_star: float, poisson: float):
    """Tangent ``k_t(Q) = k_t(0)(1 − Q/μP)^(1/3)``, ``k_t(0)`` Mindlin's (force/length)."""
    return mindlin_stiffness(contact_radius, e_star=e_star, poisson=poisson) * np.cbrt(1.0 - _ratio(load_ratio))


def cattaneo_stiffness_ratio(load_ratio):
    """Cattaneo–Mindlin ``k_t(Q)/k_t(0) = (1 − Q/μP)^(1/3)`` (Johnson 1985, §7.2; the stick radius
    over the contact radius)."""
    return np.cbrt(1.0 - _ratio(load_ratio))


def ciavarella_jaeger_stiffness_ratio(load_ratio, normal_force: float, normal_stiffness):
    """Ciavarella (1998)–Jäger (1998): ``k_t(Q)/k_t(0) = k_n(P(1 − Q/μP))/k_n(P)`` for any normal
    path, the stick zone being the contact at the normal force ``P − Q/μ``.

    *normal_stiffness*: ``k_n(F)``, a callable of the force (any unit, that of *normal_force*).
    For a power law ``k_n ∝ F^β``: ``(1 − Q/μP)^β`` (Hertz, ``β = 1/3``: Cattaneo–Mindlin; the fractal
    branch, ``β = 1/(H+1)``, eq. 11)."""
    check_finite_positive("normal_force", normal_force)
    ratio = _ratio(load_ratio)
    return np.asarray(normal_stiffness(normal_force * (1.0 - ratio)), dtype=float) / float(normal_stiffness(normal_force))


def largest_micro_slip(depth, *, friction: float, poisson: float):
    """Grzemba, Pohrt, Teidelt & Popov (Wear 309, 40 (2014), doi:10.1016/j.wear.2013.09.020): the
    tangential displacement at the onset of gross sliding, ``δ_max = μ d E*/G* = μ d (2 − ν)/(2(1 − ν))``,
    ``d`` the normal approach from first touch (length, the unit of *depth*); exact for every body of
    revolution by the Ciavarella–Jäger construction."""
    check_finite_positive("friction", friction)
    return friction * np.asarray(depth, dtype=float) / stiffness_ratio(poisson)


def mdr_sphere_stiffness(force, *, poisson: float, **kwargs) -> mdr.StiffnessEnsemble:
    """Full-stick tangential stiffness of the MDR's rough sphere: the ratio times ``k_n``.

    :func:`roughcontact.models.mdr.sphere_stiffness` (same keywords, *kwargs*) with ``stiffness``
    and ``stiffness_error`` multiplied by :func:`stiffness_ratio` (the MDR's tangential springs
    ``G* = 4G/(2 − ν)`` are the normal ``E*`` times the ratio at every point, Popov & Heß 2015).
    """
    normal = mdr.sphere_stiffness(force, **kwargs)
    ratio = stiffness_ratio(poisson)
    return mdr.StiffnessEnsemble(force=normal.force, stiffness=normal.stiffness * ratio,
                                 stiffness_error=normal.stiffness_error * ratio,
                                 realizations=normal.realizations, depth=normal.depth,
                                 contact_length=normal.contact_length)
