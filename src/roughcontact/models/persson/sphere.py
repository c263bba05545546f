"""The rough sphere of Persson's theory: the flat interface law in series with the sphere.

:func:`sphere_stiffness` presses a paraboloid on the flat interface law of
:mod:`roughcontact.models.persson.interface`, either at its apex (Hertz's pressure and the
small-pressure law) or through the axisymmetric nominal contact of
:mod:`roughcontact.models.axisymmetric`.

References
----------
B. N. J. Persson, Surf. Sci. Rep. 61, 201 (2006), doi:10.1016/j.surfrep.2006.04.001, §3.6.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..._validate import check_finite_positive
from .. import axisymmetric
from ..paper import hertz_contact_radius
from .interface import _InterfaceLaw, _check_gamma, _check_spectrum

__all__ = ["SphereStiffness", "sphere_stiffness"]

_METHODS = ("axisymmetric", "apex")


@dataclasses.dataclass(frozen=True)
class SphereStiffness:
    """Normal stiffness of a rough sphere against force (:func:`sphere_stiffness`).

    Attributes
    ----------
    force : numpy.ndarray
        Normal force ``F`` (force).
    stiffness : numpy.ndarray
        ``k = dF/dd`` (force/length).
    hertz_stiffness : numpy.ndarray
        Smooth sphere's ``k_H = (6 R E*² F)^(1/3)`` (force/length).
    approach : numpy.ndarray
        Approach ``d`` (length) from the position where the mean plane of the
        apex touches the undeformed flat; NaN for ``method="apex"`` (defined
        there only up to a constant).
    central_pressure : numpy.ndarray
        Nominal pressure at ``r = 0`` (force/length²); Hertz's ``p0`` for
        ``method="apex"``.
    separation_scale : float
        ``u0`` (length).
    method : str
    """

    force: np.ndarray
    stiffness: np.ndarray
    hertz_stiffness: np.ndarray
    approach: np.ndarray
    central_pressure: np.ndarray
    separation_scale: float
    method: str


def sphere_stiffness(force, spectrum, *, radius, e_star, gamma=0.42, method="axisymmetric",
                     n_rings=200):
    """Stiffness of a rough sphere: Persson's interfacial law in series with the sphere.

    Assumptions (both methods): the sphere's nominal shape is the paraboloid
    ``r²/(2R)`` (``r ≪ R``); the roughness of both bodies is lumped into
    ``spectrum`` on a rigid indenter pressed into a half-space of modulus
    ``E*``; the interface acts locally, ``ū(r) = ū(p(r))`` with ``ū`` of
    :func:`mean_separation` and ``p(r)`` the nominal pressure, which needs
    ``p`` to vary slowly over the longest wavelength ``L`` of the spectrum
    (nominal contact radius ≫ L); no adhesion, friction or plasticity.

    ``method="apex"`` (the simplest limit): the nominal pressure is Hertz's,
    ``p0 = (6F E*²/(π³R²))^(1/3) ∝ F^(1/3)``, and the interface at the apex
    follows the small-pressure law ``ū = −u0 ln p + c``. The approach is the
    Hertz approach plus the interface's compression at the apex,
    ``d = d_H(F) − ū(p0) = d_H(F) + (u0/3) ln F + const``, so
    ``dd/dF = 1/k_H + u0/(3F)``:

        1/k = 1/k_H + u0/(3F),    k_H = (6 R E*² F)^(1/3),

    linear, ``k ≈ 3F/u0``, at small ``F``, Hertz at large ``F``.

    ``method="axisymmetric"``: the axisymmetric nominal contact is solved with
    the interface as a nonlinear compliant layer (Greenwood–Tripp-like),
    ``r²/(2R) − d + u_z(r) = ū(p(r))``, ``u_z`` the half-space displacement
    of ``p`` (Johnson's ring kernel), ``F = ∫ 2πr p dr``; ``n_rings`` rings of
    equal width up to ``r_max = √((1.6 a_H)² + 80 R u0)`` (``a_H`` the Hertz
    radius; ``p ∝ e^{−40}`` there at small loads; doubled until the outer 10 %
    of the rings carry < 1e-9 of the force) and ``k = dF/dd`` by implicit
    differentiation of the converged discrete equations. It uses the full
    ``ū(p)``, not only its logarithmic limit. Limits: ``h → 0`` or
    ``F → ∞``: Hertz; ``F → 0`` (elastic deflection ≪ ``u0`` and ``p`` in the
    logarithmic range): ``p(r) ∝ e^{(d − r²/2R)/u0}``, so ``k → F/u0``, a
    third of the apex method's ``3F/u0`` (the nominal pressure is then a
    Gaussian of fixed width ``√(R u0)``, not Hertz's).

    Parameters
    ----------
    force : array_like
        Normal force ``F`` (force), > 0.
    spectrum : Spectrum
        Combined roughness.
    radius : float
        Sphere radius ``R`` (length).
    e_star : float
        Effective modulus ``E*`` (force/length²).
    gamma : float
        Yang & Persson's ``γ``.
    method : {"axisymmetric", "apex"}
    n_rings : int
        Radial rings of the axisymmetric method.

    Returns
    -------
    SphereStiffness

    References
    ----------
    B. N. J. Persson, Surf. Sci. Rep. 61, 201 (2006), doi:10.1016/j.surfrep.2006.04.001, §3.6;
    J. A. Greenwood, J. H. Tripp, J. Appl. Mech. 34, 153 (1967), doi:10.1115/1.3607616;
    L. Pastewka, M. O. Robbins, Appl. Phys. Lett. 108, 221601 (2016), doi:10.1063/1.4950802.
    """
    _check_spectrum(spectrum)
    check_finite_positive("radius", radius)
    check_finite_positive("e_star", e_star)
    _check_gamma(gamma)
    if method not in _METHODS:
        raise ValueError(f"method must be one of {_METHODS}, got {method!r}")
    if isinstance(n_rings, bool) or not isinstance(n_rings, int) or n_rings < 16:
        raise ValueError(f"n_rings must be an integer >= 16, got {n_rings!r}")
    force = np.asarray(force, dtype=float)
    if not np.all(np.isfinite(force)) or np.any(force <= 0):
        raise ValueError("force must be finite and > 0")
    law = _InterfaceLaw(spectrum, e_star, gamma)
    u0 = law.scale
    hertz = np.cbrt(6.0 * radius * e_star**2 * force)
    if method == "apex":
        return SphereStiffness(
            force=force, stiffness=1.0 / (1.0 / hertz + u0 / (3.0 * force)),
            hertz_stiffness=hertz, approach=np.full(force.shape, np.nan),
            central_pressure=np.cbrt(6.0 * force * e_star**2 / (np.pi**3 * radius**2)),
            separation_scale=u0, method=method)
    stiffness, approach, central = (np.empty(force.shape) for _ in range(3))
    for index in np.ndindex(force.shape):
        contact = _axisymmetric_contact(float(force[index]), radius, e_star, law, n_rings)
        stiffness[index] = contact.stiffness
        approach[index] = contact.approach
        central[index] = contact.pressure[0]
    return SphereStiffness(force=force, stiffness=stiffness, hertz_stiffness=hertz,
                           approach=approach, central_pressure=central,
                           separation_scale=u0, method=method)


def _axisymmetric_contact(force, radius, e_star, law, n_rings):
    """Solve on a domain large enough that the outer tenth of the rings carries < 1e-9 of F."""
    hertz_radius = hertz_contact_radius(force, radius=radius, e_star=e_star)
    r_max = math.sqrt((1.6 * hertz_radius) ** 2 + 80.0 * radius * law.scale)
    for _ in range(4):
        contact = axisymmetric.solve(force, radius=radius, e_star=e_star, law=law,
                                      r_max=r_max, n_rings=n_rings)
        outer = contact.radii > 0.9 * r_max
        ring_force = 2.0 * np.pi * contact.radii * contact.pressure * (r_max / n_rings)
        if ring_force[outer].sum() < 1e-9 * force:
            return contact
        r_max *= 2.0
    raise RuntimeError("nominal contact still reaches the edge of the radial domain")
