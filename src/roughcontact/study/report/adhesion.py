"""The report's adhesion figures: load–retract paths and the pull-off against roughness.

* ``paths``: per adhesive sphere combination, the force against the approach of every seed,
  loading (force-controlled, ``stiffness.nc``, solid) and retracting (``adhesion.nc``, dashed), one
  colour each, with JKR's pull-off ``−(3/2)πwR`` as a line;
* ``pull_off``: the pull-off over JKR's against Johnson's parameter ``h_rms/δ_c`` with the
  intervals over seeds, one marker per Hurst exponent.

Forces ``F/(E* L²)``, approaches in units of ``L``.
"""
from __future__ import annotations

import math

import numpy as np

from ...models.adhesion import jkr_pull_off
from ..analysis.ensemble import combinations
from .plotting import MAX_CURVES, chunks, panel_grid, pyplot, save_png
from ..config.settings import StudySettings

__all__ = ["make_adhesion_figures"]

#: most combinations drawn in the paths figure (the first ones of the sweep)
MAX_PANELS = 6


def _paths(plt, adhesion: dict, stiffness: dict, study: StudySettings, path) -> None:
    ds = adhesion.get("sphere")
    loaded = stiffness.get("sphere")
    E, L = study.e_star, study.grid.length
    combos = []
    if ds is not None:
        combos = [where for where, _ in combinations(ds, "pull_off_force", ("seed",))]
    shown = combos[:MAX_PANELS]
    cols = min(3, max(1, len(shown)))
    rows = max(1, math.ceil(len(shown) / cols))
    fig, panels = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    for ax, combo in zip(panels.flat, shown):
        sub, run = ds.sel(combo), loaded.sel(combo)
        # the seeds are replicates: one colour for loading and one for retracting, every seed drawn
        # (not a colour per seed: eight seeds would be sixteen curves to tell apart)
        for i, seed in enumerate(sub["seed"].values):
            ax.plot(run["depth"].sel(seed=seed) / L, run["force"].values / (E * L**2), "-", color="C0", lw=0.8,
                    alpha=0.7, label="loading, every seed" if i == 0 else None)
            ax.plot(sub["retract_depth"].sel(seed=seed) / L, sub["retract_force"].sel(seed=seed) / (E * L**2), "--",
                    color="C3", lw=0.8, alpha=0.7, label="retracting, every seed" if i == 0 else None)
        jkr = jkr_pull_off(radius=combo["radius"], e_star=E, work_of_adhesion=combo["work_of_adhesion"])[0] / (E * L**2)
        ax.axhline(jkr, color="k", lw=0.8, ls=":", label="JKR −(3/2)πwR")
        ax.axhline(0, color="0.6", lw=0.5)
        ax.set(xlabel="approach d / L", ylabel="F / (E* L²)",
               title=f"H {combo['hurst']:g}, R {combo['radius']:g}, h {combo['h_rms']:g}, w {combo['work_of_adhesion']:g}")
        ax.title.set_fontsize(8)
        ax.legend(fontsize=6)
    for ax in list(panels.flat)[len(shown):]:
        ax.axis("off")
    if not shown:
        panels[0][0].text(0.5, 0.5, "no adhesive sphere runs", ha="center")
    fig.suptitle("loading (solid, blue) and retracting (dashed, red), every seed", fontsize=9)
    fig.tight_layout()
    save_png(fig, path)


def _pull_off(plt, table, path) -> None:
    spheres = table[table["kind"] == "sphere"] if len(table) else table
    series = list(spheres.groupby("hurst")) if len(spheres) else []
    # at most MAX_CURVES - 1 Hurst exponents a panel (JKR's line is on every panel)
    groups = chunks(enumerate(series), MAX_CURVES - 1)
    fig, panels = panel_grid(plt, len(groups), width=5.6, height=4.2, max_columns=2, sharey=True)
    for ax, group in zip(panels, groups):
        for j, (hurst, rows) in group:
            y = rows["pull_off_ratio"].to_numpy(float)
            err = np.abs(np.array([y - rows["pull_off_ratio_ci_low"], rows["pull_off_ratio_ci_high"] - y]))
            ax.errorbar(rows["johnson_parameter"], y, yerr=np.nan_to_num(err), fmt="o", color=f"C{j % 10}", capsize=2,
                        ms=4, label=f"H = {hurst:g}")
        ax.axhline(1.0, color="k", lw=0.8, ls=":", label="smooth sphere (JKR)")
        ax.set(xscale="log", xlabel="h_rms / δ_c (Johnson)", ylabel="pull-off / JKR's −(3/2)πwR",
               title="pull-off of rough spheres (95 % interval over seeds)")
        ax.title.set_fontsize(9)
        if group:
            ax.legend(fontsize=7)
        else:
            ax.text(0.5, 0.5, "no adhesive sphere runs", ha="center", transform=ax.transAxes)
    fig.tight_layout()
    save_png(fig, path)


def make_adhesion_figures(study, adhesion_nc, stiffness_nc, pull_off_csv, out_paths, out_pull_off) -> None:
    """``adhesion_figures`` rule: the paths figure and the pull-off figure (module docstring)."""
    import pandas as pd

    from ..files.io import read_groups

    study = StudySettings.of(study)
    plt = pyplot()
    _paths(plt, read_groups(adhesion_nc), read_groups(stiffness_nc), study, out_paths)
    _pull_off(plt, pd.read_csv(pull_off_csv), out_pull_off)
