"""The scorecard's models, predicting the stiffness of a measured surface from its spectrum fit.

:func:`predict` takes a :class:`~roughcontact.surfaces.spectrum_fit.SpectrumFit` (H, the fitted
power law and the measured spectrum of a topography) and returns ``k(F)`` of every model of the
registry :mod:`roughcontact.models.scorecard`, the same functions the generated scorecard calls,
given a :class:`~roughcontact.models.scorecard.Surface` that carries the measured spectrum and
its moments:

* eq. 16 (``eq16_paper``, ``eq16_fitted`` with the caller's ``zeta``, ``eq16_law``) and
  ``contact_scale`` read the fitted H and the rms height (the fitted power law's on the
  ``n × n`` grid of side ``length``, :meth:`SpectrumFit.h_rms_for`, or the caller's ``h_rms``);
* ``greenwood_tripp`` reads the summit statistics (Nayak/McCool) of the *measured* spectrum's
  moments; ``persson`` the *measured* spectrum;
* ``mdr`` builds 1D profiles of the *fitted* self-affine spectrum (profiles of an arbitrary
  measured spectrum are not built).

``radius = inf`` (a nominally flat surface of side ``length``): eq. 16 becomes eq. 11, MDR the
flat Winkler foundation, Persson ``k = K(p) L²`` with ``p = F/L²``; Greenwood–Tripp, a sphere
model, is omitted. The crossover force of eq. 17 (:func:`crossover_force`) is NaN for the flat
surface.

Units are the caller's, consistent: lengths (``radius``, ``length``, the heights of the fit)
in one length unit, ``E*`` in force/length², forces in force units, stiffnesses in
force/length (e.g. nm, GPa = nN/nm², nN, nN/nm).
"""
from __future__ import annotations

import math

import numpy as np

from ..._validate import check_finite_positive, check_grid_size, check_radius
from ...models import paper
from ...models import scorecard as registry
from ...surfaces.spectrum_fit import SpectrumFit
from ..config import axes

__all__ = ["crossover_force", "predict", "surface_of"]


def surface_of(fit: SpectrumFit, *, radius, e_star, length, n, zeta=None, h_rms=None) -> registry.Surface:
    """The :class:`~roughcontact.models.scorecard.Surface` the models read for the fitted surface
    (paraboloid, no roll-off, no cutoff, the measured spectrum and its moments): a measured run
    is at the paper's setting of every optional axis, so its ``axes`` are the paper's coordinates
    (:func:`roughcontact.study.config.axes.paper_coordinates` of *length*)."""
    return registry.Surface(
        radius=float(radius), hurst=fit.hurst, h_rms=fit.h_rms_for(length, n) if h_rms is None else float(h_rms),
        length=float(length), e_star=float(e_star), n=int(n), zeta_fit=math.nan if zeta is None else float(zeta),
        spectrum=fit.spectrum, moments=fit.moments, axes=axes.paper_coordinates(float(length)))


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
        ``k`` (force/length) at each force for every registered model that applies (``eq16_fitted``
        with ``zeta`` only; ``greenwood_tripp`` for a finite ``radius``, NaN outside its solved
        range), in the registry's order; and ``crossover_force``, a 0-d array (force), eq. 17
        (NaN for ``radius = inf``).
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
    out = registry.predict(force, surface_of(fit, radius=radius, e_star=e_star, length=length, n=n, zeta=zeta,
                                             h_rms=h_rms))
    out["crossover_force"] = np.asarray(crossover_force(fit, radius=radius, e_star=e_star, length=length, n=n,
                                                        zeta=zeta, h_rms=h_rms))
    return out
