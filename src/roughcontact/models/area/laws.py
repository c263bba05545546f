"""Closed forms of the real contact area of a rough sphere.

Units are the caller's, consistent: forces ``e_star * length²``, areas ``length²``. The rms slope
``h′_rms`` is that of the whole gradient, ``h′_rms² = ⟨|∇h|²⟩ = Σ q² variance`` of the spectrum
(:attr:`roughcontact.surfaces.spectra.Spectrum.rms_slope`), the definition of Hyun et al. (2004) and
Pastewka & Robbins (2016), not the one-profile slope ``⟨(∂h/∂x)²⟩ = h′_rms²/2``.

* Hertz (Johnson 1985, eq. 4.22): ``A_H = π a²``, ``a = (3FR/(4E*))^(1/3)``.
* Linear law (Hyun, Pei, Molinari & Robbins, Phys. Rev. E 70, 026117 (2004),
  doi:10.1103/PhysRevE.70.026117): ``A = κ F/(E* h′_rms)``, κ ≈ 2 in simulations; Persson's theory
  gives κ = √(8/π) (J. Chem. Phys. 115, 3840 (2001), doi:10.1063/1.1388626).
* The linear law joined to Hertz (Pastewka & Robbins, Appl. Phys. Lett. 108, 221601 (2016),
  doi:10.1063/1.4950802: linear below the crossover, Hertz above): ``A = min(κ F/(E* h′_rms), π a²)``,
  the two equal at :func:`area_crossover_force`.
* The end of the one-asperity regime (this package's criterion; Pastewka & Robbins 2016 describe the
  regime, a Hertz contact on the first summit, ``A ∝ F^(2/3)``): the force where one summit's Hertz
  area ``π (3F R_s/(4E*))^(2/3)`` equals the linear law's, :func:`single_asperity_force`, the same
  closed form as ``F_A`` with the summit radius ``R_s`` for ``R``: ``F_1 = F_A (R_s/R)²``.
* Persson's area under the sphere's nominal pressure: the flat-surface law
  ``A/A0 = erf(√2 p/(E* h′_rms))`` (Persson 2001; Surf. Sci. Rep. 61, 201 (2006),
  doi:10.1016/j.surfrep.2006.04.001: ``erf(p/(2√G))``, ``G = E*² h′_rms²/8``) applied at each
  radius to Hertz's ``p(r) = p0 √(1 − r²/a²)``, ``p0 = 3F/(2π a²)``, and integrated over the
  nominal contact: with ``β = √2 p0/(E* h′_rms)``,
  ``A/(π a²) = ∫₀¹ erf(β √u) du = erf(β) (1 − 1/(2β²)) + e^(−β²)/(√π β)``
  (:func:`persson_area`). Small β: ``4β/(3√π)``, i.e. ``A = √(8/π) F/(E* h′_rms)``; large β: 1.
"""
from __future__ import annotations

import math

import numpy as np
from scipy.special import erf

from ..paper import hertz_contact_radius

__all__ = ["PERSSON_KAPPA", "SIMULATION_KAPPA", "hertz_area", "linear_area", "joined_area", "area_crossover_force",
           "single_asperity_force", "persson_area", "persson_area_fraction", "persson_fraction_at"]

#: κ of Persson's theory, √(8/π) ≈ 1.596 (small-pressure limit of erf, Persson 2001)
PERSSON_KAPPA = math.sqrt(8.0 / math.pi)
#: κ of the simulations of Hyun et al. (2004) and Pastewka & Robbins (2016), ≈ 2
SIMULATION_KAPPA = 2.0
#: below this β the series of :func:`persson_area_fraction` is used (the closed form cancels)
_SERIES_BELOW = 0.5


def hertz_area(force, *, radius: float, e_star: float):
    """Hertz's contact area ``π a²``, ``a = (3FR/(4E*))^(1/3)`` (length²)."""
    a = hertz_contact_radius(force, radius=radius, e_star=e_star)
    return math.pi * a * a


def linear_area(force, *, e_star: float, rms_slope: float, kappa: float = SIMULATION_KAPPA):
    """The linear law ``A = κ F/(E* h′_rms)`` (Hyun et al. 2004) (length²)."""
    return kappa * np.asarray(force, dtype=float) / (e_star * rms_slope)


def joined_area(force, *, radius: float, e_star: float, rms_slope: float, kappa: float = SIMULATION_KAPPA):
    """The linear law below the crossover, Hertz above: ``min(κ F/(E* h′_rms), π a²)`` (length²)."""
    return np.minimum(linear_area(force, e_star=e_star, rms_slope=rms_slope, kappa=kappa),
                      hertz_area(force, radius=radius, e_star=e_star))


def area_crossover_force(*, radius: float, e_star: float, rms_slope: float, kappa: float = SIMULATION_KAPPA):
    """The force where ``κ F/(E* h′_rms) = π a²``: ``F_A = (π/κ)³ (3R/4)² E* h′_rms³`` (there Hertz's mean
    pressure ``F/(π a²)`` equals ``E* h′_rms/κ``)."""
    return (math.pi / kappa) ** 3 * (0.75 * radius) ** 2 * e_star * rms_slope**3


def single_asperity_force(*, summit_radius: float, e_star: float, rms_slope: float,
                          kappa: float = SIMULATION_KAPPA):
    """The force where one summit's Hertz area equals the linear law's (force units):
    ``π (3 F R_s/(4E*))^(2/3) = κ F/(E* h′_rms)`` at ``F_1 = (π/κ)³ (3R_s/4)² E* h′_rms³``
    (:func:`area_crossover_force` with the summit radius ``R_s`` for the sphere's ``R``).

    Below ``F_1`` the contact is one (or a few) summits near the apex and ``A ∝ F^(2/3)``; above it
    the linear law's area is the larger. Assumes an elastic paraboloidal summit of radius *summit_radius*
    (length) and the linear law with *kappa*.
    """
    return area_crossover_force(radius=summit_radius, e_star=e_star, rms_slope=rms_slope, kappa=kappa)


def persson_area_fraction(beta):
    """``∫₀¹ erf(β √u) du``, the fraction of Hertz's area in contact under Persson's law at
    ``β = √2 p0/(E* h′_rms)`` (module docstring); 0 at β = 0, → 1 as β → ∞."""
    beta = np.asarray(beta, dtype=float)
    out = np.empty_like(beta)
    small = beta < _SERIES_BELOW
    b = beta[small]
    # (4/√π) Σ_k (−1)^k β^(2k+1) / (k! (2k+1) (2k+3)): 14 terms, error < 0.5^29/14! ~ 1e-20
    series = np.zeros_like(b)
    for k in range(14):
        series += (-1) ** k * b ** (2 * k + 1) / (math.factorial(k) * (2 * k + 1) * (2 * k + 3))
    out[small] = 4.0 / math.sqrt(math.pi) * series
    b = beta[~small]
    out[~small] = erf(b) * (1.0 - 0.5 / b**2) + np.exp(-b * b) / (math.sqrt(math.pi) * b)
    return out


def persson_area(force, *, radius: float, e_star: float, rms_slope: float):
    """Persson's real contact area under the sphere's nominal (Hertz) pressure (length²):
    ``π a² ∫₀¹ erf(β √u) du`` with ``β = √2 p0/(E* h′_rms)``, ``p0 = 3F/(2π a²)`` (module docstring)."""
    force = np.asarray(force, dtype=float)
    area = hertz_area(force, radius=radius, e_star=e_star)
    with np.errstate(divide="ignore", invalid="ignore"):
        p0 = np.where(area > 0, 1.5 * force / np.where(area > 0, area, 1.0), 0.0)
    return area * persson_area_fraction(math.sqrt(2.0) * p0 / (e_star * rms_slope))


def persson_fraction_at(ratio, kappa: float = SIMULATION_KAPPA):
    """Persson's ``A/(π a²)`` at ``F = ratio · F_A`` (:func:`area_crossover_force` with *kappa*), the same
    for every sphere and spectrum: there ``β = (3/√2)/κ · ratio^(1/3)`` (0.654 at the crossover, 0.904 at
    ``10 F_A`` for κ = 2)."""
    beta = 1.5 * math.sqrt(2.0) / kappa * np.cbrt(np.asarray(ratio, dtype=float))
    return persson_area_fraction(np.atleast_1d(beta)).reshape(np.shape(beta))
