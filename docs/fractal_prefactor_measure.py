"""Per-load measurements of rough spheres at small loads on a ladder of grids (the same surfaces).

Used by ``docs/make_fractal_prefactor.py``; kept apart so that the page's script stays short.
One row per (case, seed, grid, load): force, depth, punch stiffness, contact cells, patches, the
largest patch's cells, the contact's radius (second moment and largest distance from the apex)
and the roughness's rms of the wavelengths below ``2a`` within the contact's window.
"""
from __future__ import annotations

import time

import numpy as np
from scipy import ndimage

from roughcontact import bem
from roughcontact.surfaces import rough_sphere, self_affine

COLUMNS = ["case", "hurst", "radius", "h_rms", "period", "rolloff", "seed", "n", "N", "force", "depth", "k", "cells",
           "patches", "largest", "share", "clusters", "cluster_share", "r2", "rmax", "offset", "wall_s", "summit",
           "touch_offset"]
#: patches closer than this (L) form one cluster (two cells of a 512² grid): an asperity split by
#: the finer grids' roughness counts once
CLUSTER_GAP = 0.004


def _heights(n, finest, *, hurst, radius, h_rms, seed, period, rolloff):
    """The rough sphere on the n-grid: the finest grid's surface seen on n (``realization_of``);
    ``period = 1/m`` (m integer) tiles m × m copies of a roughness of period L/m whose power law
    has the same amplitude ``h/L^H`` (``h_rms·m^(−H)``), as a surface whose longest wave is L/m;
    ``rolloff``: the spectrum's plateau below ``2π/rolloff`` (the caller sets ``h_rms``)."""
    if np.isinf(radius):
        return self_affine(n, hurst=hurst, h_rms=h_rms, length=1.0, seed=seed, realization_of=finest)
    if period == 1.0:
        return rough_sphere(n, radius=radius, hurst=hurst, h_rms=h_rms, length=1.0, seed=seed,
                            rolloff=rolloff, realization_of=finest)
    m = int(round(1.0 / period))
    tile = self_affine(n // m, hurst=hurst, h_rms=h_rms * period**hurst, length=period, seed=seed,
                       realization_of=finest // m)
    z = np.tile(tile, (m, m))
    x = (np.arange(n) - n // 2) / n
    return z + (x[:, None] ** 2 + x[None, :] ** 2) / (2.0 * radius)


def measure(case: str, *, hurst: float, radius: float, h_rms: float, forces, grids, seed: int,
            period: float = 1.0, rolloff: float | None = None, tol: float = 1e-8) -> list[dict]:
    """Press the surface of the finest of *grids* (``realization_of``) on each grid at *forces*.

    Grids are even, so that the apex (node ``n/2``) sits at the same point ``x = L/2`` of the
    roughness on every grid. ``radius = inf``: the nominally flat surface on the periodic
    half-space. Lengths in units of L, forces of E* L².
    """
    finest = max(grids)
    periodic = bool(np.isinf(radius))
    rows = []
    for n in sorted(grids):
        z = _heights(n, finest, hurst=hurst, radius=radius, h_rms=h_rms, seed=seed, period=period,
                     rolloff=rolloff)
        gap = int(np.ceil(CLUSTER_GAP * n / 2.0))
        touch = _touch(z, n, radius) if n == finest else dict(summit=np.nan, touch_offset=np.nan)
        dx = 1.0 / n
        idx = (np.arange(n) - n // 2) * dx
        start = time.perf_counter()
        for state in bem.iter_load_path(z, forces, length=1.0, e_star=1.0, periodic=periodic, tol=tol):
            k = bem.stiffness(state, method="punch")
            contact = state.contact
            patches = bem.contact_patches(contact, periodic=periodic)
            p = state.pressure[contact]
            ii, jj = np.nonzero(contact)
            cx = float(np.sum(p * idx[ii]) / p.sum())
            cy = float(np.sum(p * idx[jj]) / p.sum())
            loads = np.bincount(patches.labels[contact], weights=p)[1:]
            clusters = ndimage.label(ndimage.binary_dilation(contact, iterations=gap))[0][contact]
            cluster_loads = np.bincount(clusters, weights=p)[1:]
            spread = (idx[ii] - cx) ** 2 + (idx[jj] - cy) ** 2
            rows.append(dict(case=case, hurst=hurst, radius=radius, h_rms=h_rms, period=period,
                             rolloff=rolloff, seed=seed, n=n, N=finest,
                             force=state.force, depth=state.depth, k=k, cells=int(contact.sum()),
                             patches=patches.count, largest=patches.largest, share=loads.max() / p.sum(),
                             clusters=int(np.count_nonzero(cluster_loads)),
                             cluster_share=cluster_loads.max() / p.sum(),
                             r2=float(np.sqrt(2.0 * np.mean(spread))), rmax=float(np.sqrt(spread.max())),
                             offset=float(np.hypot(cx, cy)),
                             wall_s=time.perf_counter() - start, **touch))
            start = time.perf_counter()
    return rows


def _touch(z, n, radius) -> dict:
    """The first touch of the heights z (rough body) on the n-grid: :func:`summit`'s numbers."""
    x = (np.arange(n) - n // 2) / n
    body = 0.0 if np.isinf(radius) else (x[:, None] ** 2 + x[None, :] ** 2) / (2.0 * radius)
    i, j = np.unravel_index(np.argmin(z), z.shape)
    rough = z - body
    rough = rough - rough.mean()
    return dict(summit=float(-rough[i, j] / np.sqrt(np.mean(rough**2))),
                touch_offset=float(np.hypot(x[i], x[j])) if np.isfinite(radius) else np.nan)


def summit(*, hurst: float, radius: float, h_rms: float, seed: int, n: int, period: float = 1.0,
           rolloff: float | None = None) -> dict:
    """Where the body first touches and how high the roughness stands there, on the n-grid.

    Heights are gaps (contact where ``z`` is least, :mod:`roughcontact.bem`): the first touch is
    ``argmin z``; ``summit = −z_r(x*)/h_rms`` is the roughness's height there in units of its rms
    (for a flat surface the height of its highest point), ``touch_offset`` the distance of x* from
    the apex (L).
    """
    z = _heights(n, n, hurst=hurst, radius=radius, h_rms=h_rms, seed=seed, period=period, rolloff=rolloff)
    return dict(seed=seed, **_touch(z, n, radius))
