"""Grid convergence of one sphere combination run on several grids at the same loads.

Each study directory holds a finished run of the same sphere (H, R, h_rms, L, E*) and force
grid on a different ``n`` (``presets/convergence-*.yaml``, ``presets/paper-fine.yaml``).
:func:`summary` collects, per grid, the quantities the verdicts rest on (ζ fitted from the
sphere's fractal branch, eq. 16's ζ from the prefactor B, F_tr, the low-force slope, each with
its 95 % bootstrap-over-seeds interval) and the cost of one indent job (Snakemake's
benchmark files: wall seconds and peak resident memory). :func:`stiffness_ratios` compares
the ensemble-mean stiffness of every grid with that of the finest grid at each common load,
``k_n(F)/k_finest(F) − 1``, with a percentile interval from resampling the seeds of both
grids independently (the surfaces of different grids are independent realisations);
:func:`against_eq16` compares every study's ensemble mean with eq. 16 instead, one
deterministic reference, so that two ensembles of one grid can stand side by side. Forces
are ``F/(E* L²)``, stiffnesses ``k/(E* L)``. :func:`resolved_range` says how many decades of
force below the measured crossover each grid resolves.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..files.directory import StudyDirectory
from .statistics import BOOTSTRAP_SEED, interval

__all__ = ["summary", "stiffness_ratios", "against_eq16", "resolved_range", "RESOLVED_CELLS"]

#: Mean contact cells from which a load counts as resolved: the grid error of the ensemble mean is
#: at most 6 % from 20 cells and below 1 % from 150 on (docs/guide/pipeline.md, "How the grid error
#: falls with the contact's cells").
RESOLVED_CELLS = (20, 150)


def _sphere(study: Path):
    """The sphere group of *study*'s stiffness.nc, its axes of length one dropped, and the grid n."""
    results = StudyDirectory(study)
    attrs = results.attrs("stiffness")
    n = int(attrs["grid_n"])
    length, e_star = float(attrs.get("grid_length", 1.0)), float(attrs.get("e_star", 1.0))
    groups = results.groups("stiffness")
    if "sphere" not in groups:
        raise ValueError(f"{study}: no sphere runs in {results.path('stiffness')}")
    ds = groups["sphere"]
    axes = [d for d in ds["stiffness"].dims if d not in ("seed", "force")]
    if any(ds.sizes[a] != 1 for a in axes):
        raise ValueError(f"{study}: a convergence study holds one sphere combination, got axes {axes}")
    ds = ds.isel({a: 0 for a in axes}).transpose("seed", "force")
    return ds.assign_coords(force=ds["force"] / (e_star * length**2)).assign(
        stiffness=ds["stiffness"] / (e_star * length)), n


def summary(studies):
    """One row per study (sorted by n): grid, seeds, the fitted quantities with their
    intervals, the ζ fit window and the median wall time and largest peak memory of a job."""
    import pandas as pd

    rows = []
    for study in map(Path, studies):
        results = StudyDirectory(study)
        zeta = results.table("zeta").iloc[0]
        cross = results.table("crossover").iloc[0]
        ds, n = _sphere(study)
        row = {"n": n, "seeds": ds.sizes["seed"]}
        for name, table, ci in (("zeta", zeta, "zeta"), ("zeta_sphere", cross, "zeta_sphere"),
                                ("Ftr_measured", cross, "Ftr"), ("slope_low", cross, "slope_low")):
            row.update({name: table[name], f"{name}_ci_low": table[f"{ci}_ci_low"],
                        f"{name}_ci_high": table[f"{ci}_ci_high"]})
        row.update(zeta_window_force_min=zeta["force_min"], zeta_window_force_max=zeta["force_max"],
                   zeta_window_points=int(zeta["n_points"]))
        bench = results.benchmarks("indent")
        row.update(job_wall_s_median=float(np.nanmedian([b["s"] for b in bench])) if bench else math.nan,
                   job_peak_rss_mb_max=float(np.nanmax([b["max_rss"] for b in bench])) if bench else math.nan)
        row["study"] = study.name
        rows.append(row)
    return pd.DataFrame(rows).sort_values("n", ignore_index=True)


def stiffness_ratios(studies, *, resamples: int = 1000, level: float = 0.95):
    """``k_n/k_finest − 1`` of the ensemble means at every load a study shares with the finest
    one, with its interval and the mean contact cells (module docstring); one row per (n, F)
    of every grid but the finest. One study per grid."""
    import pandas as pd

    data = {}
    for study in map(Path, studies):
        ds, n = _sphere(study)
        if n in data:
            raise ValueError(f"two studies on {n}^2 ({study.name} and another): give one study per grid")
        data[n] = ds
    if len(data) < 2:
        raise ValueError(f"a convergence table needs studies on at least two grids, got {len(data)}")
    finest = max(data)
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    ref = data[finest]
    rows = []
    for n, ds in sorted(data.items()):
        if n == finest:
            continue
        forces = np.intersect1d(np.round(ds["force"].values, 15), np.round(ref["force"].values, 15))
        for force in forces:
            k = ds["stiffness"].sel(force=force, method="nearest").values
            k_ref = ref["stiffness"].sel(force=force, method="nearest").values
            cells = float(ds["contact_cells"].sel(force=force, method="nearest").values.mean())
            boot = (k[rng.integers(0, k.size, (resamples, k.size))].mean(1)
                    / k_ref[rng.integers(0, k_ref.size, (resamples, k_ref.size))].mean(1) - 1)
            low, high = interval(boot, level)
            rows.append({"n": n, "force": float(force), "k_mean": float(k.mean()),
                         "ratio_to_finest_minus_1": float(k.mean() / k_ref.mean() - 1),
                         "ci_low": low, "ci_high": high, "contact_cells": cells, "finest_n": finest})
    return pd.DataFrame(rows)


def against_eq16(studies, *, resamples: int = 1000, level: float = 0.95):
    """``k̄/k_16 − 1`` per study and load: the ensemble mean against eq. 16 with ζ = 1.7/(H+1)
    (a deterministic reference, so each interval is that of the study's own seeds), with the
    mean contact cells; one row per (study, F). Studies on the same grid are allowed (two
    ensembles of one grid tell sampling from resolution)."""
    import pandas as pd

    from ...models import paper

    rng = np.random.default_rng(BOOTSTRAP_SEED)
    rows = []
    for study in map(Path, studies):
        ds, n = _sphere(study)
        hurst, radius, h_rms = (float(ds[a]) for a in ("hurst", "radius", "h_rms"))
        force = ds["force"].values
        k16 = paper.stiffness_from_force(force, radius=radius, hurst=hurst, h_rms=h_rms, length=1.0, e_star=1.0,
                                         zeta=float(paper.zeta_estimate(hurst)))
        k = ds["stiffness"].values                                    # (seed, force), normalised
        boot = k[rng.integers(0, k.shape[0], (resamples, k.shape[0]))].mean(1) / k16 - 1
        cells = ds["contact_cells"].values.mean(0)
        for j, f in enumerate(force):
            low, high = interval(boot[:, j], level)
            rows.append({"study": study.name, "n": n, "seeds": k.shape[0], "force": float(f),
                         "contact_cells": float(cells[j]), "k_over_eq16_minus_1": float(k[:, j].mean() / k16[j] - 1),
                         "ci_low": low, "ci_high": high})
    return pd.DataFrame(rows)


def _force_at_cells(force, cells, target: float) -> tuple[float, bool]:
    """The force at which the mean contact cells reach *target*, interpolated in log-log between
    the loads around it, or extrapolated with the slope of the first two loads when the first
    load already has more (then ``True``: extrapolated); ``nan`` if no load reaches it."""
    log_f, log_c = np.log(force), np.log(np.maximum(cells, 1e-300))
    above = np.flatnonzero(cells >= target)
    if above.size == 0:
        return math.nan, False
    j = int(above[0])
    if j == 0:
        slope = (log_c[1] - log_c[0]) / (log_f[1] - log_f[0])
        return float(np.exp(log_f[0] + (math.log(target) - log_c[0]) / slope)), True
    t = (math.log(target) - log_c[j - 1]) / (log_c[j] - log_c[j - 1])
    return float(np.exp(log_f[j - 1] + t * (log_f[j] - log_f[j - 1]))), False


def resolved_range(studies, *, cells=RESOLVED_CELLS):
    """How much of the fractal branch each study resolves: per study and threshold of mean contact
    cells (:data:`RESOLVED_CELLS`), the force ``F_c`` at which the ensemble's mean contact reaches
    it (:func:`_force_at_cells`; ``extrapolated`` below the study's first load), the measured
    crossover ``F_tr`` of eq. 16 (crossover.csv) and ``decades_below_Ftr = log10(F_tr/F_c)``, the
    decades of force of the fractal branch that the grid resolves (negative: not even the crossover)."""
    import pandas as pd

    rows = []
    for study in map(Path, studies):
        ds, n = _sphere(study)
        crossover = StudyDirectory(study).table("crossover").iloc[0]
        ftr = float(crossover["Ftr_measured"])
        force, mean_cells = ds["force"].values, ds["contact_cells"].values.mean(0)
        for threshold in cells:
            f_c, extrapolated = _force_at_cells(force, mean_cells, float(threshold))
            rows.append({"study": study.name, "n": n, "seeds": ds.sizes["seed"], "cells": int(threshold),
                         "force_resolved": f_c, "extrapolated": extrapolated, "Ftr_measured": ftr,
                         "decades_below_Ftr": math.log10(ftr / f_c) if f_c > 0 else math.nan})
    return pd.DataFrame(rows)
