"""The pressure and gap histograms in the report (``fields.histograms``): one load of one combination.

:func:`make_histogram_figure` draws, from ``stiffness.nc``, the histograms of the largest load
that keeps them (the most contact cells) of the sweep's first combination (the sphere's where the
sweep has one): the pressure over the contact cells and the gap over the cells out of contact, as
probability densities (counts over cells and bin width, :mod:`roughcontact.study.quantities.histograms`),
one step curve per seed (at most :data:`~roughcontact.study.report.plotting.MAX_CURVES`); on a
sphere beside Hertz's density of the smooth sphere's pressure at the same force,
``2p/p₀²`` for ``p < p₀`` (the share of the area below ``p`` is ``(p/p₀)²``; Johnson 1985, §3.9).

Pressures in units of ``E*``, gaps in the unit of ``grid.length`` (``units.length`` where set).
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ..config.settings import StudySettings
from .plotting import MAX_CURVES, pyplot, save_png

__all__ = ["make_histogram_figure"]

log = logging.getLogger(__name__)


def _density(counts, edges) -> tuple[np.ndarray, np.ndarray]:
    """``(edges, density)`` of one histogram: counts over their sum and the bin width (0 where empty)."""
    counts = np.asarray(counts, dtype=float)
    width = np.diff(edges)
    total = counts.sum()
    with np.errstate(divide="ignore", invalid="ignore"):
        density = np.where((width > 0) & (total > 0), counts / (total * width), 0.0)
    return np.asarray(edges), density


def _hertz_p0(force: float, radius: float, e_star: float) -> float:
    """Hertz's peak pressure ``p₀ = 3F/(2πa²)``, ``a = (3FR/4E*)^(1/3)`` of a smooth sphere."""
    a = (3 * force * radius / (4 * e_star)) ** (1 / 3)
    return 3 * force / (2 * math.pi * a * a)


def make_histogram_figure(study, stiffness_nc, out_png) -> None:
    """``histograms_figure`` rule: ``stiffness.nc`` -> *out_png* (module docstring)."""
    import xarray as xr

    study = StudySettings.of(study)
    kind = "sphere" if any(math.isfinite(r) for r in study.radius) else "flat"
    with xr.open_dataset(stiffness_nc, group=kind) as ds:
        ds = ds.load()
    axes = [d for d in ds["pressure_histogram"].dims if d not in ("seed", "histogram_load", "pressure_bin")]
    first = ds.isel({axis: 0 for axis in axes}).isel(histogram_load=-1)
    where = ", ".join(f"{axis} = {float(ds[axis].values[0]):g}" for axis in axes if ds.sizes[axis] > 1
                      or axis in ("hurst", "radius", "h_rms"))
    force = float(first["histogram_force"])
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.2, 3.6))
    for i, seed in enumerate(first["seed"].values[:MAX_CURVES]):
        one = first.sel(seed=seed)
        for ax, name in ((left, "pressure"), (right, "gap")):
            edges, density = _density(one[f"{name}_histogram"].values, one[f"{name}_bin_edges"].values)
            ax.stairs(density, edges, color=f"C{i}", lw=1, label=f"seed {int(seed)}")
    if kind == "sphere":
        p0 = _hertz_p0(force, float(first["radius"]), study.e_star)
        p = np.linspace(0.0, p0, 101)
        left.plot(p, 2 * p / p0**2, color="k", ls="--", lw=1, label="smooth sphere (Hertz)")
    left.set(xlabel=f"pressure p ({ds['pressure_bin_edges'].attrs.get('units', 'e_star')})",
             ylabel="probability density over the contact")
    right.set(xlabel=f"gap g ({ds['gap_bin_edges'].attrs.get('units', 'length')})",
              ylabel="probability density out of contact")
    left.legend(fontsize=7)
    fig.suptitle(f"{kind}: {where}, F/(E* L^2) = {float(first['histogram_force_normalized']):.3g}", fontsize=9)
    fig.tight_layout()
    save_png(fig, out_png)
    log.info("drew the histograms of load %d (%s) into %s", int(first["histogram_load"]), where, out_png)
