"""The scorecard's models, predicting the stiffness of a measured surface from its spectrum fit.

:func:`predict` takes a :class:`~roughcontact.surfaces.spectrum_fit.SpectrumFit` (H, the fitted
power law and the measured spectrum of a topography) and returns ``k(F)`` of the models of
:data:`roughcontact.study.scorecard.MODELS`, called as the scorecard calls them for generated
surfaces (the same functions where the inputs are parameters):

* ``eq16_paper``: eq. 16 of Pohrt & Popov (2013) with ζ = 1.7/(H+1) (eq. 13), the fitted H and
  the fitted power law's rms height on the ``n × n`` grid of side ``length``
  (:meth:`SpectrumFit.h_rms_for`, or the caller's ``h_rms``); ``eq16_fitted`` the same with the
  caller's ``zeta``;
* ``greenwood_tripp``: Greenwood & Tripp (1967) on the summit statistics (Nayak/McCool) of the
  spectral moments of the *measured* spectrum (``fit.moments``), on the scorecard's separations;
* ``persson``: Persson's interfacial law from the *measured* spectrum (``fit.spectrum``,
  rebinned as the scorecard does) under the paraboloid;
* ``mdr``: the method of dimensionality reduction on 1D profiles of the *fitted* self-affine
  spectrum (H, ``h_rms_for(length, n)``): :mod:`roughcontact.surfaces.profiles` builds profiles
  of a self-affine spectrum only, not of an arbitrary measured one.

``radius = inf`` (a nominally flat surface of side ``length``): eq. 16 becomes eq. 11,
MDR the flat Winkler foundation, Persson ``k = K(p) L²`` with ``p = F/L²`` (his interfacial
stiffness :func:`roughcontact.models.persson.interfacial_stiffness` over the nominal area);
Greenwood–Tripp, a sphere model, is omitted. The crossover force of eq. 17
(:func:`crossover_force`) is NaN for the flat surface.

Units are the caller's, consistent: lengths (``radius``, ``length``, the heights of the fit)
in one length unit, ``E*`` in force/length², forces in force units, stiffnesses in
force/length (e.g. nm, GPa = nN/nm², nN, nN/nm).
"""
from __future__ import annotations

import math

import numpy as np

from .._validate import check_finite_positive, check_grid_size, check_radius
from ..models import persson as persson_model
from ..models.asperities import asperity_parameters
from ..models.greenwood_tripp import greenwood_tripp_curve
from ..models import paper
from ..surfaces.spectrum_fit import SpectrumFit
from . import scorecard

__all__ = ["crossover_force", "predict", "GT_POINTS_PER_UNIT", "GT_RHO_LIMIT"]

#: nodes per unit of ``√(2Rσ)`` and the largest ``rho_max`` of the Greenwood–Tripp solves
#: (those of :func:`roughcontact.models.greenwood_tripp.self_affine_sphere_curve`)
GT_POINTS_PER_UNIT, GT_RHO_LIMIT = 8, 80.0


def _combination(fit: SpectrumFit, *, radius, e_star, length, n, zeta, h_rms) -> scorecard.Combination:
    """The scorecard's combination for the fitted self-affine surface (paraboloid, no roll-off,
    no cutoff, elastic): what :data:`scorecard.MODELS` reads."""
    return scorecard.Combination(
        radius=float(radius), hurst=fit.hurst, h_rms=float(h_rms), length=float(length),
        e_star=float(e_star), exponent=2.0, n=int(n), rolloff=float(length), cutoff=0.0,
        hardness=math.inf, zeta_fit=math.nan if zeta is None else float(zeta))


def _greenwood_tripp(force, fit: SpectrumFit, *, radius, e_star):
    """GT's curve from the measured spectrum's moments, each separation of the scorecard's solved
    on ``rho_max = 5, 10, 20, …`` until its pressure has died out (as
    :func:`~roughcontact.models.greenwood_tripp.self_affine_sphere_curve`), interpolated in
    log k against log F; NaN outside the solved range."""
    asperities = asperity_parameters(fit.moments)
    forces, stiffnesses = [], []
    for depth in scorecard._GT_DEPTHS:
        rho_max = 5.0
        while rho_max <= GT_RHO_LIMIT:
            try:
                curve = greenwood_tripp_curve([depth], radius=radius, e_star=e_star, asperities=asperities,
                                              rho_max=rho_max, points=int(GT_POINTS_PER_UNIT * rho_max))
            except ValueError:
                rho_max *= 2
                continue
            forces.append(curve.force[0])
            stiffnesses.append(curve.stiffness[0])
            break
    f, k = np.array(forces), np.array(stiffnesses)
    ok = np.isfinite(f) & np.isfinite(k) & (f > 0)
    if not ok.any():
        return np.full(np.shape(force), np.nan)
    order = np.argsort(f[ok])
    return np.exp(np.interp(np.log(force), np.log(f[ok][order]), np.log(k[ok][order]),
                            left=np.nan, right=np.nan))


def _persson(force, fit: SpectrumFit, *, radius, e_star, length):
    spectrum = fit.spectrum.rebinned(scorecard.PERSSON_BINS_PER_DECADE)
    if math.isinf(radius):
        return persson_model.interfacial_stiffness(force / length**2, spectrum, e_star=e_star) * length**2
    return persson_model.sphere_stiffness(force, spectrum, radius=radius, e_star=e_star).stiffness


def crossover_force(fit: SpectrumFit, *, radius: float, e_star: float, length: float, n: int,
                    zeta: float | None = None, h_rms: float | None = None) -> float:
    """Eq. 17's crossover force ``F_tr`` (force) with the fitted H and ``h_rms`` (default
    ``fit.h_rms_for(length, n)``), ζ = ``zeta`` or 1.7/(H+1); NaN for ``radius = inf``."""
    check_radius(radius)
    if math.isinf(radius):
        return math.nan
    zeta = float(paper.zeta_estimate(fit.hurst)) if zeta is None else zeta
    h_rms = fit.h_rms_for(length, n) if h_rms is None else h_rms
    return float(paper.crossover_force(radius, hurst=fit.hurst, h_rms=h_rms, length=length, e_star=e_star,
                                       zeta=zeta))


def predict(force, fit: SpectrumFit, *, radius: float, e_star: float, length: float, n: int,
            zeta: float | None = None, h_rms: float | None = None) -> dict[str, np.ndarray]:
    """Stiffness ``k(F)`` of each model of the scorecard for the surface of ``fit`` (module docstring).

    Parameters
    ----------
    force : array_like
        Normal forces ``F`` > 0 (force), scalar or 1-D.
    fit : SpectrumFit
        The topography's spectrum fit (:func:`roughcontact.surfaces.spectrum_fit.fit_spectrum`).
    radius : float
        Sphere radius ``R`` (length), or ``inf`` for the nominally flat surface.
    e_star : float
        Effective modulus ``E*`` (force/length²).
    length : float
        System size ``L`` (length) the surface is pressed over: eq. 16's ``L``, MDR's profile
        length and the flat surface's nominal side; usually ``fit.length`` or the scan's side.
    n : int
        Grid points per side ``L`` (MDR's profile points; the grid on which the fitted power
        law's rms height is taken).
    zeta : float, optional
        ζ of eq. 11 fitted elsewhere (e.g. the study's ζ(H)): adds ``eq16_fitted`` and is used
        for ``crossover_force``; ``None``: ζ = 1.7/(H+1).
    h_rms : float, optional
        Rms height (length) for eq. 16/17 and MDR instead of the fitted power law's
        ``fit.h_rms_for(length, n)``, e.g. the measured ``fit.h_rms`` for a scan whose spectrum
        rolls off inside ``L`` (the power law extrapolated to ``q0 = 2π/L`` then overestimates it).

    Returns
    -------
    dict of str to numpy.ndarray
        ``k`` (force/length) at each force for ``eq16_paper``, ``eq16_fitted`` (with ``zeta``),
        ``greenwood_tripp`` (finite ``radius``; NaN outside its solved range), ``mdr`` and
        ``persson``, in the order of :data:`scorecard.MODELS`; and ``crossover_force``, a 0-d
        array (force), eq. 17 (NaN for ``radius = inf``).
    """
    check_radius(radius)
    check_finite_positive("e_star", e_star)
    check_finite_positive("length", length)
    check_grid_size(n)
    for name, value in (("zeta", zeta), ("h_rms", h_rms)):
        if value is not None:
            check_finite_positive(name, value)
    if not isinstance(fit, SpectrumFit):
        raise TypeError(f"fit must be a SpectrumFit, got {type(fit).__name__}")
    force = np.asarray(force, dtype=float)
    if force.ndim > 1 or not np.all(np.isfinite(force)) or np.any(force <= 0):
        raise ValueError("force must be a finite scalar or 1-D array of values > 0")
    h_rms = fit.h_rms_for(length, n) if h_rms is None else float(h_rms)
    combo = _combination(fit, radius=radius, e_star=e_star, length=length, n=n, zeta=zeta, h_rms=h_rms)
    out = {}
    for name in scorecard.MODELS:
        if name == "greenwood_tripp":
            k = None if math.isinf(radius) else _greenwood_tripp(force, fit, radius=radius, e_star=e_star)
        elif name == "persson":
            k = _persson(force, fit, radius=radius, e_star=e_star, length=length)
        else:
            k = scorecard.MODELS[name](force, combo)
        if k is not None:
            out[name] = np.asarray(k, dtype=float)
    out["crossover_force"] = np.asarray(crossover_force(fit, radius=radius, e_star=e_star, length=length, n=n,
                                                        zeta=zeta, h_rms=h_rms))
    return out
