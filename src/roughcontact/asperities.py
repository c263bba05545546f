"""Greenwood–Williamson summit statistics from the spectral moments of a surface.

Summit statistics from the spectral moments ``m0, m2, m4`` of an isotropic
Gaussian surface (profile moments: ``m0`` the height variance, ``m2`` the
mean-square slope and ``m4`` the mean-square curvature of a profile) follow
Nayak, J. Lubr. Technol. 93, 398 (1971), in the closed forms of McCool,
Wear 107, 37 (1986):

* summit density ``η = m4 / (6π√3 m2)``,
* mean summit radius ``β = (3/8) √(π/m4)``,
* standard deviation of the summit heights ``σ_s = √(1 − 0.8968/α) √m0``,
  with the bandwidth parameter ``α = m0 m4 / m2²`` (``α ≥ 1.5``),
* mean summit height ``4 √m0 / √(π α)`` above the mean plane.

They feed Greenwood & Tripp's ``μ = (8/3) η σ √(2Bβ)``
(:mod:`roughcontact.greenwood_tripp`).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ._validate import check_finite_positive, check_grid_size, check_hurst

__all__ = [
    "AsperityParameters",
    "SpectralMoments",
    "asperity_parameters",
    "mu_parameter",
    "self_affine_moments",
    "spectral_moments",
]


@dataclasses.dataclass(frozen=True)
class SpectralMoments:
    """Profile spectral moments of an isotropic surface (Nayak 1971).

    Attributes
    ----------
    m0 : float
        Height variance (length²).
    m2 : float
        Mean-square slope of a profile, ``⟨(∂z/∂x)²⟩ = ⟨|∇z|²⟩/2`` (dimensionless).
    m4 : float
        Mean-square curvature of a profile, ``⟨(∂²z/∂x²)²⟩ = (3/8)⟨(∇²z)²⟩``
        (1/length²).
    """

    m0: float
    m2: float
    m4: float


def _wavevectors(n: int, length: float) -> np.ndarray:
    """:func:`roughcontact.surfaces.wavevectors`, imported on use: :mod:`roughcontact.theory`
    imports this module (through :mod:`roughcontact.greenwood_tripp`) and
    :mod:`roughcontact.surfaces` imports theory."""
    from .surfaces import wavevectors

    return wavevectors(n, length)


def _moments_from_spectrum(q: np.ndarray, power: np.ndarray) -> SpectralMoments:
    """Moments of the discrete spectrum ``power`` (``Σ power`` = variance) on wavenumbers ``q``.

    For an isotropic surface the directional moments are the angular averages
    ``m2 = ½ Σ q² P`` and ``m4 = (3/8) Σ q⁴ P`` (``⟨cos²⟩ = 1/2``,
    ``⟨cos⁴⟩ = 3/8``).
    """
    q2 = q * q
    return SpectralMoments(m0=float(power.sum()), m2=float(0.5 * (q2 * power).sum()),
                           m4=float(0.375 * (q2 * q2 * power).sum()))


def spectral_moments(heights, *, length: float) -> SpectralMoments:
    """Profile spectral moments of a periodic height map from its FFT on the grid in use.

    ``P(q) = |ĥ(q)|²`` with ``ĥ = FFT(z − mean z)/n²`` (so ``Σ P`` is the
    variance, Parseval), ``q`` the wavenumbers of
    :func:`roughcontact.surfaces.wavevectors` (the Nyquist modes of an even
    grid counted with ``|q| = π/Δ``), and the isotropic averages of
    :func:`_moments_from_spectrum`. Pass the roughness, not a rough sphere:
    the paraboloid is not periodic.
    """
    heights = np.asarray(heights, dtype=float)
    if heights.ndim != 2 or heights.shape[0] != heights.shape[1]:
        raise ValueError(f"heights must be a square 2-D array, got shape {heights.shape}")
    check_grid_size(heights.shape[0])
    check_finite_positive("length", length)
    n = heights.shape[0]
    spectrum = np.fft.fft2(heights - heights.mean()) / n**2
    return _moments_from_spectrum(_wavevectors(n, length), np.abs(spectrum) ** 2)


def self_affine_moments(hurst: float, h_rms: float, n: int, length: float) -> SpectralMoments:
    """Profile spectral moments of :func:`roughcontact.surfaces.self_affine`, exactly.

    That surface has ``|ĥ(q)|² ∝ q^(−2H−2)`` on every grid mode ``q ≠ 0``
    (random phases only) scaled to the variance ``h_rms²``, so
    ``m_k = c_k h_rms² Σ q^k q^(−2H−2) / Σ q^(−2H−2)`` over those modes,
    ``c_0 = 1``, ``c_2 = 1/2``, ``c_4 = 3/8``: a finite sum, the same for
    every seed.
    """
    check_hurst(hurst)
    check_finite_positive("h_rms", h_rms)
    check_grid_size(n)
    check_finite_positive("length", length)
    q = _wavevectors(n, length)
    power = np.zeros_like(q)
    nonzero = q > 0
    power[nonzero] = q[nonzero] ** (-2.0 * hurst - 2.0)
    return _moments_from_spectrum(q, power * (h_rms**2 / power.sum()))


@dataclasses.dataclass(frozen=True)
class AsperityParameters:
    """Greenwood–Williamson summit statistics of an isotropic Gaussian surface (McCool 1986).

    Attributes
    ----------
    density : float
        Summit density ``η = m4/(6π√3 m2)`` (1/length²).
    summit_radius : float
        Mean summit radius of curvature ``β = (3/8)√(π/m4)`` (length).
    summit_sigma : float
        Standard deviation of the summit heights ``σ_s = √(1 − 0.8968/α) √m0``
        (length): GT's ``σ``.
    summit_mean_height : float
        Mean summit height above the mean plane, ``4√m0/√(πα)`` (length).
    bandwidth : float
        Nayak's bandwidth parameter ``α = m0 m4/m2²`` (≥ 1.5).
    """

    density: float
    summit_radius: float
    summit_sigma: float
    summit_mean_height: float
    bandwidth: float


def asperity_parameters(moments: SpectralMoments) -> AsperityParameters:
    """Summit density, radius and height spread from the spectral moments (module docstring)."""
    for name in ("m0", "m2", "m4"):
        check_finite_positive(name, getattr(moments, name))
    m0, m2, m4 = moments.m0, moments.m2, moments.m4
    bandwidth = m0 * m4 / m2**2
    if bandwidth < 1.5 * (1 - 1e-12):
        raise ValueError(f"bandwidth m0 m4/m2^2 = {bandwidth:g} < 1.5: not the moments of "
                         f"an isotropic surface")
    return AsperityParameters(
        density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
        summit_radius=0.375 * math.sqrt(math.pi / m4),
        summit_sigma=math.sqrt(1.0 - 0.8968 / bandwidth) * math.sqrt(m0),
        summit_mean_height=4.0 * math.sqrt(m0) / math.sqrt(math.pi * bandwidth),
        bandwidth=bandwidth)


def mu_parameter(asperities: AsperityParameters, radius: float) -> float:
    """GT's ``μ = (8/3) η σ √(2Bβ)`` for a sphere of radius ``B = radius``."""
    check_finite_positive("radius", radius)
    return (8.0 / 3.0 * asperities.density * asperities.summit_sigma
            * math.sqrt(2.0 * radius * asperities.summit_radius))
