"""Indenter height maps: self-affine roughness, paraboloids, rough spheres.

All maps live on an ``n × n`` grid of nodes ``x_i = i·Δ``, ``Δ = length/n``,
periodic over ``length``. Heights are the indenter's shape ``z``, measured
from the undeformed half-space towards the indenter (Pohrt & Popov 2013).
Lengths are in the caller's unit.

References
----------
R. Pohrt, V. L. Popov, "Contact Mechanics of Rough Spheres: Crossover from
Fractal to Hertzian Behavior", Adv. Tribol. 2013, 974178 (2013).
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from . import theory
from ._validate import check_finite_positive, check_hurst, check_grid_size

__all__ = [
    "wavevectors",
    "self_affine",
    "paraboloid",
    "rough_sphere",
    "equivalent_profile",
    "radial_distance",
]


def wavevectors(n: int, length: float) -> np.ndarray:
    """Magnitudes ``|q|`` (rad per length unit) of the full ``n × n`` FFT grid.

    Index order is numpy's (``scipy.fft.fftfreq``): ``q[0, 0] = 0``.
    """
    q1 = 2.0 * np.pi * np.fft.fftfreq(n, d=length / n)
    return np.hypot(q1[:, None], q1[None, :])


def _mirror(a: np.ndarray) -> np.ndarray:
    """Return ``a`` evaluated at ``-q``: ``a[(-i) mod n, (-j) mod n]``."""
    return np.roll(np.flip(a, axis=(0, 1)), shift=1, axis=(0, 1))


def self_affine(n: int, *, hurst: float, h_rms: float, length: float = 1.0,
                seed: int | None = 0) -> np.ndarray:
    """Random self-affine, statistically isotropic, periodic roughness (eqs. 1–3).

    ``h(x) = Σ_q B(q) cos(q·x + φ(q))`` with ``B ∝ √C2D(q)``,
    ``C2D(q) ∝ q^(−2H−2)`` (eq. 1) over all modes of the grid except ``q = 0``
    (no cutoff), and phases uniform on ``[0, 2π)`` with ``φ(q) = −φ(−q)``
    (eq. 3), so that the surface is real. It is then scaled so that its rms
    height is ``h_rms`` exactly.

    Parameters
    ----------
    n : int
        Grid points per side (≥ 8, odd or even).
    hurst : float
        Hurst exponent ``H``, ``0 < H < 2``.
    h_rms : float
        Root-mean-square height of the whole surface (length unit).
    length : float
        Period ``L`` (length unit).
    seed : int or None
        Seed of ``numpy.random.default_rng``: equal seeds give identical
        surfaces.

    Returns
    -------
    numpy.ndarray
        ``(n, n)`` heights with mean 0 and rms ``h_rms``.
    """
    check_grid_size(n)
    check_hurst(hurst)
    check_finite_positive("h_rms", h_rms)
    check_finite_positive("length", length)
    if seed is not None and not isinstance(seed, numbers.Integral):
        raise ValueError(f"seed must be an integer or None, got {seed!r}")
    q = wavevectors(n, length)
    amplitude = np.zeros_like(q)
    nonzero = q > 0
    amplitude[nonzero] = q[nonzero] ** (-hurst - 1.0)     # √C2D, eq. 3 up to a constant
    rng = np.random.default_rng(seed)
    phase = rng.uniform(0.0, 2.0 * np.pi, size=(n, n))
    phase = phase - _mirror(phase)                         # φ(q) = −φ(−q), still uniform mod 2π
    heights = np.fft.ifft2(amplitude * np.exp(1j * phase)).real
    heights -= heights.mean()
    return heights * (h_rms / np.sqrt(np.mean(heights**2)))


def radial_distance(n: int, length: float = 1.0) -> np.ndarray:
    """Distance ``r`` of every node from the centre node ``(n//2, n//2)``."""
    check_grid_size(n)
    check_finite_positive("length", length)
    x = (np.arange(n) - n // 2) * (length / n)
    return np.hypot(x[:, None], x[None, :])


def paraboloid(n: int, *, radius: float, length: float = 1.0) -> np.ndarray:
    """Parabolic approximation of a sphere, ``z_p = r²/(2R)`` (Sec. 2).

    The apex (``z = 0``) is the node ``(n//2, n//2)``; for odd ``n`` that is the
    exact centre of the grid.
    """
    check_finite_positive("radius", radius)
    r = radial_distance(n, length)
    return r**2 / (2.0 * radius)


def rough_sphere(n: int, *, radius: float, hurst: float, h_rms: float,
                 length: float = 1.0, seed: int | None = 0) -> np.ndarray:
    """Rough sphere ``z = z_p + z_r``: paraboloid plus self-affine roughness (Fig. 2)."""
    return paraboloid(n, radius=radius, length=length) + self_affine(
        n, hurst=hurst, h_rms=h_rms, length=length, seed=seed)


def equivalent_profile(n: int, *, radius: float, hurst: float, h_rms: float,
                       length: float = 1.0, zeta: float | None = None) -> np.ndarray:
    """Axisymmetric profile equivalent to a rough sphere (eq. 15).

    ``z_c(r) = r²/(2R) + Q3D |r|^H`` with ``Q3D`` from eq. 14. ``radius=inf``
    gives the roughness-equivalent profile ``z_s`` of eq. 6 alone.
    ``zeta`` defaults to the estimate 1.7/(H+1) (eq. 13).
    """
    check_hurst(hurst)
    if not (radius > 0):
        raise ValueError(f"radius must be > 0 (inf allowed), got {radius!r}")
    if zeta is None:
        zeta = theory.zeta_estimate(hurst)
    check_finite_positive("zeta", zeta)
    r = radial_distance(n, length)
    q3d = theory.profile_prefactor(hurst, h_rms, length, zeta)
    profile = q3d * r**hurst
    if math.isfinite(radius):
        profile = profile + r**2 / (2.0 * radius)
    return profile
