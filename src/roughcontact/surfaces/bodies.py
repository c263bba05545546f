"""Smooth bodies of revolution and rough spheres on the grid (Sec. 2 and the Conclusions).

Heights are the indenter's shape ``z`` on the ``n × n`` grid of
:mod:`roughcontact.surfaces.roughness`, measured from the undeformed half-space towards the
indenter; ``r`` is measured from the node ``(n//2, n//2)``. Lengths are in the caller's unit.

References
----------
R. Pohrt, V. L. Popov, "Contact Mechanics of Rough Spheres: Crossover from
Fractal to Hertzian Behavior", Adv. Tribol. 2013, 974178 (2013), doi 10.1155/2013/974178.
"""

from __future__ import annotations

import numpy as np

from .._validate import check_finite_positive, check_grid_size
from .roughness import row_blocks, self_affine

__all__ = ["radial_distance", "body_of_revolution", "body_height", "paraboloid", "rough_sphere"]


def _coordinates(n: int, length: float) -> np.ndarray:
    """Node coordinates ``x_i − x_(n//2)`` along one side."""
    return (np.arange(n) - n // 2) * (length / n)


def body_height(r, radius: float, exponent: float):
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
    for rows in row_blocks(n, n):
        heights[rows] = body_height(np.hypot(x[rows, None], x[None, :]), radius, exponent)
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
                 rolloff: float | None = None, cutoff: float | None = None,
                 realization_of: int | None = None) -> np.ndarray:
    """Rough sphere ``z = z_p + z_r``: paraboloid plus self-affine roughness (Fig. 2).

    ``z_p`` is :func:`body_of_revolution` with ``exponent`` (default 2: the paraboloid),
    ``z_r`` is :func:`self_affine` with the other arguments (``realization_of``: the surface of a
    finer grid, seen on this one); the body is added in place,
    row block by row block, so the peak memory is that of :func:`self_affine`. The
    defaults give the same bytes as before ``exponent``, ``rolloff`` and ``cutoff`` existed.
    """
    check_finite_positive("radius", radius)
    check_finite_positive("exponent", exponent)
    heights = self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                          rolloff=rolloff, cutoff=cutoff, realization_of=realization_of)
    x = _coordinates(n, length)
    for rows in row_blocks(n, n):
        heights[rows] += body_height(np.hypot(x[rows, None], x[None, :]), radius, exponent)
    return heights
