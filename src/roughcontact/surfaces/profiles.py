"""Random one-dimensional profiles that stand for a two-dimensional self-affine surface (MDR).

The method of dimensionality reduction replaces a random isotropic roughness of 2D spectrum
``C2D`` by a 1D profile of spectrum ``C1D(q) = π q C2D(q)`` (same H; Geike & Popov 2007). The
profiles here use the same discrete spectrum as :func:`roughcontact.surfaces.self_affine`
(the grid's modes ``q = 2πk/L``, a plateau below the roll-off, nothing above the cutoff), fixed
amplitudes and uniform random phases. ``h_rms`` is always the rms of the 2D surface represented;
the profile's own variance is ``ρ h_rms²`` (:func:`profile_variance_ratio`: ρ = 1 in the
continuum, ≈ 1.19 for H = 0.7 on the lattice without roll-off).

References
----------
T. Geike, V. L. Popov, Phys. Rev. E 76, 036710 (2007), doi 10.1103/PhysRevE.76.036710.
"""
from __future__ import annotations

import numbers

import numpy as np

from .._validate import check_finite_positive, check_grid_size, check_hurst
from .roughness import band

__all__ = ["coordinates", "iter_profile_blocks", "profile_1d", "profile_ensemble", "profile_variance_ratio"]

#: profile values generated at once (:func:`iter_profile_blocks`)
_CHUNK_CELLS = 1 << 20
_SLACK = 1e-9          # as in surfaces.self_affine: a mode within 1e-9 of q_r, q_c lies on it


def _check_spectrum(n, hurst, length, rolloff, cutoff):
    """Validated ``(q_r, q_c)`` (rules of ``surfaces.self_affine``); ``None`` if not given."""
    check_grid_size(n)
    check_hurst(hurst)
    check_finite_positive("length", length)
    return band(length, rolloff=rolloff, cutoff=cutoff, n=n)


def _shape(q, hurst, q_r, q_c):
    """``C2D(|q|)`` up to a constant: q^(−2H−2), plateau below q_r, 0 above q_c and at q = 0."""
    s = np.zeros_like(q)
    nonzero = q > 0
    s[nonzero] = q[nonzero] ** (-2.0 * hurst - 2.0)
    if q_r is not None:
        s[nonzero & (q < q_r * (1.0 - _SLACK))] = q_r ** (-2.0 * hurst - 2.0)
    if q_c is not None:
        s[q > q_c * (1.0 + _SLACK)] = 0.0
    return s


def _sum_2d(n, hurst, length, q_r, q_c):
    """``Σ s(|q|)`` over the modes of the ``n × n`` grid, in blocks of rows."""
    q1 = 2.0 * np.pi * np.fft.fftfreq(n, d=length / n)
    step = max(1, _CHUNK_CELLS // n)
    return float(sum(_shape(np.hypot(q1[i:i + step, None], q1[None, :]), hurst, q_r, q_c).sum()
                     for i in range(0, n, step)))


def profile_variance_ratio(n: int, *, hurst: float, length: float = 1.0,
                           rolloff: float | None = None, cutoff: float | None = None) -> float:
    """ρ = (rms of the 1D MDR profile / rms h of the 2D surface it represents)², dimensionless.

    Derivation. ``surfaces.self_affine`` gives every mode ``q ≠ 0`` of its
    ``n × n`` grid (spacing ``Δq = 2π/L``) the variance ``C2D(q) Δq²`` with
    ``C2D = A s(q)`` (``s``: ``q^(−2H−2)``, plateau, cutoff) and fixes ``A`` by
    ``Σ_2D C2D Δq² = h²``. The 1D profile gives each mode ``q_k = 2πk/L`` of its
    ``n`` points (``k ≠ 0``, ``−⌈n/2⌉ < k ≤ ⌊n/2⌋``) the variance
    ``C1D(q_k) Δq = π |q_k| C2D(q_k) Δq``. Hence its variance is ``ρ h²`` with

        ``ρ = π Σ_1D |q_k| s(|q_k|) / (Δq Σ_2D s(|q|))``.

    In the continuum ``∫ π|q| C2D dq = 2π ∫ q C2D dq = ∫ d²q C2D``, so ρ = 1;
    the periodic grid's lattice sums differ where few modes carry the variance.
    Without roll-off (the paper's spectrum) the lowest modes dominate and ρ ≠ 1:
    for n → ∞, ``ρ → π ζ(2H+1) / (2 ζ(H+1) β(H+1))`` (Riemann ζ, Dirichlet β;
    ``Σ_(i,j)≠0 (i²+j²)^(−s) = 4 ζ(s) β(s)``), e.g. 1.0913 (H = 0.3), 1.1914
    (H = 0.7; 1.19138 at n = 513), 1.2891 (H = 1.2). With a roll-off
    ``λ_r ≪ L`` (and ``cutoff = 2L/n``) ρ → 1 (1.001 at λ_r = L/16, n = 2048).

    ``n`` is the number of points of the profile and of grid points per side of the
    2D surface; ``hurst``, ``length``, ``rolloff``, ``cutoff`` are as in
    ``surfaces.self_affine`` (length unit). The profiles of :func:`profile_1d` have
    rms ``h_rms √ρ``.
    """
    q_r, q_c = _check_spectrum(n, hurst, length, rolloff, cutoff)
    q1 = np.abs(2.0 * np.pi * np.fft.fftfreq(n, d=length / n))
    sum_1d = (np.pi * q1 * _shape(q1, hurst, q_r, q_c)).sum()
    return float(sum_1d / (2.0 * np.pi / length * _sum_2d(n, hurst, length, q_r, q_c)))


def _amplitudes(n, hurst, h_rms, length, q_r, q_c):
    """``|c_k|`` for k = 1 … n//2 with ``|c_k|² = π q_k C2D(q_k) Δq`` (see ρ)."""
    check_finite_positive("h_rms", h_rms)
    dq = 2.0 * np.pi / length
    sum_2d = _sum_2d(n, hurst, length, q_r, q_c)
    q = dq * np.arange(1, n // 2 + 1)
    return np.sqrt(np.pi * q * h_rms**2 * _shape(q, hurst, q_r, q_c) / (dq * sum_2d))


def _draw(rng, amplitudes, n, rows):
    """``rows`` profiles: ``h_j = Σ_k c_k e^(i q_k x_j)`` with phases uniform on [0, 2π).

    One ``uniform(0, 2π)`` draw of shape ``(rows, n//2)`` per call, so consecutive
    calls continue one stream row by row. The Nyquist mode of even ``n`` must be
    real: its phase only picks the sign (+ below π), which keeps its variance.
    """
    phase = rng.uniform(0.0, 2.0 * np.pi, size=(rows, n // 2))
    coefficients = amplitudes * np.exp(1j * phase)
    if n % 2 == 0:
        coefficients[:, -1] = np.where(phase[:, -1] < np.pi, 1.0, -1.0) * amplitudes[-1]
    spectrum = np.zeros((rows, n // 2 + 1), dtype=complex)
    spectrum[:, 1:] = n * coefficients
    return np.fft.irfft(spectrum, n=n, axis=1)


def _check_int(name, value, minimum, allow_none=False):
    """Raise ``ValueError`` unless ``value`` is an integer ≥ ``minimum`` (or None if allowed)."""
    if value is None and allow_none:
        return
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}"
                         f"{' or None' if allow_none else ''}, got {value!r}")


def iter_profile_blocks(n: int, count: int, *, hurst: float, h_rms: float, length: float = 1.0,
                        seed: int | None = 0, rolloff: float | None = None, cutoff: float | None = None):
    """The rows of :func:`profile_ensemble` in consecutive blocks of at most ``2**20`` values
    (one seeded stream: the blocks stacked equal ``profile_ensemble``), for ensembles too large
    to hold at once. Arguments as in :func:`profile_ensemble`; yields ``(rows, n)`` arrays."""
    q_r, q_c = _check_spectrum(n, hurst, length, rolloff, cutoff)
    _check_int("count", count, 1)
    _check_int("seed", seed, 0, allow_none=True)
    amplitudes = _amplitudes(n, hurst, h_rms, length, q_r, q_c)
    rng = np.random.default_rng(seed)
    rows = max(1, _CHUNK_CELLS // n)
    for start in range(0, count, rows):
        yield _draw(rng, amplitudes, n, min(rows, count - start))


def profile_ensemble(n: int, count: int, *, hurst: float, h_rms: float, length: float = 1.0,
                     seed: int | None = 0, rolloff: float | None = None,
                     cutoff: float | None = None) -> np.ndarray:
    """``count`` random periodic 1D MDR profiles, row ``i`` the ``i``-th of one seeded stream.

    Each row is ``h(x_j) = Σ_k c_k exp(i q_k x_j)``, ``x_j = j L/n``, over the modes
    ``q_k = 2πk/L`` of :func:`profile_variance_ratio` with fixed amplitudes
    ``|c_k|² = C1D(q_k) Δq``, ``C1D = π q C2D`` (Geike & Popov 2007) and random
    phases (the 1D analogue of eqs. 2–3), so its spectrum is exactly
    ``∝ q^(−2H−1)`` in the self-affine band, its mean is 0 and its variance is
    exactly ``ρ h_rms²``: ``h_rms`` is the rms of the 2D surface represented.
    Row 0 equals :func:`profile_1d` with the same seed; rows do not depend on ``count``.

    ``n`` (≥ 8, odd or even) points per profile, spacing ``Δx = L/n``; ``count`` ≥ 1
    profiles; ``hurst``, ``h_rms``, ``length``, ``seed``, ``rolloff``, ``cutoff`` as in
    ``surfaces.self_affine`` (length unit), ``h_rms`` being the rms of the 2D surface
    represented. Returns ``(count, n)`` heights (length unit).
    """
    q_r, q_c = _check_spectrum(n, hurst, length, rolloff, cutoff)
    _check_int("count", count, 1)
    _check_int("seed", seed, 0, allow_none=True)
    amplitudes = _amplitudes(n, hurst, h_rms, length, q_r, q_c)
    return _draw(np.random.default_rng(seed), amplitudes, n, count)


def profile_1d(n: int, *, hurst: float, h_rms: float, length: float = 1.0,
               seed: int | None = 0, rolloff: float | None = None,
               cutoff: float | None = None) -> np.ndarray:
    """One seeded 1D MDR profile, ``C1D(q) = π q C2D(q)``: row 0 of :func:`profile_ensemble`.

    Returns ``(n,)`` heights (length unit) of mean 0 and rms ``h_rms √ρ``
    (:func:`profile_variance_ratio`), representing a 2D surface of rms ``h_rms``.
    """
    return profile_ensemble(n, 1, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                            rolloff=rolloff, cutoff=cutoff)[0]


def coordinates(n: int, length: float = 1.0) -> np.ndarray:
    """Node positions ``x_j = (j − n//2) L/n`` (length unit), ``x = 0`` at node ``n//2``."""
    check_grid_size(n)
    check_finite_positive("length", length)
    return (np.arange(n) - n // 2) * (length / n)
