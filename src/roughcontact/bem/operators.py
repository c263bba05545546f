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

from .padding import PaddedWindow, padded_size

__all__ = ["love_coefficients", "FreeSpaceOperator", "PeriodicOperator", "DenseOperator", "operator_for",
           "PeriodicWindows", "periodic_windows"]


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


#: Columns of the half spectrum transformed along the padded rows at a time
#: (:meth:`FreeSpaceOperator._convolve`).
_COLUMN_BLOCK = 256
#: Rows of a dense influence matrix gathered at a time (bounds the index temporaries).
_GATHER_ROWS = 256


def _gather(table: np.ndarray, rows, cols, source_rows, source_cols, offset, out) -> np.ndarray:
    """``A[a, b] = table.flat[offset(rows[a] − source_rows[b], cols[a] − source_cols[b])]``,
    gathered a block of :data:`_GATHER_ROWS` rows at a time (into ``out`` if given)."""
    rows, cols = np.asarray(rows, dtype=np.intp), np.asarray(cols, dtype=np.intp)
    source_rows = rows if source_rows is None else np.asarray(source_rows, dtype=np.intp)
    source_cols = cols if source_cols is None else np.asarray(source_cols, dtype=np.intp)
    flat = table.reshape(-1)
    matrix = np.empty((rows.size, source_rows.size)) if out is None else out
    for start in range(0, rows.size, _GATHER_ROWS):
        stop = min(start + _GATHER_ROWS, rows.size)
        index = offset(np.subtract.outer(rows[start:stop], source_rows),
                       np.subtract.outer(cols[start:stop], source_cols))
        np.take(flat, index, out=matrix[start:stop])
    return matrix


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
    #: Kernel spectra kept per precision: a load path only grows its window, so an old
    #: size is rarely needed again. The kernel is even in both offsets, so its spectrum is
    #: real: a spectrum of the padded size ``M₀ × M₁`` holds ``M₀ (M₁/2 + 1)`` doubles
    #: (0.27 GB for the padded 8192² of a whole 4097² grid; its single-precision copy half that).
    cached_spectra = 1

    def __init__(self, n: int, length: float, e_star: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self._table = np.empty((0, 0))
        self.self_coefficient = self._coefficients(1)[0, 0]
        self._spectra: collections.OrderedDict[tuple[int, int], np.ndarray] = \
            collections.OrderedDict()
        self._single_spectra: collections.OrderedDict[tuple[int, int], np.ndarray] = \
            collections.OrderedDict()

    def _coefficients(self, size: int) -> np.ndarray:
        """Displacements under a unit cell pressure at offsets ``[0, size)²`` (at least).

        The table grows on demand (by at least half its side, at most to ``n``), so
        that a solve on a window of a large grid evaluates Love's formula on the
        offsets the window needs, not on the whole grid.
        """
        if self._table.shape[0] < size:
            side = min(self.n, max(size, (3 * self._table.shape[0]) // 2, 64))
            self._table = self._unit_table(side)
        return self._table

    def _unit_table(self, side: int) -> np.ndarray:
        """Displacements under a unit cell pressure at offsets ``[0, side)²`` (Love's formula;
        a subclass with another kernel of the same symmetry overrides this)."""
        return love_coefficients(side) * (self.spacing / (np.pi * self.e_star))

    @property
    def coefficients(self) -> np.ndarray:
        """``(n, n)`` displacements under a unit cell pressure at offsets ``(i, j) ≥ 0``."""
        return self._coefficients(self.n)

    def window_size(self, cells: int) -> int:
        """Largest window ≥ ``cells`` (≤ n) convolved with the same padded FFT size."""
        cells = min(max(int(cells), 1), self.n)
        padded = scipy.fft.next_fast_len(2 * cells - 1, real=True)
        return min((padded + 1) // 2, self.n)

    def _spectrum(self, shape: tuple[int, int]) -> tuple[tuple[int, int], np.ndarray]:
        """The kernel's spectrum on the padded size of a window of *shape*, cached by padded size.

        The kernel holds the offsets of the largest window of that padded size,
        ``min((M + 1)//2, n)`` cells a side, not those of *shape*: a cached spectrum then
        serves every window that maps to its padded size (one built for a smaller window would
        miss the far offsets of a larger one).
        """
        padded = padded_size(shape)
        spectrum = self._spectra.get(padded)
        if spectrum is None:
            window = PaddedWindow.of(padded, self.n)
            kernel = self._coefficients(window.side)[window.rows, window.cols] * window.mask
            spectrum = np.ascontiguousarray(scipy.fft.rfft2(kernel, overwrite_x=True).real)
            self._spectra[padded] = spectrum
            if len(self._spectra) > self.cached_spectra:
                self._spectra.popitem(last=False)
        else:
            self._spectra.move_to_end(padded)
        return padded, spectrum

    def column_limit(self, shape: tuple[int, int]) -> int:
        """How many columns :meth:`add_columns` sums in about the time of one FFT convolution."""
        padded = padded_size(shape)
        return max(4, int(2 * padded[0] * padded[1] * np.log2(padded[0] * padded[1])
                          / (shape[0] * shape[1]) / 3))

    def add_columns(self, field: np.ndarray, values: np.ndarray, cells: np.ndarray) -> None:
        """Add the displacement of pressures ``values`` on the flat ``cells`` of the window
        ``field`` to ``field`` in place, summing influence columns directly."""
        m1, m2 = field.shape
        table = self._coefficients(max(m1, m2))
        for value, (i, j) in zip(values, zip(*np.unravel_index(cells, field.shape))):
            # the coefficient at |r − i|, |c − j| as four blocks of the table (offsets
            # 0, 1, ... below and right of the cell, reversed above and left of it)
            below, above = table[: m1 - i], table[i:0:-1]
            field[i:, j:] += value * below[:, : m2 - j]
            field[i:, :j] += value * below[:, j:0:-1]
            field[:i, j:] += value * above[:, : m2 - j]
            field[:i, :j] += value * above[:, j:0:-1]

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray,
                         source_rows: np.ndarray | None = None,
                         source_cols: np.ndarray | None = None,
                         out: np.ndarray | None = None) -> np.ndarray:
        """Dense ``A[a, b]``: displacement at cell ``(rows[a], cols[a])`` under unit pressure
        on cell ``(source_rows[b], source_cols[b])`` (default: the same cells; grid or
        window indices: only offsets matter), written to ``out`` if given."""
        source_rows = rows if source_rows is None else source_rows
        source_cols = cols if source_cols is None else source_cols
        reach = [np.concatenate([a, b]) for a, b in ((rows, source_rows), (cols, source_cols))]
        table = self._coefficients(1 + max((int(a.max() - a.min()) for a in reach if a.size),
                                           default=0))
        side = table.shape[1]
        return _gather(table, rows, cols, source_rows, source_cols,
                       lambda di, dj: np.abs(di, out=di) * side + np.abs(dj, out=dj), out)

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Displacement on the cells of ``pressure`` (any ``m1 × m2`` window, ``m ≤ n``),
        for that pressure alone (zero outside the window).

        The 2-D transforms are done axis by axis and pruned: the forward transform
        along the rows runs on the ``m1`` rows that hold the pressure (the padding
        rows are zero), the inverse along the rows on the ``m1`` rows that are
        returned. The same 1-D transforms as ``rfft2``/``irfft2`` on the padded
        array, minus those whose input is zero or whose output is discarded.
        """
        padded, spectrum = self._spectrum(pressure.shape)
        return self._convolve(pressure, padded, spectrum)

    def single(self, pressure: np.ndarray) -> np.ndarray:
        """:meth:`__call__` with single-precision transforms (relative error ≈ 1e-6),
        returned in double precision."""
        padded, spectrum = self._spectrum(pressure.shape)
        single = self._single_spectra.get(padded)
        if single is None:
            single = self._single_spectra[padded] = spectrum.astype(np.float32)
            if len(self._single_spectra) > self.cached_spectra:
                self._single_spectra.popitem(last=False)
        return self._convolve(pressure.astype(np.float32), padded, single).astype(float)

    @staticmethod
    def _convolve(pressure, padded, spectrum):
        """The pruned padded convolution; the transform along the padded rows runs on blocks of
        :data:`_COLUMN_BLOCK` columns, so that no ``M₀ × (M₁/2 + 1)`` complex array is held (only the
        ``m₁`` rows that hold the pressure and are returned)."""
        m1, m2 = pressure.shape
        transform = scipy.fft.rfft(pressure, n=padded[1], axis=1)
        for start in range(0, transform.shape[1], _COLUMN_BLOCK):
            block = slice(start, start + _COLUMN_BLOCK)
            column = scipy.fft.fft(transform[:, block], n=padded[0], axis=0)
            column *= spectrum[:, block]
            transform[:, block] = scipy.fft.ifft(column, axis=0, overwrite_x=True)[:m1]
        return scipy.fft.irfft(transform, n=padded[1], axis=1)[:, :m2].copy()


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

    def influence_matrix(self, rows: np.ndarray, cols: np.ndarray,
                         source_rows: np.ndarray | None = None,
                         source_cols: np.ndarray | None = None,
                         out: np.ndarray | None = None) -> np.ndarray:
        """Dense ``A[a, b]``: displacement at cell ``(rows[a], cols[a])`` under unit pressure
        on cell ``(source_rows[b], source_cols[b])`` (default: the same cells), offsets
        taken modulo ``n``, written to ``out`` if given."""
        n = self.n
        return _gather(self._kernel, rows, cols, source_rows, source_cols,
                       lambda di, dj: np.remainder(di, n, out=di) * n + np.remainder(dj, n, out=dj),
                       out)

    @functools.cached_property
    def _single_spectrum(self) -> np.ndarray:
        return self.spectrum.astype(np.float32)

    def single(self, pressure: np.ndarray) -> np.ndarray:
        """:meth:`__call__` with single-precision transforms (relative error ≈ 1e-6),
        returned in double precision."""
        transform = scipy.fft.rfft2(pressure.astype(np.float32))
        transform *= self._single_spectrum
        return scipy.fft.irfft2(transform, s=(self.n, self.n), overwrite_x=True).astype(float)

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Zero-mean displacement of the periodic half-space (full ``n × n`` grid)."""
        transform = scipy.fft.rfft2(pressure)
        transform *= self.spectrum
        return scipy.fft.irfft2(transform, s=(self.n, self.n), overwrite_x=True)


class DenseOperator:
    """An influence operator restricted to a few cells, as a dense matrix.

    For contact problems whose cells that can touch number at most a couple of
    thousand, one matrix-vector product costs less than an FFT over the grid.
    Pressures and displacements are 1-D arrays over those cells.

    Parameters
    ----------
    matrix : numpy.ndarray, shape (m, m)
        ``influence_matrix`` of a grid operator for the cells (symmetric, by
        reciprocity; a view into a larger array is fine).
    """

    def __init__(self, matrix: np.ndarray):
        self.matrix = matrix
        self.self_coefficient = float(matrix[0, 0])

    def column_limit(self, shape: tuple[int, ...]) -> int:
        """How many columns :meth:`add_columns` takes in about the time of a full product."""
        return max(4, shape[0] // 4)

    def add_columns(self, field: np.ndarray, values: np.ndarray, cells: np.ndarray) -> None:
        """Add the displacement of pressures ``values`` on ``cells`` to ``field`` in place."""
        field += values @ self.matrix[cells]  # rows: the matrix is symmetric

    def __call__(self, pressure: np.ndarray) -> np.ndarray:
        """Displacement on the cells under ``pressure`` on the cells."""
        return self.matrix @ pressure


@functools.lru_cache(maxsize=8)
def operator_for(n: int, length: float, e_star: float, periodic: bool):
    """Shared, cached operator for a grid (kernel spectra are reused across solves)."""
    cls = PeriodicOperator if periodic else FreeSpaceOperator
    return cls(n, length, e_star)


class PeriodicWindows(FreeSpaceOperator):
    """The periodic half-space on windows of the grid: the windowed, zero-padded convolution of
    :class:`~roughcontact.bem.operators.FreeSpaceOperator` with the periodic kernel as its table.

    The periodic displacement under a unit cell pressure, ``k[i mod n, j mod n]``, is even in each
    offset, so the table ``k[|i|, |j|]`` of the offsets ``|i|, |j| < n`` is all a window needs:
    for pressures inside a window of at most ``n`` cells a side the linear convolution on the
    padded window gives the periodic displacement on the window exactly (round-off apart), at the
    cost of the window's FFT instead of the grid's.
    """

    periodic = True

    def __init__(self, operator: PeriodicOperator):
        self._periodic_kernel = operator._kernel
        super().__init__(operator.n, operator.n * operator.spacing, operator.e_star)

    def _coefficients(self, size: int) -> np.ndarray:
        return self._periodic_kernel


@functools.lru_cache(maxsize=4)
def periodic_windows(operator: PeriodicOperator) -> PeriodicWindows:
    """One :class:`PeriodicWindows` per (cached) periodic operator, so its spectra are reused."""
    return PeriodicWindows(operator)
