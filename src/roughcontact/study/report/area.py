"""The real contact area's page, table and figure (drawn for the ``area`` rule,
:mod:`roughcontact.study.rules.area`): the area scorecard of
:func:`roughcontact.study.analysis.area.area_scorecard` as ``area/area_models.csv`` and its HTML page,
and ``area/area.png``, the ensemble's ``A(F)`` of every sphere combination against Hertz's ``π a²``,
the linear law (κ = 2) and Persson's area. Claims (u)-(w) on the area are rows of the claims table
(:mod:`roughcontact.study.claims.area`)."""
from __future__ import annotations

import logging
import math

import numpy as np

from ...models import area as area_models
from ...models.area.laws import SIMULATION_KAPPA, hertz_area, linear_area
from ..analysis.area import AREA_TOLERANCE, MEASURED_ON, area_scorecard
from ..config.settings import StudySettings
from .plotting import data_limits, edge_mark, layout_with_legends, legend_below, panel_grid, pyplot, save_png
from .tables import write_html_table

__all__ = ["NO_AREA", "area_lead", "area_figure", "no_area_figure", "no_area_reason"]

log = logging.getLogger(__name__)

#: why area_models.csv has no row where the sweep has an elastic, adhesion-free sphere (its runs left none)
NO_AREA = "no elastic, adhesion-free sphere combination in the merged runs"


def no_area_reason(study) -> str:
    """Why the area scorecard of *study* has no row, in the words of the sweep at hand: it has no
    sphere (every radius .inf); every sphere combination is adhesive, plastic, or either; else
    :data:`NO_AREA`."""
    from ..runs import naming as runs

    study = StudySettings.of(study)
    if not any(math.isfinite(r) for r in study.radius):
        return "the sweep has no sphere (every radius is .inf): the area figure compares rough spheres with Hertz's area"
    spheres = [c for c in runs.combinations(study) if c["kind"] == "sphere"]
    sticky = [float(c.get("work_of_adhesion") or 0.0) > 0 for c in spheres]
    plastic = [c.get("hardness") is not None and math.isfinite(float(c["hardness"])) for c in spheres]
    if spheres and all(a or p for a, p in zip(sticky, plastic)):
        kind = ("adhesive (work_of_adhesion > 0)" if all(sticky) else "plastic (a finite hardness)" if all(plastic)
                else "adhesive (work_of_adhesion > 0) or plastic (a finite hardness)")
        return f"every sphere combination of the sweep is {kind}: the area models are elastic and adhesion-free"
    return NO_AREA


def area_lead() -> str:
    """The lead paragraph of the area scorecard page (the registered area models' summaries)."""
    summaries = "; ".join(m.summary for m in area_models.models().values())
    return ("Each model predicts the real contact area A(F) of the rough sphere from the surface's parameters "
            "(h'_rms = sqrt(<|grad h|^2>) of the grid's spectrum, column rms_slope); max_rel_dev is the largest "
            "|A_model/A_BEM - 1| over the area-resolved loads of the ensemble mean (the ensemble-mean contact cells "
            f"reach min_area_cells, measured for a {AREA_TOLERANCE:.0%} area error by the grid study, "
            f"{MEASURED_ON}, docs/guide/area.md), with its 95 % bootstrap-over-seeds interval; rms_rel_dev the rms "
            "of the same deviations, rank orders the models by it; systematic_low and systematic_high the mean "
            "deviation (each load weighted by the inverse variance of the ensemble mean there) below and above "
            "the area crossover F_A (crossover_force, F/(E* L^2), where 2 F/(E* h'_rms) = pi a^2) with its "
            "interval and verdict on 0; inside_band the fraction of loads inside the ensemble's band. A "
            "combination without an area-resolved load keeps one row per model whose note says "
            f"why. {summaries}. area_models.csv holds every digit.")


def area_figure(path, curves: dict, study) -> None:
    """``A(F)/L²`` of the ensemble mean of every sphere combination (one panel each; filled markers the
    area-resolved loads, open the others) against Hertz's ``π a²``, the linear law ``2 F/(E* h′_rms)``
    and the area models, with the crossover ``F_A`` marked (labelled; an arrow at the edge where it
    lies beyond the loads); Hertz's area and ``F_A`` only on a paraboloid (body exponent 2). The axes hold the measured areas and loads; every panel's legend lies
    under it."""
    study = StudySettings.of(study)
    plt = pyplot()
    norm_f, norm_a = study.e_star * study.grid.length**2, study.grid.length**2
    fig, panels = panel_grid(plt, len(curves), width=4.2, height=3.4)
    legends = []
    for ax, (label, c) in zip(panels, curves.items()):
        force = np.asarray(c["force"], dtype=float)
        ok = np.asarray(c["resolved"], dtype=bool)
        area = np.asarray(c["area"], dtype=float)
        paraboloid = float(c.get("exponent", 2.0)) == 2.0   # Hertz's area and F_A are a paraboloid's
        if ok.any():
            ax.loglog(force[ok] / norm_f, area[ok] / norm_a, "o", color="k", ms=4, label="BEM, area-resolved")
        if (~ok).any():
            ax.loglog(force[~ok] / norm_f, area[~ok] / norm_a, "o", mfc="none", color="0.5", ms=4,
                      label="BEM, area under-resolved")
        fine = np.geomspace(force.min(), force.max(), 200)
        if paraboloid:
            ax.loglog(fine / norm_f, hertz_area(fine, radius=c["radius"], e_star=study.e_star) / norm_a, "--",
                      color="C0", label="Hertz pi a^2")
        ax.loglog(fine / norm_f, linear_area(fine, e_star=study.e_star, rms_slope=c["rms_slope"]) / norm_a, ":",
                  color="C1", label=f"{SIMULATION_KAPPA:g} F/(E* h'_rms)")
        for i, (name, predicted) in enumerate(c["models"].items()):
            ax.loglog(force / norm_f, np.asarray(predicted) / norm_a, "-", lw=1, color=f"C{i + 2}", label=name)
        xlim, ylim = data_limits(force / norm_f, area / norm_a, pad=1.3)
        if xlim:
            ax.set_xlim(xlim)
        if ylim:
            ax.set_ylim(ylim)
        if paraboloid and math.isfinite(c["crossover_force"]):
            edge_mark(ax, c["crossover_force"] / norm_f, "F_A", color="0.6", ls="-", lw=0.8,
                      label=f"F_A = {c['crossover_force'] / norm_f:.2g}: Hertz = linear law")
        body = "" if paraboloid else f", m = {float(c['exponent']):g}: no Hertz area"
        ax.set(title=f"{label} (resolved: >= {c['min_cells']:g} cells{body})", xlabel="F/(E* L^2)", ylabel="A/L^2")
        ax.title.set_fontsize(8)
        legends.append(legend_below(ax, gap=0.55, fontsize=6))
    layout_with_legends(fig, legends, left=0.75, right=0.2, bottom=0.55, top=0.3, wspace=0.8, hspace=0.85)
    save_png(fig, path)


def no_area_figure(path, reason: str = NO_AREA) -> None:
    """A PNG saying why the sweep has no area figure (*reason*: :func:`no_area_reason`)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(4, 1.5))
    ax.axis("off")
    ax.text(0.5, 0.5, reason, ha="center", va="center", fontsize=8, wrap=True)
    save_png(fig, path)
