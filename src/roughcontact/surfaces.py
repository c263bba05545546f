"""Indenter height maps: self-affine roughness, bodies of revolution, rough spheres.

All maps live on an ``n × n`` grid of nodes ``x_i = i·Δ``, ``Δ = length/n``,
periodic over ``length``. Heights are the indenter's shape ``z``, measured
from the undeformed half-space towards the indenter (Pohrt & Popov 2013).
Lengths are in the caller's unit.

The generators work on blocks of rows so that their peak memory stays near the
size of the arrays they must hold (``benchmarks/memory.py``), and give the same
bytes as the whole-array formulas they replace.

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
    "body_of_revolution",
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


#: Cells per block of rows (or columns) that the generators work on at once: 2**16 cells are
#: 1 MB of complex128, so the temporaries stay small next to the ``n × n`` arrays.
_BLOCK_CELLS = 1 << 16
#: Relative slack with which a grid mode counts as lying on ``q_r`` or ``q_c``.
_SLACK = 1e-9


def _row_blocks(stop: int, n: int, start: int = 0):
    """Consecutive slices of ``max(1, _BLOCK_CELLS // n)`` indices covering ``[start, stop)``."""
    step = max(1, _BLOCK_CELLS // n)
    return [slice(i, min(i + step, stop)) for i in range(start, stop, step)]


def _band(n: int, length: float, rolloff, cutoff) -> tuple[float | None, float | None]:
    """Validated roll-off and cutoff wavenumbers ``(q_r, q_c)``; ``None`` where not given."""
    if rolloff is not None:
        check_finite_positive("rolloff", rolloff)
        if rolloff > length:
            raise ValueError(f"rolloff must be a wavelength with 0 < rolloff <= length = "
                             f"{length!r}, got {rolloff!r}")
    if cutoff is not None:
        check_finite_positive("cutoff", cutoff)
        upper = length if rolloff is None else rolloff
        if not 2.0 * length / n <= cutoff < upper:
            raise ValueError(f"cutoff must be a wavelength with 2*length/n = {2.0 * length / n!r}"
                             f" <= cutoff < {'rolloff' if rolloff is not None else 'length'}"
                             f" = {upper!r}, got {cutoff!r}")
    return (None if rolloff is None else 2.0 * np.pi / rolloff,
            None if cutoff is None else 2.0 * np.pi / cutoff)


def _amplitude(q1: np.ndarray, rows, hurst: float, q_r, q_c) -> np.ndarray:
    """``√C2D`` up to a constant on the given rows of the FFT grid (``q1``: 1-D wavenumbers)."""
    q = np.hypot(q1[rows, None], q1[None, :])
    amplitude = np.zeros_like(q)
    nonzero = q > 0
    amplitude[nonzero] = q[nonzero] ** (-hurst - 1.0)
    if q_r is not None:
        amplitude[nonzero & (q < q_r * (1.0 - _SLACK))] = q_r ** (-hurst - 1.0)
    if q_c is not None:
        amplitude[q > q_c * (1.0 + _SLACK)] = 0.0
    return amplitude


def _spectrum(n: int, length: float, hurst: float, seed, q_r, q_c) -> np.ndarray:
    """Complex spectrum ``B(q) exp(iφ(q))`` with ``φ(q) = φ₀(q) − φ₀(−q)`` (eqs. 2–3).

    ``φ₀`` is one ``(n, n)`` draw of ``uniform(0, 2π)``, taken in row blocks (the same
    stream). It is kept in the real parts of the result until the rows ``i`` and
    ``(−i) mod n`` that need it have been built, so the peak is the 16 B/cell of the result.
    """
    q1 = 2.0 * np.pi * np.fft.fftfreq(n, d=length / n)
    spectrum = np.empty((n, n), dtype=complex)
    phase = spectrum.real
    rng = np.random.default_rng(seed)
    for rows in _row_blocks(n, n):
        phase[rows] = rng.uniform(0.0, 2.0 * np.pi, size=(rows.stop - rows.start, n))
    flip = -np.arange(n) % n                               # column of −q
    for row in [0] + ([n // 2] if n % 2 == 0 else []):     # rows that are their own mirror
        own = phase[[row]]
        spectrum[[row]] = (_amplitude(q1, [row], hurst, q_r, q_c)
                           * np.exp(1j * (own - own[:, flip])))
    for block in _row_blocks((n + 1) // 2, n, start=1):    # rows i and n − i together
        rows = np.arange(block.start, block.stop)
        mirrors = n - rows
        own, other = phase[rows], phase[mirrors]
        spectrum[rows] = (_amplitude(q1, rows, hurst, q_r, q_c)
                          * np.exp(1j * (own - other[:, flip])))
        spectrum[mirrors] = (_amplitude(q1, mirrors, hurst, q_r, q_c)
                             * np.exp(1j * (other - own[:, flip])))
    return spectrum


def _ifft2_in_place(a: np.ndarray) -> None:
    """``a[:] = numpy.fft.ifft2(a)`` with the same bytes, in ``a``'s memory.

    ``ifft2`` is one 1-D transform per row, then one per column; pocketfft transforms each
    line on its own, so doing the lines block by block gives identical bytes.
    (``numpy.fft.ifft2`` ignores ``out=`` up to numpy 2.4, numpy issue 30909.)
    """
    for rows in _row_blocks(a.shape[0], a.shape[1]):
        np.fft.ifft(a[rows], axis=1, out=a[rows])
    for cols in _row_blocks(a.shape[1], a.shape[0]):
        np.fft.ifft(a[:, cols], axis=0, out=a[:, cols])


def self_affine(n: int, *, hurst: float, h_rms: float, length: float = 1.0,
                seed: int | None = 0, rolloff: float | None = None,
                cutoff: float | None = None) -> np.ndarray:
    """Random self-affine, statistically isotropic, periodic roughness (eqs. 1–3).

    ``h(x) = Σ_q B(q) cos(q·x + φ(q))`` with ``B ∝ √C2D(q)`` and phases uniform on
    ``[0, 2π)`` with ``φ(q) = −φ(−q)`` (eq. 3), so that the surface is real. The spectrum is

    * ``C2D(q) = C2D(q_r)`` (a plateau) for ``0 < |q| < q_r = 2π/rolloff``,
    * ``C2D(q) ∝ |q|^(−2H−2)`` (eq. 1) for ``q_r ≤ |q| ≤ q_c = 2π/cutoff``,
    * ``C2D(q) = 0`` for ``|q| > q_c`` and at ``q = 0``.

    The mode on ``q_c`` itself is kept, and a mode within a relative ``1e-9`` of
    ``q_r`` or ``q_c`` counts as lying on it (round-off of the grid's wavenumbers). The
    amplitude is continuous at ``q_r``. The surface is then scaled so that its rms height
    is ``h_rms`` exactly. The defaults (no roll-off, no cutoff: all grid modes but
    ``q = 0``, as in the paper) give the same bytes for every seed as before the roll-off
    and cutoff existed.

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
    rolloff : float, optional
        Roll-off wavelength ``λ_r = 2π/q_r`` (length unit), ``0 < λ_r ≤ L``;
        ``None`` (default) is ``L``: no plateau.
    cutoff : float, optional
        Short-wavelength cutoff ``λ_c = 2π/q_c`` (length unit), ``2L/n ≤ λ_c < λ_r``
        (at least two cells, and a non-empty self-affine band); ``None`` (default)
        keeps every mode of the grid. ``λ_c = 2L/n`` puts ``q_c`` on the Nyquist
        wavenumber and still drops the grid's corners ``|q| > q_c``.

    Returns
    -------
    numpy.ndarray
        ``(n, n)`` heights with mean 0 and rms ``h_rms``.

    Notes
    -----
    Peak memory is about 24 B per grid cell (the complex spectrum, transformed in place,
    plus the result), against 73 B before (``benchmarks/memory.py``).
    """
    check_grid_size(n)
    check_hurst(hurst)
    check_finite_positive("h_rms", h_rms)
    check_finite_positive("length", length)
    if seed is not None and not isinstance(seed, numbers.Integral):
        raise ValueError(f"seed must be an integer or None, got {seed!r}")
    q_r, q_c = _band(n, length, rolloff, cutoff)
    spectrum = _spectrum(n, length, hurst, seed, q_r, q_c)
    _ifft2_in_place(spectrum)
    heights = spectrum.real
    heights -= heights.mean()
    return heights * (h_rms / np.sqrt(np.mean(heights**2)))


def _coordinates(n: int, length: float) -> np.ndarray:
    """Node coordinates ``x_i − x_(n//2)`` along one side."""
    return (np.arange(n) - n // 2) * (length / n)


def _body(r, radius: float, exponent: float):
    """``z = (R/m)(r/R)^m``, evaluated as ``r^m/(m R^(m−1))`` (``r²/(2R)`` for ``m = 2``)."""
    return r**exponent / (exponent * radius ** (exponent - 1.0))


def radial_distance(n: int, length: float = 1.0) -> np.ndarray:
    """Distance ``r`` of every node from the centre node ``(n//2, n//2)``."""
    check_grid_size(n)
    check_finite_positive("length", length)
    x = _coordinates(n, length)
    return np.hypot(x[:, None], x[None, :])


def body_of_revolution(n: int, *, radius: float, exponent: float,
                       length: float = 1.0) -> np.ndarray:
    """Smooth body of revolution ``z = (R/m)(r/R)^m = Q r^m``, ``Q = R^(1−m)/m``.

    The profile of eq. 6 with ``H`` replaced by ``m`` and ``Q3D = Q`` (the paper's
    Conclusions: "arbitrary bodies of revolution"). ``m = 2`` is the paraboloid
    ``r²/(2R)`` of Sec. 2 (same bytes as :func:`paraboloid`), ``m = 1`` a cone of slope 1;
    ``R`` is the radius of curvature of the apex for ``m = 2`` and a length scale
    otherwise. ``r`` is measured from the node ``(n//2, n//2)``, the exact centre of the
    grid for odd ``n``.

    Parameters
    ----------
    n : int
        Grid points per side (≥ 8).
    radius : float
        ``R`` (length unit), finite and > 0.
    exponent : float
        ``m``, finite and > 0.
    length : float
        Side ``L`` of the grid (length unit).

    Returns
    -------
    numpy.ndarray
        ``(n, n)`` heights (length unit), 0 at the apex.
    """
    check_grid_size(n)
    check_finite_positive("radius", radius)
    check_finite_positive("exponent", exponent)
    check_finite_positive("length", length)
    x = _coordinates(n, length)
    heights = np.empty((n, n))
    for rows in _row_blocks(n, n):
        heights[rows] = _body(np.hypot(x[rows, None], x[None, :]), radius, exponent)
    return heights


def paraboloid(n: int, *, radius: float, length: float = 1.0) -> np.ndarray:
    """Parabolic approximation of a sphere, ``z_p = r²/(2R)`` (Sec. 2).

    :func:`body_of_revolution` with ``m = 2``. The apex (``z = 0``) is the node
    ``(n//2, n//2)``; for odd ``n`` that is the exact centre of the grid.
    """
    check_finite_positive("radius", radius)
    return body_of_revolution(n, radius=radius, exponent=2.0, length=length)


def rough_sphere(n: int, *, radius: float, hurst: float, h_rms: float,
                 length: float = 1.0, seed: int | None = 0, exponent: float = 2.0,
                 rolloff: float | None = None, cutoff: float | None = None) -> np.ndarray:
    """Rough sphere ``z = z_p + z_r``: paraboloid plus self-affine roughness (Fig. 2).

    ``z_p`` is :func:`body_of_revolution` with ``exponent`` (default 2: the paraboloid),
    ``z_r`` is :func:`self_affine` with the other arguments; the body is added in place,
    row block by row block, so the peak memory is that of :func:`self_affine`. The
    defaults give the same bytes as before ``exponent``, ``rolloff`` and ``cutoff`` existed.
    """
    check_finite_positive("radius", radius)
    check_finite_positive("exponent", exponent)
    heights = self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                          rolloff=rolloff, cutoff=cutoff)
    x = _coordinates(n, length)
    for rows in _row_blocks(n, n):
        heights[rows] += _body(np.hypot(x[rows, None], x[None, :]), radius, exponent)
    return heights


def equivalent_profile(n: int, *, radius: float, hurst: float, h_rms: float,
                       length: float = 1.0, zeta: float | None = None,
                       exponent: float = 2.0) -> np.ndarray:
    """Axisymmetric profile equivalent to a rough sphere (eq. 15).

    ``z_c(r) = r²/(2R) + Q3D |r|^H`` with ``Q3D`` from eq. 14; with ``exponent = m``
    the body term is that of :func:`body_of_revolution`, ``(R/m)(r/R)^m``.
    ``radius=inf`` gives the roughness-equivalent profile ``z_s`` of eq. 6 alone.
    ``zeta`` defaults to the estimate 1.7/(H+1) (eq. 13).
    """
    check_hurst(hurst)
    if not (radius > 0):
        raise ValueError(f"radius must be > 0 (inf allowed), got {radius!r}")
    check_finite_positive("exponent", exponent)
    if zeta is None:
        zeta = theory.zeta_estimate(hurst)
    check_finite_positive("zeta", zeta)
    r = radial_distance(n, length)
    q3d = theory.profile_prefactor(hurst, h_rms, length, zeta)
    profile = q3d * r**hurst
    if math.isfinite(radius):
        profile = profile + _body(r, radius, exponent)
    return profile
