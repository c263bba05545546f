"""The tangential runs' figures in the report (rules ``tangential_figures`` and ``partial_slip_figures``,
:mod:`roughcontact.study.rules.tangential_figures`):

* :func:`ratio_figure` — ``ratio``: the ensemble's full-stick ``k_t/k_n`` against the
  normal force with its interval, Mindlin's ``2(1 − ν)/(2 − ν)`` as a line and ``F_tr`` marked, one
  panel per sphere combination, one colour per ``ν``; with friction, ``slip``: ``k_t(Q)/k_t(0)``
  against ``Q/μP`` at each slip load (at most :data:`~roughcontact.study.report.plotting.MAX_CURVES`
  per panel) beside Cattaneo–Mindlin's ``(1 − Q/μP)^(1/3)`` and, dotted, Ciavarella–Jäger's from the
  normal path (:func:`slip_figure`); and ``micro_slip`` (:func:`micro_slip_figure`): the largest
  micro-slip against Grzemba et al.'s ``μ d E*/G*``.

Forces ``F/(E* L²)``, stiffnesses ``k/(E* L)``.
"""
from __future__ import annotations

import numpy as np

from ...models import tangential as theory
from ..analysis import tangential as estimate
from .plotting import MAX_CURVES, chunks, panel_grid, save_png

__all__ = ["ratio_figure", "slip_figure", "micro_slip_figure"]

#: most panels of a figure (the first combinations of the sweep)
MAX_PANELS = 6


def _label(where: dict) -> str:
    return f"H = {where['hurst']:g}, R = {where['radius']:g}, h_rms = {where['h_rms']:g}"


def ratio_figure(plt, table, path) -> None:
    """The ``ratio`` figure (module docstring) of ``tangential.csv`` (*table*) to *path* (PNG)."""
    normal = [c for c in table.columns if c not in ("poisson", "force", "branch", "crossover_force", "kt_over_kn",
                                                    "ci_low", "ci_high", "mindlin", "rel_dev")]
    groups = list(table.groupby(normal, sort=False))[:MAX_PANELS]
    fig, panels = panel_grid(plt, len(groups), width=4.6, height=3.6)
    for ax, (key, sub) in zip(panels, groups):
        where = dict(zip(normal, key if isinstance(key, tuple) else (key,)))
        for i, (nu, curve) in enumerate(list(sub.groupby("poisson"))[:MAX_CURVES]):
            colour = f"C{i}"
            ok = curve["branch"] != "unresolved"
            ax.errorbar(curve["force"][ok], curve["kt_over_kn"][ok],
                        yerr=[curve["kt_over_kn"][ok] - curve["ci_low"][ok], curve["ci_high"][ok] - curve["kt_over_kn"][ok]],
                        color=colour, marker="o", ms=3, lw=1, label=f"nu = {nu:g}")
            ax.plot(curve["force"][~ok], curve["kt_over_kn"][~ok], color=colour, marker="o", ms=3, lw=0, mfc="none")
            ax.axhline(float(curve["mindlin"].iloc[0]), color=colour, ls="--", lw=0.8)
        f_tr = float(sub["crossover_force"].iloc[0])
        if np.isfinite(f_tr):
            ax.axvline(f_tr, color="0.5", ls=":", lw=1)
        ax.set_xscale("log")
        ax.set_xlabel("F/(E* L²)")
        ax.set_ylabel("k_t/k_n")
        ax.set_title(_label(where), fontsize=9)
        ax.legend(fontsize=7, title="dashed: Mindlin; dotted: F_tr", title_fontsize=7)
    fig.tight_layout()
    save_png(fig, path)


def slip_figure(plt, groups: dict, path) -> None:
    """The ``slip`` figure (module docstring) of ``tangential.nc`` (*groups*) to *path* (PNG)."""
    panels_data = []
    for where, stick, slip in estimate.slip_combinations(groups):
        loads = list(range(slip.sizes["slip_load"]))
        for part in chunks(loads, MAX_CURVES):
            panels_data.append((where, stick, slip, part))
    panels_data = panels_data[:MAX_PANELS]
    fig, panels = panel_grid(plt, len(panels_data), width=4.6, height=3.6)
    f_line = np.linspace(0, 1, 101)
    for ax, (where, stick, slip, part) in zip(panels, panels_data):
        f = slip["slip_step"].values
        index = slip["slip_load_index"].values
        k_t0 = stick["tangential_stiffness"].values
        for c, j in enumerate(part):
            i = int(index[j])
            measured = slip["slip_stiffness"].values[:, j, :].mean(0) / k_t0[:, i].mean()
            cj = estimate.ciavarella_jaeger(stick, i, f).mean(0) / stick["stiffness"].values[:, i].mean()
            ax.plot(f, measured, color=f"C{c}", marker="o", ms=2.5, lw=1,
                    label=f"F = {slip['slip_load'].values[j]:.2g}")
            ax.plot(f, cj, color=f"C{c}", ls=":", lw=1)
        ax.plot(f_line, theory.cattaneo_stiffness_ratio(f_line), color="k", ls="--", lw=1)
        ax.set_xlabel("Q/(mu P)")
        ax.set_ylabel("k_t(Q)/k_t(0)")
        ax.set_title(f"{_label(where)}, nu = {where['poisson']:g}, mu = {where['friction']:g}", fontsize=8)
        ax.legend(fontsize=6, title="dashed: Cattaneo-Mindlin; dotted: C-J", title_fontsize=6)
    fig.tight_layout()
    save_png(fig, path)


def micro_slip_figure(plt, groups: dict, path) -> None:
    """The ``micro_slip`` figure (module docstring) of ``tangential.nc`` (*groups*) to *path* (PNG)."""
    fig, ax = plt.subplots(figsize=(4.8, 4.0))
    lows, highs = [], []
    for c, (where, _, slip) in enumerate(list(estimate.slip_combinations(groups))[:MAX_CURVES]):
        depth = slip["slip_depth"].values.mean(0)
        law = theory.largest_micro_slip(depth, friction=where["friction"], poisson=where["poisson"])
        delta = slip["gross_slip_displacement"].values.mean(0)
        ax.plot(law, delta, marker="o", ms=3.5, lw=0, color=f"C{c}",
                label=f"{_label(where)}, nu = {where['poisson']:g}, mu = {where['friction']:g}")
        lows.append(min(law.min(), delta.min()))
        highs.append(max(law.max(), delta.max()))
    if lows:
        line = np.array([min(lows), max(highs)])
        ax.plot(line, line, color="k", ls="--", lw=1, label="Grzemba et al.: delta_max = mu d E*/G*")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("mu d E*/G*  (L)")
    ax.set_ylabel("largest micro-slip delta_max  (L)")
    ax.legend(fontsize=6)
    fig.tight_layout()
    save_png(fig, path)
