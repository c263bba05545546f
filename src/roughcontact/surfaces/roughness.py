"""Self-affine random roughness on a periodic grid (the paper's eqs. 1–3).

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

import numbers

import numpy as np

from .._validate import check_finite_positive, check_grid_size, check_hurst

__all__ = ["wavevectors", "band", "self_affine", "row_blocks"]



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


def row_blocks(stop: int, n: int, start: int = 0):
    """Consecutive slices of ``max(1, _BLOCK_CELLS // n)`` indices covering ``[start, stop)``."""
    step = max(1, _BLOCK_CELLS // n)
    return [slice(i, min(i + step, stop)) for i in range(start, stop, step)]


def band(length: float, *, rolloff=None, cutoff=None, n: int | None = None) -> tuple[float | None, float | None]:
    """Validated roll-off and cutoff wavelengths as wavenumbers ``(q_r, q_c) = (2π/λ_r, 2π/λ_c)``.

    ``0 < rolloff ≤ length`` and ``2·length/n ≤ cutoff < rolloff`` (else ``< length``; without
    ``n`` the lower bound is 0); ``None`` where not given. The one check of every function
    that takes a roll-off or a cutoff.
    """
    if rolloff is not None:
        check_finite_positive("rolloff", rolloff)
        if rolloff > length:
            raise ValueError(f"rolloff must be a wavelength with 0 < rolloff <= length = "
                             f"{length!r}, got {rolloff!r}")
    if cutoff is not None:
        check_finite_positive("cutoff", cutoff)
        upper = length if rolloff is None else rolloff
        lower, lower_name = (0.0, "0") if n is None else (2.0 * length / n, "2*length/n")
        if not lower <= cutoff < upper:
            raise ValueError(f"cutoff must be a wavelength with {lower_name} = {lower!r}"
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
    for rows in row_blocks(n, n):
        phase[rows] = rng.uniform(0.0, 2.0 * np.pi, size=(rows.stop - rows.start, n))
    flip = -np.arange(n) % n                               # column of −q
    for row in [0] + ([n // 2] if n % 2 == 0 else []):     # rows that are their own mirror
        own = phase[[row]]
        spectrum[[row]] = (_amplitude(q1, [row], hurst, q_r, q_c)
                           * np.exp(1j * (own - own[:, flip])))
    for block in row_blocks((n + 1) // 2, n, start=1):    # rows i and n − i together
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
    for rows in row_blocks(a.shape[0], a.shape[1]):
        np.fft.ifft(a[rows], axis=1, out=a[rows])
    for cols in row_blocks(a.shape[1], a.shape[0]):
        np.fft.ifft(a[:, cols], axis=0, out=a[:, cols])


def self_affine(n: int, *, hurst: float, h_rms: float, length: float = 1.0,
                seed: int | None = 0, rolloff: float | None = None,
                cutoff: float | None = None, realization_of: int | None = None) -> np.ndarray:
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
    realization_of : int, optional
        The grid ``N ≥ n`` whose realisation to return, seen on this ``n × n`` grid: the surface
        of ``self_affine(N, ...)`` (same seed, spectrum and rms ``h_rms`` over ``N × N``)
        low-passed to the modes ``|k_x|, |k_y| < n/2`` and sampled at this grid's nodes, so that
        coarser grids carry the same physical surface (a grid-convergence study of one
        ensemble). ``None`` (default): ``N = n``, the surface of this grid itself. Its rms is
        ``h_rms`` less the power of the dropped modes.

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
    if realization_of is not None and realization_of != n:
        return _coarsened(n, realization_of, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                          rolloff=rolloff, cutoff=cutoff)
    q_r, q_c = band(length, rolloff=rolloff, cutoff=cutoff, n=n)
    spectrum = _spectrum(n, length, hurst, seed, q_r, q_c)
    _ifft2_in_place(spectrum)
    heights = spectrum.real
    heights -= heights.mean()
    return heights * (h_rms / np.sqrt(np.mean(heights**2)))


def _coarsened(n: int, fine: int, *, hurst, h_rms, length, seed, rolloff, cutoff) -> np.ndarray:
    """:func:`self_affine` ``(fine, ...)`` low-passed to ``|k| < n/2`` per direction and sampled on
    the ``n × n`` grid (``realization_of``).

    The fine heights are ``h = c · ifft2(S)`` with ``c = h_rms / rms(ifft2(S))``; by Parseval
    ``rms² = Σ|S|²/N⁴`` (``S(0) = 0``), so ``c`` needs no fine transform. A mode ``k`` of the
    fine grid is ``S(k) e^{2πi k·j/N}/N²`` at node ``j``; at the coarse node ``x = jL/n`` it is
    ``S(k) e^{2πi k·j/n}/N²``, i.e. the coarse grid's own ``ifft2`` of ``S(k) n²/N²``.
    """
    check_grid_size(fine)
    if fine < n:
        raise ValueError(f"realization_of must be a grid of at least n = {n} points, got {fine!r}")
    q_r, q_c = band(length, rolloff=rolloff, cutoff=cutoff, n=n)
    spectrum = _spectrum(fine, length, hurst, seed, q_r, q_c)
    scale = h_rms / np.sqrt(np.sum(np.abs(spectrum) ** 2) / float(fine) ** 4)
    keep = np.arange(-((n - 1) // 2), (n - 1) // 2 + 1)     # |k| < n/2: an even grid's Nyquist mode dropped
    coarse = np.zeros((n, n), dtype=complex)
    coarse[np.ix_(keep % n, keep % n)] = spectrum[np.ix_(keep % fine, keep % fine)] * (n / fine) ** 2 * scale
    return np.fft.ifft2(coarse).real
