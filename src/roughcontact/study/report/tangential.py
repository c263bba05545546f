"""The tangential runs in the report: the ``tangential`` rule's files and the report's figures.

* :func:`run_tangential` — the run files and ``crossover.csv`` -> ``tangential.nc``
  (:func:`roughcontact.study.analysis.tangential.merge_tangential`), ``tangential.csv``
  (:func:`~roughcontact.study.analysis.tangential.per_load_table`) and its page;
* :func:`make_tangential_figures` — ``ratio``: the ensemble's full-stick ``k_t/k_n`` against the
  normal force with its interval, Mindlin's ``2(1 − ν)/(2 − ν)`` as a line and ``F_tr`` marked, one
  panel per sphere combination, one colour per ``ν``; with friction, ``slip``: ``k_t(Q)/k_t(0)``
  against ``Q/μP`` at each slip load (at most :data:`~roughcontact.study.report.plotting.MAX_CURVES`
  per panel) beside Cattaneo–Mindlin's ``(1 − Q/μP)^(1/3)`` and, dotted, Ciavarella–Jäger's from the
  normal path; and ``micro_slip``: the largest micro-slip against Grzemba et al.'s ``μ d E*/G*``.

Forces ``F/(E* L²)``, stiffnesses ``k/(E* L)``.
"""
from __future__ import annotations

import logging

import numpy as np

from ...models import tangential as theory
from ..analysis import tangential as estimate
from ..config.settings import StudySettings
from ..files import provenance
from .plotting import MAX_CURVES, chunks, panel_grid, pyplot, save_png
from .tables import csv_to_html

__all__ = ["run_tangential", "make_tangential_figures"]

log = logging.getLogger(__name__)

#: most panels of a figure (the first combinations of the sweep)
MAX_PANELS = 6


def _crossover(crossover_csv):
    from ..files.io import read_csv

    return read_csv(crossover_csv)


def run_tangential(study, run_files, crossover_csv, out_nc, out_csv, out_html) -> None:
    """``tangential`` rule (module docstring)."""
    from ..files.io import write_csv, write_groups

    study = StudySettings.of(study)
    groups = estimate.merge_tangential(study, list(run_files))
    attrs = provenance.provenance_attrs(
        config=study.config, title="roughcontact parameter study: tangential contact of the sphere runs",
        layout="groups full_stick (per load) and partial_slip (friction > 0)", grid_n=study.grid.n,
        grid_length=study.grid.length, e_star=study.e_star, seeds=list(study.seeds))
    write_groups(out_nc, groups, attrs)
    table = estimate.per_load_table(groups, _crossover(crossover_csv), study)
    write_csv(table, out_csv, reason="no tangential run has a full-stick stiffness (no sphere with a poisson ratio)")
    csv_to_html(out_csv, out_html, "tangential")
    log.info("merged the tangential runs (%s) into %s; %d rows in %s", ", ".join(groups), out_nc, len(table), out_csv)


def _label(where: dict) -> str:
    return f"H = {where['hurst']:g}, R = {where['radius']:g}, h_rms = {where['h_rms']:g}"


def _ratio_figure(plt, table, path) -> None:
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


def _slip_figure(plt, groups: dict, path) -> None:
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


def _micro_slip_figure(plt, groups: dict, path) -> None:
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


def make_tangential_figures(study, tangential_nc, tangential_csv, out_ratio=None, out_slip=None, out_micro_slip=None):
    """``tangential_figures`` (*out_ratio*) and ``partial_slip_figures`` (*out_slip*,
    *out_micro_slip*; friction only) rules: the figures of the module docstring that are asked for."""
    import pandas as pd

    from ..files.io import read_groups

    plt = pyplot()
    if out_ratio:
        _ratio_figure(plt, pd.read_csv(tangential_csv), out_ratio)
    if out_slip or out_micro_slip:
        groups = read_groups(tangential_nc)
        if out_slip:
            _slip_figure(plt, groups, out_slip)
        if out_micro_slip:
            _micro_slip_figure(plt, groups, out_micro_slip)
