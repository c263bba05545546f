"""The pressure and gap histograms in the report (``fields.histograms``): one load of one combination.

:func:`make_histogram_figure` draws, from ``stiffness.nc``, the histograms of the largest load
that keeps them (the most contact cells) of the sweep's first combination (the sphere's where the
sweep has one), in normalized units common to every run
(:func:`roughcontact.study.analysis.histograms.mean_histograms`): the pressure over the contact
cells in units of the run's mean contact pressure ``p̄ = F/A`` and the gap over the cells out of
contact in units of ``h_rms``, as probability densities; the ensemble's mean (black, with ± two
standard errors over the seeds shaded) over one thin curve per seed (at most
:data:`~roughcontact.study.report.plotting.MAX_CURVES`); on a sphere beside Hertz's density of the
smooth sphere's pressure, ``8x/9`` for ``x = p/p̄ < 3/2`` (the share of the area below ``p`` is
``(p/p₀)²`` and ``p̄ = 2p₀/3``; Johnson 1985, §3.9). Each panel's legend lies under it.
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ..analysis.histograms import mean_histograms
from ..config.settings import StudySettings
from .plotting import MAX_CURVES, layout_with_legends, legend_below, pyplot, save_png

__all__ = ["make_histogram_figure"]

log = logging.getLogger(__name__)


def make_histogram_figure(study, stiffness_nc, out_png) -> None:
    """``histograms_figure`` rule: ``stiffness.nc`` -> *out_png* (module docstring)."""
    import xarray as xr

    study = StudySettings.of(study)
    kind = "sphere" if any(math.isfinite(r) for r in study.radius) else "flat"
    with xr.open_dataset(stiffness_nc, group=kind) as ds:
        ds = ds.load()
    axes = [d for d in ds["pressure_histogram"].dims if d not in ("seed", "histogram_load", "pressure_bin")]
    first = ds.isel({axis: 0 for axis in axes}).isel(histogram_load=[-1])
    mean = mean_histograms(first).isel(histogram_load=0)
    where = ", ".join(f"{axis} = {float(ds[axis].values[0]):g}" for axis in axes if ds.sizes[axis] > 1
                      or axis in ("hurst", "radius", "h_rms"))
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(9.2, 3.6))
    for ax, name, ratio in ((left, "pressure", "pressure_ratio"), (right, "gap", "gap_ratio")):
        edges = mean[f"{ratio}_edges"].values
        for i, seed in enumerate(mean["seed"].values[:MAX_CURVES]):
            ax.stairs(mean[f"{name}_density"].sel(seed=seed).values, edges, color=f"C{i}", lw=0.6, alpha=0.6,
                      label=f"seed {int(seed)}")
        m, sem = mean[f"{name}_density_mean"].values, mean[f"{name}_density_sem"].fillna(0.0).values
        ax.stairs(m + 2 * sem, edges, baseline=np.maximum(m - 2 * sem, 0.0), fill=True, color="0.7", alpha=0.5,
                  label="mean ± 2 s.e.")
        ax.stairs(m, edges, color="k", lw=1.6, label=f"ensemble mean ({mean.sizes['seed']} seeds)")
    if kind == "sphere":
        x = np.linspace(0.0, 1.5, 101)
        left.plot(np.append(x, 1.5), np.append(8 * x / 9, 0.0), color="k", ls="--", lw=1, label="smooth sphere (Hertz): 8x/9")
    left.set(xlabel="p / p̄   (p̄ = F/A, the run's mean contact pressure)",
             ylabel="probability density over the contact")
    right.set(xlabel="g / h_rms", ylabel="probability density out of contact")
    fig.suptitle(f"{kind}: {where}, F/(E* L^2) = {float(first['histogram_force_normalized'][0]):.3g}", fontsize=9)
    legends = [legend_below(ax, gap=0.55, fontsize=7, ncol=2) for ax in (left, right)]   # under the densities
    layout_with_legends(fig, legends, left=0.7, right=0.2, bottom=0.55, top=0.4, wspace=0.8)
    save_png(fig, out_png)
    log.info("drew the mean histograms of load %d (%s) into %s", int(first["histogram_load"][0]), where, out_png)
