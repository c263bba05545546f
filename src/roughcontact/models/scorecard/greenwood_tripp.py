"""Greenwood & Tripp's rough sphere (J. Appl. Mech. 34, 153 (1967), doi:10.1115/1.3607616) on
the summit statistics of the grid's self-affine spectrum or of a measured spectrum."""
from __future__ import annotations

import numpy as np

from ..asperities import asperity_parameters
from ..greenwood_tripp import greenwood_tripp_curve, self_affine_sphere_curve
from .registry import SELF_AFFINE, Model, Surface, register

#: central separations d* (units of GT's σ) of the curve: F from ~1e-7 to ~20 E*L² on the paper's sphere
DEPTHS_STAR = np.linspace(3.5, -1.5, 11)
#: nodes per unit of ``√(2Rσ)`` and the largest ``rho_max`` of the solves on a measured spectrum
#: (those of :func:`roughcontact.models.greenwood_tripp.self_affine_sphere_curve`)
POINTS_PER_UNIT, RHO_LIMIT = 8, 80.0


def _interpolated(force, f, k):
    """``k(force)`` interpolated in log k against log F; NaN outside the solved range."""
    ok = np.isfinite(f) & np.isfinite(k) & (f > 0)
    if not ok.any():
        return np.full(np.shape(force), np.nan)
    order = np.argsort(f[ok])
    return np.exp(np.interp(np.log(force), np.log(f[ok][order]), np.log(k[ok][order]), left=np.nan, right=np.nan))


def _measured_curve(s: Surface):
    """GT's curve from the measured spectrum's moments, each separation solved on
    ``rho_max = 5, 10, 20, …`` until its pressure has died out (as
    :func:`~roughcontact.models.greenwood_tripp.self_affine_sphere_curve`)."""
    asperities = asperity_parameters(s.moments)
    forces, stiffnesses = [], []
    for depth in DEPTHS_STAR:
        rho_max = 5.0
        while rho_max <= RHO_LIMIT:
            try:
                curve = greenwood_tripp_curve([depth], radius=s.radius, e_star=s.e_star, asperities=asperities,
                                              rho_max=rho_max, points=int(POINTS_PER_UNIT * rho_max))
            except ValueError:
                rho_max *= 2
                continue
            forces.append(curve.force[0])
            stiffnesses.append(curve.stiffness[0])
            break
    return np.array(forces), np.array(stiffnesses)


def greenwood_tripp(force, s: Surface):
    """GT on the summit statistics of the measured spectrum's moments, else of the grid's own
    self-affine spectrum, interpolated in log k against log F; NaN outside the solved range. A
    sphere model: a paraboloid, and for a generated surface no roll-off or cutoff (the moments
    are those of the pure self-affine spectrum)."""
    if s.flat or s.exponent != 2.0:
        return None
    if s.moments is not None:
        return _interpolated(force, *_measured_curve(s))
    if not s.pure_self_affine:
        return None
    curve = self_affine_sphere_curve(hurst=s.hurst, h_rms=s.h_rms, n=s.n, length=s.length, radius=s.radius,
                                     e_star=s.e_star, depths_star=DEPTHS_STAR)
    return _interpolated(force, curve.force, curve.stiffness)


register(Model("greenwood_tripp", "greenwood_tripp: Greenwood & Tripp (1967) on the grid's spectral moments",
               greenwood_tripp, "doi:10.1115/1.3607616",
               # declines (None) off the paraboloid and with a roll-off or a cutoff; elastic only
               axes=("exponent", "rolloff", "cutoff"), ranges=SELF_AFFINE, precomputable=True))
