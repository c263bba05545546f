"""Fig. 3's crossover forces, read from ``crossover.csv`` (:mod:`roughcontact.study.report.figures`):
the row of a sphere combination, its marks on the axes (eq. 17 with ζ of eq. 13 and with the fitted
ζ, each with the table's verdict; the measured crossover and its interval) and the title's words for
the optional axes off the paper's setting."""
from __future__ import annotations

import math

import numpy as np

from ...models import paper
from ..config import axes
from ..runs import naming as runs
from .plotting import edge_mark

__all__ = ["crossover_marks", "crossover_row", "variant_text"]


def variant_text(combo: dict, length: float) -> str:
    """The optional axes of a sphere combination off the paper's setting, as ``tag = value``
    (``m = 1, w = 0.001``; empty at the paper's setting): the title's words for the run name's tags."""
    out = []
    for axis in axes.optional_axes():
        if axis.name not in combo or axis.name not in runs.AXES["sphere"]:
            continue
        value = runs.axis_value(axis.name, combo[axis.name], length)
        if value != axis.paper:
            out.append(f"{axis.tag} = {value:g}" if isinstance(value, (int, float)) else f"{axis.tag} = {value}")
    return ", ".join(out)


def crossover_row(crossover, combo: dict):
    """The row of ``crossover.csv`` (a DataFrame) of the sphere combination *combo*, or None."""
    if crossover is None or not len(crossover):
        return None
    row = crossover
    for a in runs.AXES["sphere"]:
        if a in row:
            row = row[np.isclose(row[a], combo[a], rtol=1e-12, atol=0) | (np.isinf(row[a]) & np.isinf(combo[a]))]
    return row.iloc[0] if len(row) else None


def _verdict(row, column: str) -> str:
    """``": verdict"`` of crossover.csv's *column* as the table has it (empty without one)."""
    word = row.get(column)
    return f": {word}" if isinstance(word, str) and word else ""


def crossover_marks(ax, row, hurst: float) -> None:
    """Fig. 3's crossover forces of one crossover.csv *row* on *ax* (its limits set): eq. 17 with
    ζ = 1.7/(H+1) (eq. 13, the paper's prediction) and with the fitted ζ, each labelled with its
    value and the table's verdict for it (``verdict_estimate``, ``verdict_fit``), and the measured
    crossover with its 95 % interval (shaded). A predicted force beyond the axes is an arrow at
    their edge (:func:`~roughcontact.study.report.plotting.edge_mark`)."""
    zeta_est = float(row.get("zeta_estimate", paper.zeta_estimate(hurst)))
    estimate = float(row.get("Ftr_pred_estimate", math.nan))
    if math.isfinite(estimate):
        edge_mark(ax, estimate, "eq. 17, ζ = 1.7/(H+1)", color="0.35", ls="-.",
                  label=f"F_tr eq. 17, ζ = 1.7/(H+1) = {zeta_est:.3g}: {estimate:.2g}{_verdict(row, 'verdict_estimate')}")
    fitted = float(row.get("Ftr_pred_fit", math.nan))
    if math.isfinite(fitted):
        zeta_fit = float(row.get("zeta_fit", math.nan))
        name = f"fitted ζ = {zeta_fit:.3g}" if math.isfinite(zeta_fit) else "fitted ζ"
        edge_mark(ax, fitted, "eq. 17, fitted ζ", color="C1", ls=(0, (5, 2)),
                  label=f"F_tr eq. 17, {name}: {fitted:.2g}{_verdict(row, 'verdict_fit')}")
    low, high = float(row.get("Ftr_ci_low", math.nan)), float(row.get("Ftr_ci_high", math.nan))
    if math.isfinite(low) and math.isfinite(high):
        ax.axvspan(low, high, color="C3", alpha=0.15, lw=0,
                   label=f"F_tr measured = {float(row['Ftr_measured']):.2g} ({low:.2g}-{high:.2g}, 95 %)")
        ax.axvline(float(row["Ftr_measured"]), color="C3", ls=":", lw=1.2)
