"""The prefactor ζ of a rough sphere's fractal branch (eq. 16's low-force limit) from where it touches.

Eq. 16's rough term is eq. 12, ``F = E* L h (k/(ζ E* L))^(H+1)``, with the ζ of nominally flat
surfaces (eq. 13; :func:`roughcontact.models.zeta_law.zeta_law`). On the same surfaces pressed as
spheres and converged on 2048² (``docs/results/fractal_prefactor.md``, issue 31), the branch's ζ is
not one constant times the flat law: it falls with the height of the roughness at the point where
the sphere first touches,

    ζ_s = ζ_law(H) · exp(−β u),      u = −z_r(x*)/h_rms,

``x*`` the first touch of the rough body (the least of ``z_r + r²/2R`` in this package's gap
convention), ``z_r`` the roughness, ``u`` its height there in units of its rms (ensemble mean).
A small sphere touches near its apex at an ordinary point of the roughness (u ≈ 0.3); a large
one, or a rough one, searches a wider apex region and touches a higher summit, whose long waves
rise to it like a cap (``u`` → 3 on a flat periodic cell, the highest point of the surface): the
long wavelengths then act as a peaked form, and the contact is softer at the same force. u is a
property of the surface and the body alone (no contact solve): :func:`touch_height` for one
surface, :func:`expected_touch_height` for the mean over seeds.

Calibrated on 12 sphere cases of that page (H 0.3–0.9 at R = 0.5 L, h_rms = 9·10⁻³ L; R 0.1–2 L and
h_rms 3·10⁻³–2.7·10⁻² L at H = 0.7; spectra self-affine from L down to a 2048² grid, no roll-off;
2026-11-27): see :data:`CALIBRATED`. Range of validity: that range, ``√(4 R h_rms)/L`` 0.06–0.27;
not tested with a roll-off or a cutoff, on other grids, or above the crossover (eq. 16's Hertz term
keeps its form). Not registered in the model scorecard (to be judged on held-out presets).
Lengths in units of the caller (``length`` = L), forces as in :mod:`roughcontact.models.paper`.
"""
from __future__ import annotations

import numpy as np

from ..surfaces import self_affine
from ..surfaces.bodies import body_height, radial_distance
from .zeta_law import zeta_law

__all__ = ["CALIBRATED", "fractal_prefactor", "touch_height", "expected_touch_height"]

#: β of ζ_s = ζ_law(H) exp(−β u), least squares of ln(ζ_s/ζ_law) against u over the 12 sphere cases
#: of docs/results/fractal_prefactor.md (12–36 seeds, 2048², loads of the converged fractal branch),
#: the intercept fixed to 1 (free, it is 0.999); largest residual 2.9 %, 2026-11-27
CALIBRATED = {"beta": 0.0576, "source": "docs/results/fractal_prefactor.md (python docs/make_fractal_prefactor.py)"}


def fractal_prefactor(hurst, touch, *, beta=None):
    """ζ_s = ζ_law(H) · exp(−β u): the prefactor of eq. 12 on a rough sphere's fractal branch.

    Parameters
    ----------
    hurst : array_like
        H, in the calibrated range 0.3–0.9.
    touch : array_like
        u, the mean height of the roughness at the first touch in units of its rms
        (:func:`expected_touch_height`); dimensionless.
    beta : float, optional
        β; default :data:`CALIBRATED`.

    Returns
    -------
    numpy.ndarray
        ζ_s (dimensionless), to use in eq. 12/16 in place of ζ
        (:func:`roughcontact.models.paper.stiffness_from_force`).
    """
    beta = CALIBRATED["beta"] if beta is None else beta
    return zeta_law(hurst) * np.exp(-beta * np.asarray(touch, dtype=float))


def touch_height(roughness, *, radius, length=1.0, exponent=2.0):
    """u = −z_r(x*)/rms(z_r) at the first touch x* = argmin(z_r + z_body) of one surface.

    Parameters
    ----------
    roughness : array_like, shape (n, n)
        z_r (length unit), heights as gaps (:mod:`roughcontact.bem`: contact where z is least).
    radius : float
        R of the body (length unit); ``inf``: the flat surface, u = −min z_r/rms.
    length : float
        L, the side of the grid (length unit).
    exponent : float
        m of the body of revolution (2: the paraboloid of :func:`roughcontact.surfaces.rough_sphere`).

    Returns
    -------
    float
        u (dimensionless); the body's apex is node ``(n//2, n//2)`` as in ``rough_sphere``.
    """
    z = np.asarray(roughness, dtype=float)
    if z.ndim != 2 or z.shape[0] != z.shape[1]:
        raise ValueError(f"roughness must be a square 2-D array, got shape {z.shape}")
    total = z if np.isinf(radius) else z + body_height(radial_distance(z.shape[0], length), radius, exponent)
    rough = z - z.mean()
    return float(-rough.flat[np.argmin(total)] / np.sqrt(np.mean(rough**2)))


def expected_touch_height(n, *, radius, hurst, h_rms, length=1.0, seeds=range(12), realization_of=None):
    """Mean of :func:`touch_height` over the seeds' surfaces :func:`roughcontact.surfaces.self_affine`
    (no roll-off, no cutoff; ``realization_of`` as there): one FFT of the grid per seed.

    Returns
    -------
    float
        ū (dimensionless).
    """
    return float(np.mean([touch_height(self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                                                   realization_of=realization_of), radius=radius, length=length)
                          for seed in seeds]))
