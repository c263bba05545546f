"""Greenwood & Tripp's rough sphere in physical units: load curves from GT's solver.

:func:`greenwood_tripp_curve` solves :func:`roughcontact.models.greenwood_tripp.solver.greenwood_tripp`
at a list of central separations ``d*`` for a sphere of radius ``R`` on summits of given statistics
(:mod:`roughcontact.models.asperities`) and converts force, approach and stiffness to physical
units; :func:`self_affine_sphere_curve` does so for the paper's rough sphere, the summit statistics
from the spectral moments of a generated self-affine spectrum.

J. A. Greenwood, J. H. Tripp, "The elastic contact of rough spheres",
J. Appl. Mech. 34, 153 (1967), doi:10.1115/1.3607616.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..._validate import check_finite_positive
from ...surfaces.moments import self_affine_moments
from ..asperities import AsperityParameters, asperity_parameters, mu_parameter
from .solver import greenwood_tripp

__all__ = [
    "GreenwoodTrippCurve",
    "greenwood_tripp_curve",
    "self_affine_sphere_curve",
]


@dataclasses.dataclass(frozen=True, eq=False)
class GreenwoodTrippCurve:
    """GT's load curve of a rough sphere in physical units.

    Attributes
    ----------
    depth_star : numpy.ndarray
        Central separations ``d*`` solved (units ``σ``).
    force : numpy.ndarray
        Normal force ``F = E* σ^(3/2) √(R/2) · force_star`` (force unit).
    approach : numpy.ndarray
        Rigid-body approach ``σ · approach_star`` (length unit), counted from
        the apex touching the undeformed mean summit plane.
    stiffness : numpy.ndarray
        ``k = dF/d(approach) = E* √(σR/2) · stiffness_star`` (force/length).
    mu : float
        GT's ``μ`` of the surface and sphere.
    sigma : float
        GT's ``σ`` (the summit-height standard deviation, length unit).
    """

    depth_star: np.ndarray
    force: np.ndarray
    approach: np.ndarray
    stiffness: np.ndarray
    mu: float
    sigma: float


def greenwood_tripp_curve(depths_star, *, radius: float, e_star: float,
                          asperities: AsperityParameters, rho_max: float = 5.0,
                          points: int = 100) -> GreenwoodTrippCurve:
    """Force against stiffness (and approach) of GT for a sphere of radius ``radius``.

    Solves :func:`greenwood_tripp` at each ``d*`` with ``μ`` from
    :func:`mu_parameter`, ``σ = asperities.summit_sigma`` and ``B = radius``,
    and converts to physical units (:class:`GreenwoodTrippCurve`); ``F`` of
    ``k`` is the curve ``(stiffness, force)``, to be set beside eq. 16 of
    Pohrt & Popov (2013) or a BEM load path.
    """
    check_finite_positive("e_star", e_star)
    mu = mu_parameter(asperities, radius=radius)
    depths = np.atleast_1d(np.asarray(depths_star, dtype=float))
    solutions = [greenwood_tripp(float(d), mu, rho_max=rho_max, points=points) for d in depths]
    return _curve(depths, solutions, radius=radius, e_star=e_star, asperities=asperities)


def _curve(depths, solutions, *, radius, e_star, asperities) -> GreenwoodTrippCurve:
    """GT solutions at ``depths`` (d*) in physical units."""
    mu, sigma = mu_parameter(asperities, radius=radius), asperities.summit_sigma
    force_unit = e_star * sigma**1.5 * math.sqrt(radius / 2.0)
    return GreenwoodTrippCurve(
        depth_star=depths,
        force=force_unit * np.array([s.force_star for s in solutions]),
        approach=sigma * np.array([s.approach_star for s in solutions]),
        stiffness=force_unit / sigma * np.array([s.stiffness_star for s in solutions]),
        mu=mu, sigma=sigma)


#: central separations d* = d/σ of :func:`self_affine_sphere_curve`: from light contact (3σ)
#: to well past GT's transition to Hertz (−1.5σ)
SPHERE_DEPTHS_STAR = np.linspace(3.0, -1.5, 10)


def self_affine_sphere_curve(*, hurst: float, h_rms: float, n: int, length: float, radius: float,
                             e_star: float, depths_star=SPHERE_DEPTHS_STAR, points_per_unit: int = 8,
                             rho_limit: float = 80.0) -> GreenwoodTrippCurve:
    """GT's load curve for the paper's rough sphere: the asperity parameters (η, β,
    σ) from the spectral moments of the generated self-affine spectrum on an
    ``n × n`` grid of side ``length`` (:func:`self_affine_moments`, Nayak/McCool),
    ``B = radius``. Each ``d*`` is solved on ``rho_max = 5, 10, 20, ...`` (units
    √(2Bσ), ``points_per_unit`` nodes per unit, keyword-only) until the pressure
    has died out at ``rho_max``; separations whose load spreads beyond
    ``rho_limit`` are left out of the curve."""
    asperities = asperity_parameters(self_affine_moments(hurst, h_rms=h_rms, n=n, length=length))
    mu = mu_parameter(asperities, radius=radius)
    depths, solutions = [], []
    for depth in np.atleast_1d(np.asarray(depths_star, dtype=float)):
        rho_max = 5.0
        while rho_max <= rho_limit:
            try:
                solutions.append(greenwood_tripp(float(depth), mu, rho_max=rho_max,
                                                 points=int(points_per_unit * rho_max)))
            except ValueError:
                rho_max *= 2
                continue
            depths.append(depth)
            break
    return _curve(np.array(depths), solutions, radius=radius, e_star=e_star, asperities=asperities)
