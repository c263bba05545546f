"""The zero-padded FFT windows of the free half-space's operators (:mod:`roughcontact.bem.operators`,
:mod:`roughcontact.bem.cerruti`): a window of ``m`` cells a side is convolved on ``M = next_fast_len(2m − 1)``
points, and a kernel's table of offsets is placed on that padded grid circularly."""
from __future__ import annotations

import numpy as np
import scipy.fft

__all__ = ["padded_size", "PaddedWindow"]


def padded_size(shape) -> tuple[int, int]:
    """The zero-padded FFT size of a window of *shape*: ``next_fast_len(2m − 1)`` per axis."""
    return tuple(scipy.fft.next_fast_len(2 * m - 1, real=True) for m in shape)


class PaddedWindow:
    """Where a kernel's table goes on a padded FFT grid (:func:`padded_size`): the offsets of the
    largest window of that padded size, ``side = min((M + 1)//2, n)`` cells a side per axis, placed
    circularly (offset ``i`` at ``i`` and ``−i`` at ``M − i``), the rest zero.

    Attributes
    ----------
    side : int
        The table's side needed (the larger axis's window).
    rows, cols : numpy.ndarray
        ``|offset|`` of each padded row (as a column) and column (as a row), for indexing a table.
    mask : numpy.ndarray
        Whether each padded cell holds an offset of the window (bool, broadcast ``(M0, M1)``).
    signs : tuple of numpy.ndarray
        Per axis, ``+1`` at non-negative offsets, ``−1`` at negative ones, 0 where unused: the sign
        of a kernel odd in that axis.
    """

    def __init__(self, rows, cols, mask, signs, side):
        self.rows, self.cols, self.mask, self.signs, self.side = rows, cols, mask, signs, side

    @classmethod
    def of(cls, padded: tuple[int, int], n: int) -> "PaddedWindow":
        """The placement of the padded size *padded* on a grid of *n* cells a side."""
        largest = [min((size + 1) // 2, n) for size in padded]
        index = [np.arange(size) for size in padded]
        used = [(idx < m) | (idx > size - m) for idx, m, size in zip(index, largest, padded)]
        offsets = [np.where(idx < m, idx, np.where(use, size - idx, 0))
                   for idx, m, size, use in zip(index, largest, padded, used)]
        signs = tuple(np.where(idx < m, 1.0, -1.0) * use for idx, m, use in zip(index, largest, used))
        return cls(offsets[0][:, None], offsets[1][None, :], used[0][:, None] & used[1][None, :], signs,
                   max(largest))
