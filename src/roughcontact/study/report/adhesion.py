"""The report's adhesion figures: load–retract paths and the pull-off against roughness.

* ``paths``: per adhesive sphere combination, the force against the approach of every seed,
  loading (force-controlled, ``stiffness.nc``, solid) and retracting (``adhesion.nc``, dashed), one
  colour each, with JKR's pull-off ``−(3/2)πwR`` as a line;
* ``pull_off``: the pull-off over JKR's against Johnson's parameter ``h_rms/δ_c`` with the
  intervals over seeds, one marker per Hurst exponent, open where the run is below resolution
  (``pull_off.csv``'s ``resolved``: the method's own pull-off error above 3 %,
  :mod:`roughcontact.study.analysis.adhesion`); the paths figure names that error in the panel's
  title;
* the pull-off table's page (:func:`write_pull_off_page`): ``pull_off.csv`` with a lead that says how
  many combinations are below resolution and by the error of which relation.

Forces ``F/(E* L²)``, approaches in units of ``L``.
"""
from __future__ import annotations

import math

import numpy as np

from ...models.adhesion import jkr_pull_off
from ..analysis.adhesion import ERROR_CELLS, METHOD_ERRORS, RESOLVED_CELLS, RESOLVED_ERROR, resolved
from ..analysis.ensemble import combinations
from .plotting import MAX_CURVES, chunks, panel_grid, save_png
from ..config.settings import StudySettings

__all__ = ["paths_figure", "pull_off_figure", "resolution_note", "write_pull_off_page"]

#: most combinations drawn in the paths figure (the first ones of the sweep)
MAX_PANELS = 6


def _below(table, combo: dict) -> str:
    """``", below resolution: +11 %"`` for a combination of *table* that is not resolved, else ``""``."""
    if table is None or not len(table):
        return ""
    match = np.ones(len(table), dtype=bool)
    for axis, value in combo.items():
        if axis in table:
            match &= np.isclose(table[axis].to_numpy(float), value, rtol=1e-12, atol=0)
    rows = table[match & (table["kind"] == "sphere").to_numpy()]
    if not len(rows) or resolved(rows)[0]:
        return ""
    error = float(rows["method_error"].iloc[0]) if "method_error" in rows else math.nan
    return f", below resolution ({error:+.0%})" if math.isfinite(error) else ", below resolution"


def paths_figure(plt, adhesion: dict, stiffness: dict, study: StudySettings, path, table=None) -> None:
    """The ``paths`` figure (module docstring) of the merged adhesive runs *adhesion* and the loaded
    runs *stiffness* (``{kind: Dataset}``), *table* the pull-off table (``None``: no resolution note)."""
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
               title=f"H {combo['hurst']:g}, R {combo['radius']:g}, h {combo['h_rms']:g}, "
                     f"w {combo['work_of_adhesion']:g}{_below(table, combo)}")
        ax.title.set_fontsize(8)
        ax.legend(fontsize=6)
    for ax in list(panels.flat)[len(shown):]:
        ax.axis("off")
    if not shown:
        panels[0][0].text(0.5, 0.5, "no adhesive sphere runs", ha="center")
    fig.suptitle("loading (solid, blue) and retracting (dashed, red), every seed", fontsize=9)
    fig.tight_layout()
    save_png(fig, path)


def pull_off_figure(plt, table, path) -> None:
    """The ``pull_off`` figure (module docstring) of the pull-off *table* (``pull_off.csv``)."""
    spheres = table[table["kind"] == "sphere"] if len(table) else table
    series = list(spheres.groupby("hurst")) if len(spheres) else []
    # at most MAX_CURVES - 1 Hurst exponents a panel (JKR's line is on every panel)
    groups = chunks(enumerate(series), MAX_CURVES - 1)
    fig, panels = panel_grid(plt, len(groups), width=5.6, height=4.2, max_columns=2, sharey=True)
    for ax, group in zip(panels, groups):
        for j, (hurst, rows) in group:
            fine = resolved(rows)
            for keep, face in ((fine, f"C{j % 10}"), (~fine, "none")):   # open markers: below resolution
                if not keep.any():
                    continue
                part = rows[keep]
                y = part["pull_off_ratio"].to_numpy(float)
                err = np.abs(np.array([y - part["pull_off_ratio_ci_low"], part["pull_off_ratio_ci_high"] - y]))
                named = keep is fine or not fine.any()    # one legend entry per H
                ax.errorbar(part["johnson_parameter"], y, yerr=np.nan_to_num(err), fmt="o", color=f"C{j % 10}",
                            mfc=face, capsize=2, ms=4, label=f"H = {hurst:g}" if named else None)
        ax.axhline(1.0, color="k", lw=0.8, ls=":", label="smooth sphere (JKR)")
        ax.set(xscale="log", xlabel="h_rms / δ_c (Johnson)", ylabel="pull-off / JKR's −(3/2)πwR",
               title="pull-off of rough spheres (95 % interval over seeds)\nopen: below resolution (method's "
                     f"own error > {RESOLVED_ERROR:.0%})")
        ax.title.set_fontsize(9)
        if group:
            ax.legend(fontsize=7)
        else:
            ax.text(0.5, 0.5, "no adhesive sphere runs", ha="center", transform=ax.transAxes)
    fig.tight_layout()
    save_png(fig, path)


def resolution_note(table) -> str:
    """One sentence on the adhesive combinations of a pull-off *table* below resolution, for the
    pull-off page's lead."""
    if not len(table):
        return "No adhesive combination."
    fine = resolved(table)
    head = (f"{int((~fine).sum())} of {len(table)} adhesive combinations are below resolution"
            if (~fine).any() else f"Every adhesive combination ({len(table)}) is resolved")
    errors = table["method_error"].to_numpy(float) if "method_error" in table else np.full(len(table), np.nan)
    shown = errors[~fine & np.isfinite(errors)]
    span = (f" (the method's own pull-off error there {shown.min():+.1%} to {shown.max():+.1%})"
            if shown.size else "")
    return (f"{head}{span}: resolved means that the detachment criterion's own pull-off error, method_error, "
            f"is at most {RESOLVED_ERROR:.0%}, i.e. JKR's pull-off radius (jkr_radius_cells) spans at least "
            f"{RESOLVED_CELLS:.0f} cells; method_error is the error measured on the smooth sphere at "
            f"{', '.join(f'{c:g}' for c in ERROR_CELLS)} cells ({', '.join(f'{e:+.1%}' for e in METHOD_ERRORS)}; "
            "tests/test_adhesion_jkr_convergence.py, docs/guide/adhesion.md) interpolated in ln(cells), NaN below "
            f"{ERROR_CELLS[0]:g} cells and for a flat surface. Rows "
            "below resolution are kept and marked (resolved = False, open markers in the pull-off figure); claims "
            "(n)-(p) do not judge them (untested: unresolved, or left out and counted).")


def write_pull_off_page(csv_path, html_path) -> None:
    """The report's page of ``pull_off.csv``: the table (resolution columns first after the axes) and
    the lead of :data:`~roughcontact.study.report.tables.TABLE_PAGES` with :func:`resolution_note`."""
    import os

    import pandas as pd

    from .tables import TABLE_PAGES, write_html_table

    table = pd.read_csv(csv_path) if os.path.getsize(csv_path) > 1 else pd.DataFrame()
    title, lead = TABLE_PAGES["pull_off"]
    first = ("kind", "hurst", "radius", "h_rms", "work_of_adhesion", "resolved", "method_error", "jkr_radius_cells",
             "pull_off_ratio", "pull_off_ratio_ci_low", "pull_off_ratio_ci_high")
    write_html_table(table, html_path, title=title, lead=f"{lead} {resolution_note(table)}", verdict_columns=(),
                     first=first)
