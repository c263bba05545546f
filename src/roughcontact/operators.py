"""Elastic half-space influence operators: surface displacement from pressure.

Pressure is piecewise constant on the square cells (side ``Δ = length/n``) of an
``n × n`` grid; displacements are taken at the cell centres and are positive
into the half-space. ``E*`` is the effective modulus, ``1/E* = (1−ν²)/E`` for a
rigid indenter.

* :class:`FreeSpaceOperator` — non-periodic half-space: Love's closed-form
  displacement of a uniformly loaded rectangle (Love 1929; Johnson 1985,
  eq. 3.25) convolved with a zero-padded FFT (DC-FFT: Liu, Wang & Liu,
  Wear 243, 101 (2000)). Any rectangular window of the grid can be convolved
  on its own padded size, with results identical to the full grid for
  pressures that vanish outside the window.
* :class:`PeriodicOperator` — half-space periodic over ``length``:
  ``ũ(q) = 2 p̃(q)/(E* |q|)`` for ``q ≠ 0`` and ``ũ(0) = 0`` (the mean
  displacement of a periodic half-space is not defined; depths are then
  measured against the mean plane).
"""

from __future__ import annotations

import collections
import functools

import numpy as np
import scipy.fft

__all__ = ["love_coefficients", "FreeSpaceOperator", "PeriodicOperator", "DenseOperator", "operator_for"]


def love_coefficients(n: int) -> np.ndarray:
    """Dimensionless displacement ``c[i, j]`` at offset ``(i, j)`` cells from a loaded cell.

    ``u = c[|i|, |j|] · p Δ/(π E*)`` for a uniform pressure ``p`` on one square
    cell of side ``Δ``. With cell-unit coordinates and the half-width 1/2,

    ``c = Σ_corners ± [X asinh(Y/|X|) + Y asinh(X/|Y|)]``,
    ``X = i ± 1/2``, ``Y = j ± 1/2`` (Johnson 1985, eq. 3.25, with the
    ``X ln|X|`` terms cancelled between corners). ``X`` and ``Y`` are never 0.
    Self-coefficient: ``c[0, 0] = 4 ln(1 + √2)``.
    """
    offset = np.arange(n, dtype=float)
    x = offset[:, None]
    y = offset[None, :]

    def corner(cx, cy):
        return cx * np.arcsinh(cy / np.abs(cx)) + cy * np.arcsinh(cx / np.abs(cy))

    return (corner(x + 0.5, y + 0.5) - corner(x + 0.5, y - 0.5)
            - corner(x - 0.5, y + 0.5) + corner(x - 0.5, y - 0.5))


class FreeSpaceOperator:
    """Non-periodic elastic half-space on an ``n × n`` grid (DC-FFT).

    Parameters
    ----------
    n : int
        Cells per side.
    length : float
        Side length of the grid (length unit); cell size ``Δ = length/n``.
    e_star : float
        Effective modulus (pressure unit).

    Notes
    -----
    Kernel spectra are cached per padded shape. For a window of ``m`` cells the
    padded size is ``M = next_fast_len(2m − 1)``; :meth:`window_size` returns the
    largest window that fits the same ``M``.
    """

    periodic = False
    #: Kernel spectra kept (least recently used dropped first): a load path
    #: only grows its window, so old sizes are rarely needed again.
    cached_spectra = 6

    def __init__(self, n: int, length: float, e_star: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self.coefficients = love_coefficients(n) * (self.spacing / (np.pi * e_star))
        self.self_coefficient = self.coefficients[0, 0]
        self._spectra: collections.OrderedDict[tuple[int, int], np.ndarray] = \
            collections.OrderedDict()
        self._symmetric: np.ndarray | None = None

    def window_size(self, cells: int) -> int:
        """Largest window ≥ ``cells`` (≤ n) convolved with the same padded FFT size."""
        cells = min(max(int(cells), 1), self.n)
        padded = scipy.fft.next_fast_len(2 * cells - 1, real=True)
        return min((padded + 1) // 2, self.n)

    def _spectrum(self, shape: tuple[int, int]) -> tuple[tuple[int, int], np.ndarray]:
        padded = tuple(scipy.fft.next_fast_len(2 * m - 1, real=True) for m in shape)
        spectrum = self._spectra.get(padded)
        if spectrum is None:
            index = [np.arange(size) for size in padded]
            used = [(idx < m) | (idx > size - m) for idx, m, size in zip(index, shape, padded)]
            offsets = [np.where(idx < m, idx, np.where(use, size - idx, 0))
                       for idx, m, size, use in zip(index, shape, padded, used)]
            kernel = self.coefficients[offsets[0][:, None], offsets[1][None, :]]
            kernel = kernel * (used[0][:, None] & used[1][None, :])
            spectrum = scipy.fft.rfft2(kernel)
            self._spectra[padded] = spectrum
            if len(self._spectra) > self.cached_spectra:
                self._spectra.popitem(last=False)
        else:
            self._spectra.move_to_end(padded)
        return padded, spectrum

    def _kernel(self, half: int) -> np.ndarray:
        """Symmetric influence array for windows of up to ``half`` cells a side:
        ``[half−1+i, half−1+j]`` holds the coefficient at offset (i, j), ``|i|, |j| < half``.

        Kept for the largest window seen, so its memory follows the window, not
        the grid: ``(2 half − 1)²`` values instead of ``(2n − 1)²``.
        """
        if self._symmetric is None or (self._symmetric.shape[0] + 1) // 2 < half:
            index = np.abs(np.arange(-(half - 1), half))
            self._symmetric = self.coefficients[index[:, None], index[None, :]]
        return self._symmetric

    def column_limit(self, shape: tuple[int, int]) -> int:
        """How many columns :meth:`add_columns` sums in about the time of one FFT convolution."""
        padded = [scipy.fft.next_fast_len(2 * m - 1, real=True) for m in shape]
        return max(4, int(2 * padded[0] * padded[1] * np.log2(padded[0] * padded[1])
                          / (shape[0] * shape[1]) / 3))

    def add_columns(self, field: np.ndarray, values: np.ndarray, cells: np.ndarray) -> None:
        """Add the displacement of pressures ``values`` on the flat ``cells`` of the window
        ``field`` to ``field`` in place, summing influence columns directly."""
        m1, m2 = field.shape
        kernel = self._kernel(max(m1, m2))
        origin = (kernel.shape[0] - 1) // 2
        for value, (i, j) in zip(values, zip(*np.unravel_index(cells, field.shape))):
            field += value * kernel[origin - i: origin - i + m1, origin - j: origin - j + m2]

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """Dense ``A[a, b]``: displacement at cell ``(rows[a], cols[a])`` under unit pressure
        on cell ``(rows[b], cols[b])`` (grid or window indices: only offsets matter)."""
        return self.coefficients[np.abs(rows[:, None] - rows[None, :]),
                                 np.abs(cols[:, None] - cols[None, :])]

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Displacement on the cells of ``pressure`` (any ``m1 × m2`` window, ``m ≤ n``),
        for that pressure alone (zero outside the window)."""
        shape = pressure.shape
        padded, spectrum = self._spectrum(shape)
        product = scipy.fft.rfft2(pressure, s=padded) * spectrum
        return scipy.fft.irfft2(product, s=padded)[: shape[0], : shape[1]]


class PeriodicOperator:
    """Elastic half-space periodic over ``length`` on an ``n × n`` grid.

    ``ũ(q) = 2 p̃(q)/(E* |q|)`` for ``q ≠ 0``; ``ũ(0) = 0``.
    """

    periodic = True

    def __init__(self, n: int, length: float, e_star: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        qx = 2.0 * np.pi * scipy.fft.fftfreq(n, d=self.spacing)
        qy = 2.0 * np.pi * scipy.fft.rfftfreq(n, d=self.spacing)
        q = np.hypot(qx[:, None], qy[None, :])
        q[0, 0] = np.inf
        self.spectrum = 2.0 / (e_star * q)
        self.self_coefficient = float(self._kernel[0, 0])

    @functools.cached_property
    def _kernel(self) -> np.ndarray:
        """Displacement of the whole grid under a unit pressure on cell (0, 0)."""
        unit = np.zeros((self.n, self.n))
        unit[0, 0] = 1.0
        return self(unit)

    def column_limit(self, shape: tuple[int, int]) -> int:
        """How many columns :meth:`add_columns` sums in about the time of one FFT convolution."""
        return max(4, int(np.log2(shape[0] * shape[1])))

    def add_columns(self, field: np.ndarray, values: np.ndarray, cells: np.ndarray) -> None:
        """Add the displacement of pressures ``values`` on the flat ``cells`` to ``field`` in place."""
        n, kernel = self.n, self._kernel
        for value, (i, j) in zip(values, zip(*np.unravel_index(cells, field.shape))):
            # the kernel rolled by (i, j), added as four blocks (no rolled copy)
            field[i:, j:] += value * kernel[: n - i, : n - j]
            field[i:, :j] += value * kernel[: n - i, n - j:]
            field[:i, j:] += value * kernel[n - i:, : n - j]
            field[:i, :j] += value * kernel[n - i:, n - j:]

    @functools.cached_property
    def min_coefficient(self) -> float:
        """Most negative displacement under a unit cell pressure: ``u ≥ min_coefficient · Σ p``."""
        return float(self._kernel.min())

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """Dense ``A[a, b]``: displacement at cell ``(rows[a], cols[a])`` under unit pressure
        on cell ``(rows[b], cols[b])``, offsets taken modulo ``n``."""
        n = self.n
        return self._kernel[(rows[:, None] - rows[None, :]) % n, (cols[:, None] - cols[None, :]) % n]

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Zero-mean displacement of the periodic half-space (full ``n × n`` grid)."""
        n = self.n
        return scipy.fft.irfft2(scipy.fft.rfft2(pressure) * self.spectrum, s=(n, n))


class DenseOperator:
    """An influence operator restricted to a few cells, as a dense matrix.

    For contact problems whose cells that can touch number at most a couple of
    thousand, one matrix-vector product costs less than an FFT over the grid.
    Pressures and displacements are 1-D arrays over those cells.

    Parameters
    ----------
    matrix : numpy.ndarray, shape (m, m)
        ``influence_matrix`` of a grid operator for the cells.
    """

    def __init__(self, matrix: np.ndarray):
        self.matrix = matrix
        self.self_coefficient = float(matrix[0, 0])

    def column_limit(self, shape: tuple[int, ...]) -> int:
        """How many columns :meth:`add_columns` takes in about the time of a full product."""
        return max(4, shape[0] // 4)

    def add_columns(self, field: np.ndarray, values: np.ndarray, cells: np.ndarray) -> None:
        """Add the displacement of pressures ``values`` on ``cells`` to ``field`` in place."""
        field += self.matrix[:, cells] @ values

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Displacement on the cells under ``pressure`` on the cells."""
        return self.matrix @ pressure


@functools.lru_cache(maxsize=8)
def operator_for(n: int, length: float, e_star: float, periodic: bool):
    """Shared, cached operator for a grid (kernel spectra are reused across solves)."""
    cls = PeriodicOperator if periodic else FreeSpaceOperator
    return cls(n, length, e_star)
