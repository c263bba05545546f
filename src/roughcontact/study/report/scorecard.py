"""The model scorecard's page and figures (the ``models`` rule, :mod:`roughcontact.study.rules.models`):
what :func:`roughcontact.study.analysis.scorecard.scorecard` measures, drawn for the report."""
from __future__ import annotations

import math

import numpy as np

from ...models import scorecard as registry
from ..analysis import decision
from ..analysis import not_modelled as unmodelled
from ..analysis.grid_error import NO_COMPANION
from ..analysis.scorecard import empty_reason
from ..config import axes
from .plotting import MAX_CURVES, chunks, layout_with_legends, legend_below, panel_grid, pyplot, save_png
from .tables import not_measured, write_html_table

__all__ = ["scorecard_lead", "scorecard_figure", "write_scorecard_page"]


def scorecard_lead(table=None, grid=None) -> str:
    """The lead paragraph of the scorecard page of the report (the registered models' summaries,
    :data:`roughcontact.study.analysis.decision.RULE` and, given the *table*, whether its grid error is
    measured; *grid*: the study's :class:`~roughcontact.study.analysis.grid_error.GridErrorStatement`,
    whose reason is said where it is not)."""
    summaries = "; ".join(f"{model.summary} (modelled axes: {', '.join(model.axes) or 'none'})"
                          for model in registry.models().values())
    optional = ", ".join(a.name for a in axes.optional_axes(normal=True))
    reason = grid.why_not if grid is not None else NO_COMPANION
    grid = "" if table is None else decision.grid_note(table, reason) + " "
    return (f"{decision.RULE} {grid}"
            "Each model predicts the rough sphere's stiffness k(F) from the surface's parameters; "
            "max_rel_dev is the largest |k_model/k_BEM - 1| over the resolved loads of the ensemble "
            "mean, with its 95 % bootstrap-over-seeds interval, rms_rel_dev the rms of the same "
            "deviations; rank orders the scored rows by max_rel_dev alone (rank 1 the smallest; the recommended model is the rule's, above); paper_setting says whether every "
            f"optional axis ({optional}) is at the paper's value; not_modelled names the optional axes, with "
            "their values, at which the combination is off the paper's value and which the model does not "
            "model (its prediction ignores them; each model's modelled axes follow its summary at the end): such a "
            "row keeps its deviations but is not scored (no rank, every verdict untested: not modelled); "
            "inside_band the fraction of those loads where the model lies inside the ensemble's band; "
            "systematic_low and systematic_high the mean deviation below and above the crossover force (eq. 17), weighted by the inverse variance of the "
            "ensemble mean, with its interval and verdict on 0 (differs: a significant systematic deviation). "
            "With grid.coarse (the same surfaces on a coarser grid): grid_error_max the largest grid error "
            "estimate over those loads (Richardson's from |k_coarse/k_BEM - 1|, the measured order and a safety "
            "factor; results/grid_error.csv), grid_resolved the fraction of loads where it is at "
            "most half the band, inside_band_total the fraction inside the band widened by the grid error, and "
            "the *_total_verdict columns the systematic verdicts with the grid error added to the interval "
            "(differs: a model error). outside_range names why a combination lies outside the model's stated range "
            "of validity (such a row is flagged, keeps its deviations and rank, and is never recommended); "
            "decision_score is S, difference_ci_low/high the paired interval of S - S_recommended, "
            "grid_error_measured whether S includes a measured grid error, grid_error_note why not (the "
            f"grid-error columns are then NaN). {summaries}. models.csv holds every digit.")


#: the legend's mark of a model by its decision (models.csv), and what the legend's title says it means
MARKS = {"recommended": "★", "tied": "≈"}
MEANING = {"recommended": "recommended by the decision rule", "tied": "tied with the recommended model"}


def scorecard_figure(path, label: str, curve, table) -> None:
    """The figure of one sphere combination: every model's ``k_model/k_BEM − 1`` against the load,
    in the ensemble's band (widened by the grid error where measured); the models split evenly
    over as few panels as hold at most :data:`~roughcontact.study.report.plotting.MAX_CURVES` lines
    each (the zero line included). The legends lie under the panels; a model recommended by the
    decision rule is marked ★ in its legend, one tied with it ≈, and the legend's title says so."""
    plt = pyplot()
    force = curve["force_normalized"].values
    shown = curve["resolved"].values.astype(bool)
    names = [name for name in registry.models() if name in curve]
    panels = max(1, math.ceil(len(names) / (MAX_CURVES - 1)))
    groups = chunks(names, math.ceil(len(names) / panels) if names else 1)
    fig, axes = panel_grid(plt, len(groups), width=6, height=4, max_columns=2, sharey=True)
    # the bands at the scored (resolved) loads only: at an unresolved load the grid error can be
    # 1e15 or infinite, and the axis would hide every model
    low, high = curve["band_low"].values[shown], curve["band_high"].values[shown]
    legends = []
    for ax, group in zip(axes, groups):
        marks = set()
        if "grid_error" in curve:
            g = np.abs(curve["grid_error"].values[shown])
            ax.fill_between(force[shown], -np.sqrt(low ** 2 + g ** 2), np.sqrt(high ** 2 + g ** 2), color="0.93",
                            label="band and grid error")
        ax.fill_between(force[shown], low, high, color="0.85", label="BEM ensemble, 95 % band")
        ax.axhline(0, color="0.4", lw=0.8)
        for name in group:
            mark = table[(table["combination"] == label) & (table["model"] == name)]
            text = f" (max {float(mark['max_rel_dev'].iloc[0]):.1%})" if len(mark) else ""
            missing = mark[unmodelled.COLUMN].iloc[0] if len(mark) else ""
            if missing:                      # not scored: dashed, the axes it ignores named
                text += ", not modelled: " + missing
            if len(mark) and "decision" in mark and mark["decision"].iloc[0] in MARKS:
                marks.add(mark["decision"].iloc[0])
                text += " " + MARKS[mark["decision"].iloc[0]]
            ax.semilogx(force[shown], curve[name].values[shown], "o--" if missing else "o-", ms=3,
                        label=name + text)
        ax.set(xlabel="F / (E* L²)", ylabel="k_model / k_BEM − 1")
        # the marks the legend uses, explained in its title (models.csv's decision column)
        title = "; ".join(f"{MARKS[d]} {MEANING[d]}" for d in MARKS if d in marks) or None
        legends.append(legend_below(ax, gap=0.62, fontsize=7, title=title, title_fontsize=7))
    fig.suptitle(label + ("" if "grid_error" in curve else " (grid error not measured)"), fontsize=10)
    layout_with_legends(fig, legends, left=0.82, right=0.18, bottom=0.62, top=0.62, wspace=0.42, hspace=1.0)
    save_png(fig, path)


def write_scorecard_page(table, study, path, grid=None) -> None:
    """The report's page of the scorecard *table* (:func:`roughcontact.study.analysis.scorecard.scorecard`
    of *study*): the decision matrix above it, :func:`scorecard_lead` (and why the table is empty,
    where it is) and the columns that decide first; *grid*: the study's
    :class:`~roughcontact.study.analysis.grid_error.GridErrorStatement`."""
    absent = "" if len(table) else f"{not_measured(empty_reason(study))} "
    reason = grid.why_not if grid is not None else NO_COMPANION
    write_html_table(table, path, title="Model scorecard", lead=absent + scorecard_lead(table, grid),
                     above=decision.matrix_html(table, list(registry.models()), grid_reason=reason),
                     verdict_columns=("systematic_low_verdict", "systematic_high_verdict",
                                      "systematic_low_total_verdict", "systematic_high_total_verdict"),
                     first=("combination", "model", "decision", "tied_models", "decision_score", "difference_ci_low",
                            "difference_ci_high", "rank", unmodelled.COLUMN, decision.OUTSIDE, "max_rel_dev", "max_rel_dev_ci_low",
                            "max_rel_dev_ci_high", "rms_rel_dev", "inside_band", "inside_band_total",
                            "grid_error_max", "grid_resolved", "systematic_low", "systematic_low_verdict",
                            "systematic_low_total_verdict", "systematic_high", "systematic_high_verdict",
                            "systematic_high_total_verdict", "grid_error_measured", "n_loads"))
