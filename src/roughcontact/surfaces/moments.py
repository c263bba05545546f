"""Spectral moments of an isotropic surface: height variance, profile slope and curvature.

The profile moments ``m0, m2, m4`` (Nayak, J. Lubr. Technol. 93, 398 (1971),
doi 10.1115/1.3451608) of a periodic height map, or exactly those of
:func:`roughcontact.surfaces.self_affine`, from the power on the grid's own modes. They feed
the summit statistics of :mod:`roughcontact.models.asperities`.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from .._validate import check_finite_positive, check_grid_size, check_hurst
from .roughness import wavevectors

__all__ = ["SpectralMoments", "self_affine_moments", "spectral_moments"]


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
    return _moments_from_spectrum(wavevectors(n, length), np.abs(spectrum) ** 2)


def self_affine_moments(hurst: float, *, h_rms: float, n: int, length: float) -> SpectralMoments:
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
    q = wavevectors(n, length)
    power = np.zeros_like(q)
    nonzero = q > 0
    power[nonzero] = q[nonzero] ** (-2.0 * hurst - 2.0)
    return _moments_from_spectrum(q, power * (h_rms**2 / power.sum()))
