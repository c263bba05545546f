"""Tangential influence operators: surface displacements ``u_x`` (and ``u_y``) from tangential tractions.

Cerruti's solution (Johnson 1985, eq. 2.19; §3.8 for distributed tractions): a tangential point
force ``Q`` in ``x`` on the surface of a half-space of shear modulus ``G`` and Poisson ratio ``ν``
displaces the surface by

    u_x = Q/(2πG) · [(1 − ν)/ρ + ν x²/ρ³],
    u_y = Q/(2πG) · ν x y/ρ³,
    u_z = −Q(1 − 2ν)/(4πG) · x/ρ².

Components: :class:`FreeTangentialOperator` and :class:`PeriodicTangentialOperator` give ``u_x``
from ``q_x`` alone (``q_y = 0`` and ``u_y`` left free: the one-component simplification of
Cattaneo–Mindlin and of the rough-surface BEM of Grzemba et al. 2014); :class:`FreeCerrutiPair`
and :class:`PeriodicCerrutiPair` give ``(u_x, u_y)`` from ``(q_x, q_y)``, the full tangential block
with the cross kernel ``ν/(1 − ν) · xy/ρ³`` (:func:`cerruti_cross_coefficients`). Stated
simplification: the normal–tangential coupling ``u_z(q)`` (and ``u_x(p)``) is neglected: exact for
elastically similar bodies and for ``ν = 1/2``, the assumption of Mindlin, Cattaneo,
Ciavarella–Jäger and the MDR.

Moduli: the package works in ``E*``. For a rigid indenter on an elastic half-space
``E* = E/(1 − ν²)`` and ``G = E/(2(1 + ν))``, so ``G = E*(1 − ν)/2`` and
``1/(2πG) = 1/(π E* (1 − ν))``.

``x`` is the grid's first axis (``heights[i, j]``: ``i`` along ``x``). Traction is piecewise
constant on the square cells (side ``Δ``), displacements are taken at the cell centres, as for
the normal operators of :mod:`roughcontact.bem.operators`:

* :class:`FreeTangentialOperator` — non-periodic half-space: the cell integral of Cerruti's
  ``u_x`` in closed form (:func:`cerruti_coefficients`), convolved by zero-padded FFT;
* :class:`PeriodicTangentialOperator` — periodic over ``length``:
  ``ũ_x(q) = 2 (1 − ν q_x²/|q|²) q̃_x(q) / (E* (1 − ν) |q|)``, ``ũ_x(0) = 0`` (the Fourier
  transform of Cerruti's ``u_x``; Johnson 1985, §2.2; e.g. Campañá, Persson & Müser,
  J. Phys.: Condens. Matter 23, 085001 (2011), doi:10.1088/0953-8984/23/8/085001); its pair
  ``ũ_i = 2 (δ_ij − ν q_i q_j/|q|²) q̃_j / (E* (1 − ν) |q|)``. As the normal periodic operator (and
  tamaas), this samples the continuum spectrum: its near field differs from the cell integral of
  the free operators, most for the odd cross kernel (at offset (1, 1) by half), while smooth
  tractions give the same displacements (tests/test_tangential_kernel.py).

At ``ν = 0`` both equal the normal operators of the same ``E*``.
"""

from __future__ import annotations

import collections
import functools

import numpy as np
import scipy.fft

from .operators import FreeSpaceOperator, PeriodicOperator, _gather, love_coefficients
from .padding import PaddedWindow, padded_size

__all__ = ["shear_modulus", "cerruti_coefficients", "cerruti_cross_coefficients", "FreeTangentialOperator",
           "PeriodicTangentialOperator", "tangential_operator_for", "FreeCerrutiPair", "PeriodicCerrutiPair",
           "cerruti_pair_for"]


def shear_modulus(e_star: float, poisson: float) -> float:
    """``G = E*(1 − ν)/2`` of an elastic half-space under a rigid indenter (force/length²).

    From ``E* = E/(1 − ν²)`` and ``G = E/(2(1 + ν))`` (Johnson 1985, §3.8 and eq. 4.22).
    """
    return 0.5 * e_star * (1.0 - poisson)


def cerruti_coefficients(n: int, poisson: float) -> np.ndarray:
    """Dimensionless ``u_x`` at offset ``(i, j)`` cells (``i`` along ``x``) from a cell under ``q_x``.

    ``u_x = c[|i|, |j|] · q Δ/(π E*)`` for a uniform tangential traction ``q`` on one square cell
    of side ``Δ``: the cell integral of Cerruti's ``u_x`` (module docstring),

    ``c = c_Love + ν/(1 − ν) · Σ_corners ± Y asinh(X/|Y|)``,

    ``X = i ± 1/2`` (along ``x``), ``Y = j ± 1/2``, corners signed as in
    :func:`~roughcontact.bem.operators.love_coefficients` (whose ``c_Love`` integrates ``1/ρ``);
    ``Y asinh(X/|Y|)`` integrates ``x²/ρ³`` (``∂²/∂x∂y [y ln(x + ρ)] = x²/ρ³``, the ``y ln|y|``
    terms cancel between corners). Self-coefficient ``c[0, 0] = 4 ln(1 + √2) (1 + ν/(2(1 − ν)))``.
    """
    offset = np.arange(n, dtype=float)
    x = offset[:, None]
    y = offset[None, :]

    def corner(cx, cy):
        return cy * np.arcsinh(cx / np.abs(cy))

    along = (corner(x + 0.5, y + 0.5) - corner(x + 0.5, y - 0.5)
             - corner(x - 0.5, y + 0.5) + corner(x - 0.5, y - 0.5))
    return love_coefficients(n) + (poisson / (1.0 - poisson)) * along


def cerruti_cross_coefficients(n: int, poisson: float) -> np.ndarray:
    """Dimensionless ``u_y`` at offset ``(i, j) ≥ 0`` cells from a cell under ``q_x`` (and ``u_x``
    under ``q_y``, by reciprocity).

    ``u_y = sign(i) sign(j) c[|i|, |j|] · q Δ/(π E*)``: the cell integral of Cerruti's
    ``ν/(1 − ν) · x y/ρ³`` (module docstring, with ``1/(2πG) = 1/(πE*(1 − ν))``), whose
    antiderivative is ``−ρ`` (``∂²ρ/∂x∂y = −xy/ρ³``): ``c = −ν/(1 − ν) Σ_corners ± ρ(X, Y)``,
    corners as in :func:`cerruti_coefficients`. Odd in ``x`` and in ``y``: 0 on both axes.
    """
    offset = np.arange(n, dtype=float)
    x = offset[:, None]
    y = offset[None, :]
    corners = (np.hypot(x + 0.5, y + 0.5) - np.hypot(x + 0.5, y - 0.5)
               - np.hypot(x - 0.5, y + 0.5) + np.hypot(x - 0.5, y - 0.5))
    return -(poisson / (1.0 - poisson)) * corners


class FreeTangentialOperator(FreeSpaceOperator):
    """Non-periodic half-space, ``u_x`` from ``q_x`` on an ``n × n`` grid (DC-FFT).

    Parameters
    ----------
    n : int
        Cells per side.
    length : float
        Side length of the grid (length unit).
    e_star : float
        Effective modulus ``E*`` (pressure unit).
    poisson : float
        Poisson ratio ``ν`` of the half-space, ``−1 < ν ≤ 1/2``.

    Notes
    -----
    The kernel is even in ``x`` and in ``y`` separately, so the tables, windows and cached
    spectra of :class:`~roughcontact.bem.operators.FreeSpaceOperator` serve it unchanged.
    """

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.poisson = float(poisson)
        super().__init__(n, length, e_star)

    def _unit_table(self, side: int) -> np.ndarray:
        return cerruti_coefficients(side, self.poisson) * (self.spacing / (np.pi * self.e_star))


class PeriodicTangentialOperator(PeriodicOperator):
    """Half-space periodic over ``length``, ``u_x`` from ``q_x`` on an ``n × n`` grid.

    ``ũ_x(q) = 2 (1 − ν q_x²/|q|²) q̃_x / (E* (1 − ν) |q|)`` for ``q ≠ 0``; ``ũ_x(0) = 0``
    (zero-mean displacement). Parameters as :class:`FreeTangentialOperator`.
    """

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self.poisson = float(poisson)
        qx = 2.0 * np.pi * scipy.fft.fftfreq(n, d=self.spacing)
        qy = 2.0 * np.pi * scipy.fft.rfftfreq(n, d=self.spacing)
        q2 = qx[:, None] ** 2 + qy[None, :] ** 2
        q2[0, 0] = 1.0
        shape = 1.0 - self.poisson * qx[:, None] ** 2 / q2
        q = np.sqrt(q2)
        q[0, 0] = np.inf
        self.spectrum = 2.0 * shape / (e_star * (1.0 - self.poisson) * q)
        self.self_coefficient = float(self._kernel[0, 0])


@functools.lru_cache(maxsize=8)
def tangential_operator_for(n: int, length: float, e_star: float, poisson: float, periodic: bool):
    """Shared, cached tangential operator for a grid (kernel spectra are reused across solves)."""
    cls = PeriodicTangentialOperator if periodic else FreeTangentialOperator
    return cls(n, length, e_star, poisson)


class FreeCerrutiPair:
    """Non-periodic half-space, both components: ``(u_x, u_y)`` from ``(q_x, q_y)`` (DC-FFT).

    The full tangential block of Cerruti's solution: ``K_xx`` (:func:`cerruti_coefficients`),
    ``K_yy`` its transpose in ``(i, j)``, and ``K_xy = K_yx`` (:func:`cerruti_cross_coefficients`,
    odd in ``x`` and ``y``). Parameters as :class:`FreeTangentialOperator`; :meth:`window_size`
    is its own. Spectra are cached per padded shape (three per shape).
    """

    periodic = False
    cached_spectra = 6

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self.poisson = float(poisson)
        self.along = FreeTangentialOperator(n, length, e_star, poisson)
        self.self_coefficient = self.along.self_coefficient
        self._side = 0
        self._spectra: collections.OrderedDict = collections.OrderedDict()

    def window_size(self, cells: int) -> int:
        """As :meth:`~roughcontact.bem.operators.FreeSpaceOperator.window_size`."""
        return self.along.window_size(cells)

    def _tables(self, size: int) -> tuple[np.ndarray, np.ndarray]:
        """``K_xx`` and ``K_xy`` at offsets ``[0, size)²`` at least (grown on demand, as the normal
        operator's table)."""
        if self._side < size:
            self._side = min(self.n, max(size, (3 * self._side) // 2, 64))
            scale = self.spacing / (np.pi * self.e_star)
            self._xx = cerruti_coefficients(self._side, self.poisson) * scale
            self._xy = cerruti_cross_coefficients(self._side, self.poisson) * scale
        return self._xx, self._xy

    def _spectrum(self, shape):
        padded = padded_size(shape)
        spectra = self._spectra.get(padded)
        if spectra is None:
            w = PaddedWindow.of(padded, self.n)
            xx, xy = self._tables(w.side)
            kernels = (xx[w.rows, w.cols] * w.mask, xx[w.cols, w.rows] * w.mask,
                       xy[w.rows, w.cols] * (w.signs[0][:, None] * w.signs[1][None, :]))
            spectra = self._spectra[padded] = tuple(scipy.fft.rfft2(k) for k in kernels)
            if len(self._spectra) > self.cached_spectra:
                self._spectra.popitem(last=False)
        else:
            self._spectra.move_to_end(padded)
        return padded, spectra

    def __call__(self, qx: np.ndarray, qy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(u_x, u_y)`` on the cells of a window (``m1 × m2``) under tractions on it alone."""
        (p0, p1), (sxx, syy, sxy) = self._spectrum(qx.shape)
        m1, m2 = qx.shape

        def forward(field):
            return scipy.fft.fft(scipy.fft.rfft(field, n=p1, axis=1), n=p0, axis=0, overwrite_x=True)

        def inverse(transform):
            transform = scipy.fft.ifft(transform, axis=0, overwrite_x=True)
            return scipy.fft.irfft(transform[:m1], n=p1, axis=1)[:, :m2]

        fx, fy = forward(qx), forward(qy)
        return inverse(sxx * fx + sxy * fy), inverse(sxy * fx + syy * fy)

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """Dense ``2m × 2m`` block matrix ``[[K_xx, K_xy], [K_xy, K_yy]]`` on the cells
        ``(rows[a], cols[a])`` (tractions and displacements stacked ``x`` then ``y``)."""
        rows, cols = np.asarray(rows, dtype=np.intp), np.asarray(cols, dtype=np.intp)
        m = rows.size
        reach = max([int(a.max() - a.min()) for a in (rows, cols) if a.size], default=0)
        xx, xy = self._tables(1 + reach)
        side = xx.shape[1]

        def offset(di, dj):
            return np.abs(di, out=di) * side + np.abs(dj, out=dj)

        matrix = np.empty((2 * m, 2 * m))
        matrix[:m, :m] = _gather(xx, rows, cols, None, None, offset, None)
        matrix[m:, m:] = _gather(xx, cols, rows, None, None, offset, None)
        cross = _gather(xy, rows, cols, None, None, offset, None)
        cross *= np.sign(np.subtract.outer(rows, rows))
        cross *= np.sign(np.subtract.outer(cols, cols))
        matrix[:m, m:] = cross
        matrix[m:, :m] = cross
        return matrix


class PeriodicCerrutiPair:
    """Half-space periodic over ``length``, both components: ``(u_x, u_y)`` from ``(q_x, q_y)``.

    ``ũ_i = 2 (δ_ij − ν k_i k_j/k²) q̃_j / (E* (1 − ν) k)`` for ``k ≠ 0``, 0 at ``k = 0``
    (the Fourier transform of Cerruti's solution; ``K_xx`` is
    :class:`PeriodicTangentialOperator`'s). On an even grid the Nyquist row and column of the odd
    ``K_xy`` are 0, as for any odd lattice kernel. Parameters as :class:`FreeTangentialOperator`.
    """

    periodic = True

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self.poisson = float(poisson)
        kx = 2.0 * np.pi * scipy.fft.fftfreq(n, d=self.spacing)[:, None]
        ky = 2.0 * np.pi * scipy.fft.rfftfreq(n, d=self.spacing)[None, :]
        k2 = kx**2 + ky**2
        k2[0, 0] = 1.0
        base = 2.0 / (e_star * (1.0 - self.poisson) * np.sqrt(k2))
        base[0, 0] = 0.0
        cross = -base * self.poisson * kx * ky / k2
        if n % 2 == 0:
            cross[n // 2, :] = 0.0
            cross[:, -1] = 0.0
        self.spectra = (base * (1.0 - self.poisson * kx**2 / k2), base * (1.0 - self.poisson * ky**2 / k2),
                        cross)
        self.self_coefficient = float(self._kernels[0][0, 0])

    @functools.cached_property
    def _kernels(self) -> tuple[np.ndarray, ...]:
        """``K_xx``, ``K_yy``, ``K_xy`` of a unit traction on cell (0, 0), over the grid."""
        return tuple(scipy.fft.irfft2(s, s=(self.n, self.n)) for s in self.spectra)

    def window_size(self, cells: int) -> int:
        return self.n

    def __call__(self, qx: np.ndarray, qy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Zero-mean ``(u_x, u_y)`` over the grid."""
        sxx, syy, sxy = self.spectra
        fx, fy = scipy.fft.rfft2(qx), scipy.fft.rfft2(qy)
        shape = (self.n, self.n)
        return (scipy.fft.irfft2(sxx * fx + sxy * fy, s=shape, overwrite_x=True),
                scipy.fft.irfft2(sxy * fx + syy * fy, s=shape, overwrite_x=True))

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """Dense ``2m × 2m`` block matrix as :meth:`FreeCerrutiPair.influence_matrix`, offsets
        modulo ``n``."""
        n, m = self.n, len(rows)

        def offset(di, dj):
            return np.remainder(di, n, out=di) * n + np.remainder(dj, n, out=dj)

        matrix = np.empty((2 * m, 2 * m))
        for (a, b), kernel in zip(((slice(None, m), slice(None, m)), (slice(m, None), slice(m, None)),
                                   (slice(None, m), slice(m, None))), self._kernels):
            matrix[a, b] = _gather(kernel, rows, cols, None, None, offset, None)
        matrix[m:, :m] = matrix[:m, m:].T
        return matrix


@functools.lru_cache(maxsize=8)
def cerruti_pair_for(n: int, length: float, e_star: float, poisson: float, periodic: bool):
    """Shared, cached two-component operator for a grid."""
    cls = PeriodicCerrutiPair if periodic else FreeCerrutiPair
    return cls(n, length, e_star, poisson)
