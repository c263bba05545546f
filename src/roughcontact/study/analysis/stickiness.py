"""The stickiness runs merged (``stickiness.nc``) and their table (``stickiness.csv``).

The merged file has the runs' scalars over ``(hurst, number, seed)``
(:data:`roughcontact.study.files.runfile.STICKINESS_SCALARS`); each run's loading path, which ends where
its contact passes ``stickiness.area`` and so has a length of its own, stays in its run file
(``results/stickiness_run/``). The table has one row per (H, N):

* ``loading_slope`` — the mean over seeds of ``dF/dA`` in units of ``h′E*`` (negative: sticky), with
  its percentile bootstrap interval over seeds (``fit.bootstrap``, ``fit.confidence``);
* ``sticky_fraction`` — the fraction of seeds with a negative slope;
* ``pastewka_robbins_number``, ``range_ratio`` (``Δr/g₀``), ``interaction_range``, ``work_of_adhesion``,
  ``rms_curvature`` — means over seeds (the number is the sweep's own at every seed);
* ``predicted_sticky`` — Pastewka & Robbins' prediction, ``N < 1``;
* ``threshold`` — the measured number at which the surfaces of that H turn sticky: where the mean
  slope changes sign from below (at the smallest N) to above 0, interpolated linearly in ``ln N``
  between the two numbers around it (:func:`threshold`), with its interval from the same bootstrap
  over seeds (the same surfaces at every N, so each replicate takes the same seeds at every N);
  NaN where the sweep's slopes do not change sign (the same value on every row of that H);
* ``n``, ``n_seeds`` — the grid and the number of seeds.
"""
from __future__ import annotations

import math

import numpy as np

from ...errors import MergeError
from ..files import runfile
from ..config.axes import coordinate_attrs
from .merge import KindLayout, gather
from .statistics import bootstrap_indices, interval
from ..config.stickiness import StickinessSettings

__all__ = ["merge_stickiness", "stickiness_layout", "stickiness_table", "threshold"]

#: the number coordinate (hurst and seed: those of every merged file, coordinate_attrs)
NUMBER_ATTRS = {"long_name": "Pastewka & Robbins' number N of the sweep", "units": "1"}


def merge_stickiness(s: StickinessSettings, paths):
    """The scalars of the stickiness run files *paths* (one per :meth:`StickinessSettings.jobs`, in
    its order) as one Dataset (module docstring). Each is read by
    :func:`roughcontact.study.files.io.read_run` against its :class:`~.settings.StickinessRun`, which raises
    :class:`~roughcontact.errors.MergeError` naming a file that is missing, not a stickiness run or
    computed with other settings (its ``config_hash``)."""
    import xarray as xr

    jobs = s.jobs()
    if len(paths) != len(jobs):
        raise MergeError(f"the stickiness merge got {len(paths)} run files for {len(jobs)} runs")
    data = gather(stickiness_layout(s, paths), lambda row: s.run(**row),
                  {name: meta.dtype for name, meta in runfile.STICKINESS_SCALARS.items()}).data
    dims = ("hurst", "number", "seed")
    meta = runfile.STICKINESS_SCALARS
    return xr.Dataset({name: (dims, values, {"long_name": meta[name].long_name, "units": meta[name].units})
                       for name, values in data.items()},
                      coords={"hurst": ("hurst", np.array(s.hurst), coordinate_attrs("hurst")),
                              "number": ("number", np.array(s.number), NUMBER_ATTRS),
                              "seed": ("seed", np.arange(s.seeds), coordinate_attrs("seed"))},
                      attrs={"grid_n": s.n, "area": s.area, "cutoff_cells": s.cutoff})


def stickiness_layout(s: StickinessSettings, paths) -> KindLayout:
    """The :class:`~roughcontact.study.analysis.merge.KindLayout` of the sweep's runs (one path of *paths*
    per :meth:`StickinessSettings.jobs`, in its order): flat surfaces over ``hurst, number`` and
    ``seed``, each row a dict of its run's ``hurst``, ``number`` and ``seed``."""
    rows = [({"hurst": job.hurst, "number": job.number, "seed": job.seed}, path) for job, path in zip(s.jobs(), paths)]
    return KindLayout(kind="flat", rows=rows, axes=("hurst", "number"),
                      coords={"hurst": list(s.hurst), "number": list(s.number), "seed": list(range(s.seeds))},
                      at={id(row): {"hurst": row["hurst"], "number": row["number"]} for row, _ in rows})


def threshold(numbers, slopes) -> float:
    """The number where the mean *slopes* (one per N of the increasing *numbers*) first change sign
    from negative to positive, interpolated linearly in ``ln N``; NaN where they do not."""
    numbers, slopes = np.asarray(numbers, float), np.asarray(slopes, float)
    for k in range(1, numbers.size):
        if slopes[k - 1] < 0.0 <= slopes[k]:
            t = slopes[k - 1] / (slopes[k - 1] - slopes[k])
            return float(math.exp((1.0 - t) * math.log(numbers[k - 1]) + t * math.log(numbers[k])))
    return math.nan


def stickiness_table(ds, s: StickinessSettings):
    """``stickiness.csv`` (module docstring) of the merged runs *ds*."""
    import pandas as pd

    indices = bootstrap_indices(s.seeds, s.bootstrap)
    rows = []
    for i, hurst in enumerate(s.hurst):
        slopes = ds["loading_slope"].values[i]                          # (number, seed)
        replicates = slopes[:, indices].mean(-1)                         # (number, resample)
        measured = threshold(s.number, slopes.mean(-1))
        low, high = interval(np.array([threshold(s.number, r) for r in replicates.T]), s.confidence)
        crossing = {"threshold": measured, "threshold_ci_low": low, "threshold_ci_high": high}
        for j, number in enumerate(s.number):
            slope = slopes[j]                                            # (seed,)
            low, high = interval(replicates[j], s.confidence)
            finite = slope[np.isfinite(slope)]
            rows.append({
                "hurst": hurst, "number": number, "loading_slope": float(np.mean(slope)),
                "loading_slope_ci_low": low, "loading_slope_ci_high": high,
                "sticky_fraction": float(np.mean(finite < 0)) if finite.size else math.nan,
                **{name: float(ds[name].values[i, j].mean())
                   for name in ("pastewka_robbins_number", "range_ratio", "interaction_range", "work_of_adhesion",
                                "rms_curvature")},
                "rms_slope": s.rms_slope, "predicted_sticky": bool(number < 1), **crossing, "n": s.n,
                "n_seeds": s.seeds,
            })
    return pd.DataFrame(rows)
