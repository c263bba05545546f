"""Sub-windows of a measured surface and the jump across its edges.

A measured scan is one realisation: :func:`tiles` cuts it into non-overlapping square
windows, the ensemble over which the study's intervals are taken. A scan is not periodic:
:func:`edge_jump` measures the step across its edges that a periodic solver would see.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .._validate import check_grid_size
from .instrument_files import frozen
from .measured import MeasuredSurface

__all__ = ["EdgeJump", "edge_jump", "tiles"]


def tiles(surface: MeasuredSurface, size: int) -> list[MeasuredSurface]:
    """Non-overlapping ``size × size`` sub-windows of ``surface``, row by row.

    Each tile is re-centred to mean 0 (same sign convention) and has
    ``length = size · Δ``; its record is the parent's plus ``tile_index``,
    ``tile_i0``, ``tile_j0`` (first cell in the parent), ``n``, ``length`` and ``sq``.
    The ``(n // size)²`` tiles are an ensemble of the one measured surface (not independent
    samples: they share the long wavelengths of the scan).
    """
    check_grid_size(size)
    n = surface.n
    if size > n:
        raise ValueError(f"size must be <= n = {n}, got {size!r}")
    out = []
    delta = surface.cell_size
    count = n // size
    for a in range(count):
        for b in range(count):
            block = surface.heights[a * size:(a + 1) * size, b * size:(b + 1) * size]
            block = block - block.mean()
            record = dict(surface.record)
            record.update({"tile_index": a * count + b, "tile_i0": a * size, "tile_j0": b * size,
                           "n": int(size), "length": size * delta,
                           "sq": float(np.sqrt(np.mean(block ** 2)))})
            out.append(MeasuredSurface(heights=frozen(block), length=size * delta,
                                       unit=surface.unit, record=record))
    return out


@dataclasses.dataclass(frozen=True)
class EdgeJump:
    """Height jumps of a map that a periodic solver would repeat (:func:`edge_jump`).

    Attributes
    ----------
    edge : float
        Rms of the jumps across the periodic seam, ``z[0, :] − z[−1, :]`` and
        ``z[:, 0] − z[:, −1]`` (both directions pooled).
    neighbour : float
        Rms of the jumps between neighbouring cells inside the map, both directions pooled.
    gradient : float
        ``√(⟨Δ_x²⟩ + ⟨Δ_y²⟩)``: the neighbour jumps as the rms gradient magnitude times
        ``Δ`` (SurfaceTopography's ``Sdq·Δ``), ``√2 ×`` ``neighbour`` for isotropic maps.
    sq : float
        Rms height of the map about its mean.
    """

    edge: float
    neighbour: float
    gradient: float
    sq: float

    @property
    def edge_ratio(self) -> float:
        """``edge / sq``."""
        return self.edge / self.sq

    @property
    def neighbour_ratio(self) -> float:
        """``neighbour / sq``."""
        return self.neighbour / self.sq

    @property
    def is_periodic_like(self) -> bool:
        """The seam is no larger a jump than typical neighbours (``edge ≤ 2 neighbour``)."""
        return self.edge <= 2.0 * self.neighbour


def edge_jump(heights) -> EdgeJump:
    """How far a map is from periodic: the jump across its edges against its neighbours'.

    ``heights``: a :class:`MeasuredSurface` or a 2-D array. A periodic map has
    ``edge ≈ neighbour``; a measured scan, cut anywhere, has ``edge`` of order ``Sq``
    (for a 257² centred crop of ``opd-1.opd``: ``edge ≈ 1.1 Sq``, ``neighbour ≈ 0.38 Sq``).
    """
    z = heights.heights if isinstance(heights, MeasuredSurface) else np.asarray(heights, float)
    if z.ndim != 2 or min(z.shape) < 2:
        raise ValueError(f"heights must be a 2-D array of at least 2 x 2, got shape {z.shape}")
    seam = np.concatenate([z[0, :] - z[-1, :], z[:, 0] - z[:, -1]])
    dxx = np.diff(z, axis=0).ravel()
    dyy = np.diff(z, axis=1).ravel()
    mx, my = np.mean(dxx ** 2), np.mean(dyy ** 2)
    return EdgeJump(edge=float(np.sqrt(np.mean(seam ** 2))),
                    neighbour=float(np.sqrt(np.mean(np.concatenate([dxx, dyy]) ** 2))),
                    gradient=float(np.sqrt(mx + my)),
                    sq=float(np.std(z)))
