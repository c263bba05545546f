"""Eq. 16 generalised: the forces of the body and of the roughness joined by a p-norm, the roughness
seen at the scale of the contact.

Pohrt & Popov add, at a given stiffness k = 2 E* a, the forces of the two equivalent
axisymmetric profiles (eq. 16): ``F = F_body(k) + F_rough(k)``, with
``F_body = E* (k/E*)^(m+1)/c_m`` (eq. 10; ``c_2 = 6R``) and
``F_rough = E* L h (k/(ζ E* L))^(H+1)`` (eq. 12). The sum is exact only for one profile that
is the sum of the two, ``z = r²/2R + Q3D r^H`` (eq. 15), and eq. 15 itself is a model: the
rough surface is not axisymmetric and its equivalent profile's prefactor ζ is fitted on flat
surfaces. This module joins the two forces by their p-norm

    F = (F_body(k)^p + F_rough(k)^p)^(1/p),        p ≥ 1,

which keeps both asymptotes (eqs. 9 and 11), is eq. 16 for ``p = 1`` and tends to
``max(F_body, F_rough)`` (``k = min(k_9, k_11)``) as ``p → ∞``. At the crossover stiffness
(``F_body = F_rough``) the force is ``2^(1/p)`` times either term instead of twice it: a
``p > 1`` makes the transition sharper, a ``0 < p < 1`` broader than eq. 16's.

**The roughness seen at the scale of the contact.** Eq. 12 holds for the paper's spectrum,
self-affine from L down to the grid, where it depends on h and L only through the amplitude
``h/L^H`` of the power law (:func:`roughcontact.models.paper.fractal_stiffness`). A contact of
radius ``a = k/(2E*)`` feels the roughness at wavelengths of about its size; longer ones move
it as a whole. Given the surface's spectrum, this module replaces h in eq. 12 by

    h_a = h · √(SF(λ)/SF_ref(λ)),   λ = min(w·a, L),

``SF(λ)`` the spectrum's structure function (the mean square height difference over a distance
λ, :meth:`roughcontact.surfaces.spectra.Spectrum.structure_function`) and ``SF_ref`` that of the pure
self-affine spectrum of the same H, h and grid. For the paper's spectrum ``h_a = h`` and this is
eq. 16 exactly. Below a roll-off λ_r < L, ``h_a > h`` (at equal h_rms the power law then carries
more of the variance); above it the structure function saturates at ``2 h_rms²`` while
``SF_ref`` grows as ``λ^(2H)``, so the roughness's force levels off, as that of an equivalent
profile that is flat beyond λ_r; below a cutoff the surface is smooth and ``SF ∝ λ²``.
``w`` (the window, 2 by default: the contact's diameter) is a modelling choice.

**A tail towards the body's law.** Near the body's branch (``x = F_rough/F_body → 0``) the p-norm
gives ``F = F_body (1 + x^p/p)``, so the order that shapes the crossover also sets how fast the
rough sphere reaches eq. 9: ``1 − k/k_body ∝ F^(−(m − H) p/(m + 1))``. BEM ensembles approach
Hertz faster than the p that fits the crossover allows (results, "The fractal branch's model",
"The Hertz end": about ``F^(−0.72)`` against ``F^(−0.51…−0.57)``). A compliance of the interface
in series with the body, an extra approach that grows as ``ln p̄`` with the mean pressure
``p̄ ∝ F^((m − 1)/(m + 1))`` under the body (the separation of a rough interface falls as
``−ln p``: B. N. J. Persson, Phys. Rev. Lett. 99, 125502 (2007), doi:10.1103/PhysRevLett.99.125502),
gives ``1 − k/k_body ∝ F^(−m/(m + 1))``: ``F^(−2/3)`` for the paraboloid. The join with a tail

    F = F_body (1 + β x^s + x^p)^(1/p),     s = m/(m − H),

has that law near the body's branch when ``s < p``, ``1 − k/k_body → β x^s/(p (m + 1))``, and
the roughness's branch (eq. 11) where ``x → ∞``; ``β = 0`` is the p-norm.

:data:`CALIBRATED` holds p and a factor on ζ calibrated on the BEM ensembles of named presets
(:mod:`roughcontact.study.analysis.calibration`); :data:`CALIBRATED_HURST` makes both linear in
H (the model ``contact_scale_h``, :func:`hurst_calibrated_stiffness`); :data:`CALIBRATED_TAIL`
adds the tail's β (the model ``contact_scale_tail``, :func:`tail_calibrated_stiffness`). The derivation and the
calibrations are in the documentation (guide, "Models"; results, "The fractal branch's model").

Units are the caller's, consistent as in :mod:`roughcontact.models.paper`.
"""
from __future__ import annotations

import math

import numpy as np

from .paper import _body_coefficient, body_stiffness, fractal_stiffness
from .zeta_law import zeta_law

__all__ = ["CALIBRATED", "CALIBRATED_HURST", "CALIBRATED_TAIL", "rough_force", "force_from_stiffness",
           "stiffness_from_force", "tail_exponent", "calibrated_stiffness", "hurst_constants",
           "hurst_calibrated_stiffness", "tail_calibrated_stiffness"]

#: c_ζ (the factor on :func:`roughcontact.models.zeta_law.zeta_law`) and p, calibrated by
#: ``python -m roughcontact.study.analysis.calibration`` on the sphere ensembles of presets/calibration.yaml
#: (H 0.4, 0.7, 1.0; R 0.1, 0.5; h_rms 5e-3, 2e-2; 513², 12 seeds), convergence-513.yaml (50 seeds)
#: and convergence-1025.yaml (20 seeds), 189 resolved loads, 2026-11-24: χ²/point 1.29
#: (eq. 16 with the same ζ law: 3.46; with ζ = 1.7/(H+1): 4.60)
CALIBRATED = {"zeta_factor": 0.8866, "power": 1.4215,
              "source": "presets calibration, convergence-513, convergence-1025 (python -m roughcontact.study.analysis.calibration)"}
#: ``contact_scale_h``: c_ζ and p polynomials in H (:func:`hurst_constants`), here of degree 1,
#: calibrated by ``python -m roughcontact.study.analysis.calibration --form hurst`` on the sphere
#: ensembles of presets/calibration-branches.yaml (449², 256 seeds), calibration-branches-451.yaml
#: (451², 128 seeds) and calibration-branches-447.yaml (447², 256 seeds) alone: the same spheres
#: (H 0.3, 0.6, 0.9; R 0.15, 0.6 L; h_rms 8e-3, 3e-2 L) on three sets of surfaces, 396 resolved
#: loads, 2026-11-27: χ²/point 1.95; the sets alone give c_ζ(0.6) 0.875, 0.840 and 0.885 (each set's
#: combinations share their surfaces, so each carries one sampling offset; 95 % intervals over seeds
#: in docs/results/fractal_branch_model.md); ``hurst``: the H range it rests on
CALIBRATED_HURST = {"zeta_factor": (0.9214, -0.0837), "power": (0.7752, 0.7693), "hurst": (0.3, 0.9),
                    "source": "presets calibration-branches, calibration-branches-451 and calibration-branches-447 "
                              "(python -m roughcontact.study.analysis.calibration --form hurst)"}

#: ``contact_scale_tail``: c_ζ and p linear in H as in :data:`CALIBRATED_HURST`, and the tail's β
#: (module docstring), calibrated by ``python -m roughcontact.study.analysis.calibration --form tail``
#: on the same three presets, 396 resolved loads, 2026-11-27: χ²/point 1.19 (the form ``hurst``:
#: 1.95); 95 % intervals over 50 resamples of the seeds: c₀ [0.955, 1.010], c₁ [−0.012, 0.072],
#: p₀ [1.736, 1.837], p₁ [0.329, 0.700], β [2.150, 2.711]; ``hurst``: the H range it rests on
CALIBRATED_TAIL = {"zeta_factor": (0.9793, 0.0286), "power": (1.7916, 0.4938), "tail": 2.3869, "hurst": (0.3, 0.9),
                   "source": "presets calibration-branches, calibration-branches-451 and calibration-branches-447 "
                             "(python -m roughcontact.study.analysis.calibration --form tail)"}


def tail_exponent(hurst, exponent=2.0):
    """``s = m/(m − H)`` of the join's tail (module docstring): ``x^s ∝ k^(−m)``, so that
    ``1 − k/k_body ∝ F^(−m/(m + 1))`` near the body's branch."""
    return exponent / (exponent - hurst)


def rough_force(stiffness, *, hurst, h_rms, length, e_star, zeta, spectrum=None, reference=None, window=2.0):
    """The roughness's force at stiffness k: eq. 12, ``F = E* L h (k/(ζ E* L))^(H+1)``, with h
    replaced by ``h_a`` of the scale of the contact when *spectrum* and *reference* are given
    (module docstring).

    Parameters
    ----------
    stiffness : array_like
        k (force/length), > 0.
    hurst, h_rms, length, e_star, zeta : float
        H, h (length), L (length), E* (force/length²) and ζ of eq. 12.
    spectrum, reference : roughcontact.surfaces.Spectrum, optional
        The surface's spectrum and the pure self-affine spectrum of the same H, h and grid
        (:func:`roughcontact.surfaces.spectra.self_affine_spectrum`); both or neither.
    window : float
        ``w`` of ``λ = min(w a, L)``, a = k/(2E*).

    Returns
    -------
    numpy.ndarray
        F (force).
    """
    k = np.asarray(stiffness, dtype=float)
    h = h_rms
    if (spectrum is None) != (reference is None):
        raise ValueError("give both spectrum and reference, or neither")
    if spectrum is not None:
        lag = np.minimum(window * k / (2.0 * e_star), length)
        with np.errstate(invalid="ignore", divide="ignore"):
            ratio = spectrum.structure_function(lag) / reference.structure_function(lag)
        h = h_rms * np.sqrt(np.where(np.isfinite(ratio), ratio, 0.0))
    return e_star * length * h * (k / (zeta * e_star * length)) ** (hurst + 1.0)


def force_from_stiffness(stiffness, *, radius, hurst, h_rms, length, e_star, zeta, power, exponent=2.0,
                         spectrum=None, reference=None, window=2.0, tail=0.0):
    """Force at stiffness k: the p-norm (``p = power``) of eqs. 10 and 12, with the tail
    ``β = tail`` when it is positive (module docstring).

    Parameters
    ----------
    stiffness : array_like
        k (force/length), > 0.
    radius : float
        R (length); ``inf`` leaves the roughness term alone (eq. 11).
    hurst, h_rms, length, e_star, zeta : float
        H, h (length), L (length), E* (force/length²) and ζ of eq. 12.
    power : float
        p > 0; 1 is eq. 16.
    exponent : float
        m of the body of revolution z = (R/m)(r/R)^m; 2 is the paraboloid.
    spectrum, reference, window
        The roughness at the contact's scale (:func:`rough_force`); ``None``: eq. 12.
    tail : float
        β ≥ 0 of ``F = F_body (1 + β x^s + x^p)^(1/p)``; 0 is the p-norm.

    Returns
    -------
    numpy.ndarray
        F (force).
    """
    if not power > 0.0:
        raise ValueError(f"power must be > 0, got {power!r}")
    if not tail >= 0.0:
        raise ValueError(f"tail must be >= 0, got {tail!r}")
    k = np.asarray(stiffness, dtype=float)
    rough = rough_force(k, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta,
                        spectrum=spectrum, reference=reference, window=window)
    if math.isinf(radius):
        return rough
    body = e_star * (k / e_star) ** (exponent + 1.0) / _body_coefficient(radius, exponent)
    if tail > 0.0:
        # ln(1 + β x^s + x^p) by log-sum-exp (no overflow for large x or p); x = 0 (no roughness
        # force at the contact's scale, e.g. below a cutoff) gives ln x = −inf and F = F_body
        with np.errstate(divide="ignore"):
            log_x = np.log(rough / body)
        terms = np.stack([np.zeros_like(log_x), math.log(tail) + tail_exponent(hurst, exponent) * log_x,
                          power * log_x])
        return body * np.exp(np.logaddexp.reduce(terms, axis=0) / power)
    top = np.maximum(body, rough)
    # the p-norm scaled by its larger term (no overflow for large p)
    return top * ((body / top) ** power + (rough / top) ** power) ** (1.0 / power)


def stiffness_from_force(force, *, radius, hurst, h_rms, length, e_star, zeta, power, exponent=2.0,
                         spectrum=None, reference=None, window=2.0, tail=0.0):
    """Invert :func:`force_from_stiffness` for k at given force(s) (bisection in ln k).

    F(k) increases with k. With a finite radius the body's term alone bounds k from above by
    the body's stiffness at F (eq. 9; the p-norm is at least its larger term for every p > 0); with ``radius = inf`` and a spectrum, ``k_top`` is eq. 11's
    stiffness times e³⁰. 200 halvings of ``[ln k_top − 60, ln k_top]`` reach machine precision.
    """
    force = np.asarray(force, dtype=float)
    kwargs = dict(radius=radius, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta, power=power,
                  exponent=exponent, spectrum=spectrum, reference=reference, window=window, tail=tail)
    if spectrum is None and math.isinf(radius):
        return fractal_stiffness(force, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star, zeta=zeta)
    if math.isinf(radius):
        top = np.log(fractal_stiffness(force, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star,
                                       zeta=zeta)) + 30.0
    else:
        top = np.log(body_stiffness(force, radius=radius, e_star=e_star, exponent=exponent))
    lo, hi = top - 60.0, top
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        too_stiff = force_from_stiffness(np.exp(mid), **kwargs) > force
        hi = np.where(too_stiff, mid, hi)
        lo = np.where(too_stiff, lo, mid)
    return np.exp(0.5 * (lo + hi))


def calibrated_stiffness(force, *, radius, hurst, h_rms, length, e_star, exponent=2.0, spectrum=None,
                         reference=None, zeta_factor=None, power=None, tail=0.0):
    """The scorecard's ``contact_scale``: :func:`stiffness_from_force` with ζ = c_ζ · ζ_law(H)
    (:func:`roughcontact.models.zeta_law.zeta_law`) and the p-norm's p; ``zeta_factor`` and
    ``power`` default to :data:`CALIBRATED` (the calibration passes its trial values); ``tail``
    the join's β (0: none)."""
    zeta_factor = CALIBRATED["zeta_factor"] if zeta_factor is None else zeta_factor
    power = CALIBRATED["power"] if power is None else power
    return stiffness_from_force(force, radius=radius, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star,
                                zeta=zeta_factor * float(zeta_law(hurst)), power=power, exponent=exponent,
                                spectrum=spectrum, reference=reference, tail=tail)


def hurst_constants(hurst, constants=None) -> tuple[float, float]:
    """``(c_ζ, p)`` at the Hurst exponent H: polynomials in H, ``c_ζ = c₀ + c₁ H (+ c₂ H²)`` and
    ``p = p₀ + p₁ H (+ p₂ H²)``, the coefficients ``constants["zeta_factor"] = (c₀, c₁, ...)`` and
    ``constants["power"] = (p₀, p₁, ...)`` in rising order (default :data:`CALIBRATED_HURST`)."""
    constants = CALIBRATED_HURST if constants is None else constants
    c, p = (np.polynomial.polynomial.polyval(hurst, constants[key]) for key in ("zeta_factor", "power"))
    return float(c), float(p)


def hurst_calibrated_stiffness(force, *, radius, hurst, h_rms, length, e_star, exponent=2.0, spectrum=None,
                               reference=None, constants=None):
    """The scorecard's ``contact_scale_h``: :func:`calibrated_stiffness` with ``c_ζ`` and ``p``
    linear in H (:func:`hurst_constants`, :data:`CALIBRATED_HURST`), and the join's tail β where
    *constants* has one (``constants["tail"]``; :func:`tail_calibrated_stiffness`)."""
    constants = CALIBRATED_HURST if constants is None else constants
    zeta_factor, power = hurst_constants(hurst, constants)
    return calibrated_stiffness(force, radius=radius, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star,
                                exponent=exponent, spectrum=spectrum, reference=reference,
                                zeta_factor=zeta_factor, power=power, tail=constants.get("tail", 0.0))


def tail_calibrated_stiffness(force, *, radius, hurst, h_rms, length, e_star, exponent=2.0, spectrum=None,
                              reference=None, constants=None):
    """The scorecard's ``contact_scale_tail``: :func:`hurst_calibrated_stiffness` with the tail's β
    (module docstring), all constants from :data:`CALIBRATED_TAIL` unless *constants* (the same
    keys) are given."""
    return hurst_calibrated_stiffness(force, radius=radius, hurst=hurst, h_rms=h_rms, length=length, e_star=e_star,
                                      exponent=exponent, spectrum=spectrum, reference=reference,
                                      constants=CALIBRATED_TAIL if constants is None else constants)
