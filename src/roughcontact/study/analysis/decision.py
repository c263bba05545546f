"""The scorecard's decision: one stated rule picks the recommended model of each combination.

Rule (:data:`RULE`). For a model ``m`` of a sphere combination, with ``d_F = k_model/k_BEM − 1``
its deviation from the ensemble mean at each resolved load ``F`` and ``g_F`` the grid error
there (the estimate ``ê`` of the study grid's error from its companion on ``grid.coarse``,
:func:`roughcontact.study.analysis.grid_error.estimate`;
0 where it is not measured, and then every table and page says so), the score is the larger of
the two branches' (below/above the crossover force of eq. 17) root-mean-square deviation, each
load's deviation enlarged by the grid error there::

    S_m = max_b sqrt( mean_{F ∈ b} (|d_F| + g_F)² )        (``decision_score``)

the largest rms error on either branch that the grid could hide. Every resolved load counts
alike (an inverse-variance weight, as in ``systematic_*``, would let the Hertz end, where every
model agrees, decide). A row *holds* (``holds``, :func:`holds`) when both branches have resolved
loads and on each its systematic deviation is within :data:`HOLDS_SYSTEMATIC` (3 %), or within
:data:`HOLDS_SYSTEMATIC_CONSISTENT` (5 %) and consistent with 0 once the grid error is added
(``systematic_*_total_verdict``; the sampling verdict ``systematic_*_verdict`` where no grid error
is measured), and it lies inside the ensemble's band widened by the grid error at a fraction
:data:`HOLDS_INSIDE` (80 %) of the resolved loads or more (``inside_band_total``; ``inside_band``
without a grid error). Among the *scored* rows of the combination (``not_modelled`` and
``outside_range`` empty, ``S_m`` finite) the recommended model ``r`` minimises ``S_m`` over the
rows that hold, or over every scored row when none holds (the registry's order breaks an exact
tie). Another scored model ``m`` is *tied* with ``r`` when its
disadvantage is not significant: with ``D_j = S_m^(j) − S_r^(j)``, ``S^(j)`` the score against the
ensemble mean of the bootstrap's resample ``j`` of the seeds (the *same* resamples for both
models: a paired bootstrap), and ``[D_low, D_high]`` its percentile interval at the study's
confidence level::

    tied  ⇔  D_low ≤ 2 max(ĝ_m, ĝ_r),      ĝ = max_b sqrt( mean_{F ∈ b} g_F² ),

since a reference off by at most ``g_F`` moves each model's rms by at most ``ĝ`` (the triangle
inequality), so their difference by at most ``2ĝ``. Otherwise it is ``worse``. A row that is not
scored (not modelled, outside its model's stated range,
:attr:`roughcontact.models.scorecard.Model.ranges`, or without a score) is ``not scored`` and
never recommended.

Columns added to ``models.csv``: ``outside_range`` (why the combination lies outside the model's
stated range; empty inside), ``decision_score`` (``S_m``), ``difference_ci_low`` /
``difference_ci_high`` (the paired interval of ``S_m − S_r``; 0 for ``r``), ``grid_error_measured``
(bool: a finite grid error at a resolved load), ``holds`` (bool, :func:`holds`), ``recommended`` (bool, exactly one row per
combination with a scored model), ``tied_with_recommended`` (bool), ``tied_models`` (on the
recommended row: the tied models, comma-separated) and ``decision`` (``recommended``, ``tied``,
``worse``, ``not scored``); ``rank`` (by ``max_rel_dev``) is kept. :func:`sort` orders the table
by combination, then decision, then score; :func:`matrix_html` is the compact matrix above the
long table of the report's page.
"""
from __future__ import annotations

import html
import math

import numpy as np

from .grid_error import NO_COMPANION
from .statistics import CONSISTENT, interval

__all__ = ["RULE", "DECISIONS", "OUTSIDE", "HOLDS_SYSTEMATIC", "HOLDS_SYSTEMATIC_CONSISTENT", "HOLDS_INSIDE",
           "HOLDS_CRITERION",
           "inputs", "score", "holds", "both_branches", "decide", "sort", "matrix", "matrix_html", "grid_note"]

#: the column naming why a row lies outside its model's stated range
OUTSIDE = "outside_range"
#: the values of the ``decision`` column, in the order of the sorted table
DECISIONS = ("recommended", "tied", "worse", "not scored")
#: a row holds when each branch's systematic deviation is at most this (relative) ...
HOLDS_SYSTEMATIC = 0.03
#: ... or at most this and consistent with 0 once the grid error is added ...
HOLDS_SYSTEMATIC_CONSISTENT = 0.05
#: ... and it lies inside the band widened by the grid error at this fraction of the resolved loads
HOLDS_INSIDE = 0.8
#: what *holds* means (:func:`holds`), in words made from the three constants above
HOLDS_CRITERION = (f"each branch's systematic deviation within {100 * HOLDS_SYSTEMATIC:g} %, or within "
                   f"{100 * HOLDS_SYSTEMATIC_CONSISTENT:g} % and consistent with 0 with the grid error, and inside "
                   f"the band widened by the grid error at >= {100 * HOLDS_INSIDE:g} % of the resolved loads")
#: the rule in one sentence, for the page's lead and the guide
RULE = ("Decision rule: per combination, the recommended model (★) minimises S = max over the two branches "
        "(below/above the crossover) of the rms over the resolved loads of (|k_model/k_BEM - 1| + grid error "
        f"at the load) among the scored rows (not not_modelled, not outside_range) that hold ({HOLDS_CRITERION}), "
        "or among every scored row when none holds; a model is tied (≈) with it "
        "when the lower end of the paired bootstrap-over-seeds interval of S_model − S_recommended is at most "
        "twice the larger rms grid error, else worse.")
_MARK = {"recommended": "★", "tied": "≈", "worse": "", "not scored": "n.s."}


def inputs(k_model, k_mean, k_boot, use, branches: dict, g=None) -> dict:
    """What the decision reads of one model on one combination.

    Parameters
    ----------
    k_model, k_mean : numpy.ndarray
        The model's and the ensemble mean's stiffness at every load.
    k_boot : numpy.ndarray
        The ensemble mean on each bootstrap resample of the seeds, ``(resample, load)``.
    use : numpy.ndarray of bool
        The resolved loads where the model has a value.
    branches : dict of str to numpy.ndarray of bool
        Branch name -> its loads (subsets of *use*).
    g : numpy.ndarray, optional
        The grid error (its estimate ``ê`` or ``k̄_coarse/k̄ − 1``) at every load (NaN: none there);
        ``None``: not measured.

    Returns
    -------
    dict
        ``dev`` (resolved loads), ``boot`` (resample × resolved load), ``g`` (``|g|``, 0 where
        unknown), ``measured`` (bool) and ``branches`` (masks over the resolved loads).
    """
    use = np.asarray(use, dtype=bool)
    grid = np.zeros(int(use.sum())) if g is None else np.abs(np.asarray(g, dtype=float)[use])
    return {"dev": k_model[use] / k_mean[use] - 1, "boot": k_model[use] / k_boot[:, use] - 1,
            "g": np.nan_to_num(grid, nan=0.0), "measured": bool(g is not None and np.isfinite(grid).any()),
            "branches": {b: np.asarray(m, dtype=bool)[use] for b, m in branches.items()}}


def score(inp: dict):
    """``S``, its bootstrap replicates and ``ĝ`` of one model (module docstring).

    Parameters
    ----------
    inp : dict
        :func:`inputs`.

    Returns
    -------
    tuple of (float, numpy.ndarray, float)
        ``S`` (NaN without a branch with loads), ``S`` on each resample, ``ĝ``.
    """
    values, boots, g_hat = [], [], 0.0
    for mask in inp["branches"].values():
        if not mask.any():
            continue
        g = inp["g"][mask]
        values.append(float(np.sqrt(np.mean((np.abs(inp["dev"][mask]) + g) ** 2))))
        boots.append(np.sqrt(np.mean((np.abs(inp["boot"][:, mask]) + g) ** 2, axis=1)))
        g_hat = max(g_hat, float(np.sqrt(np.mean(g ** 2))))
    if not values:
        return math.nan, None, g_hat
    return max(values), np.max(boots, axis=0), g_hat


def holds(row: dict) -> bool:
    """Whether a scorecard row holds (module docstring): each branch with resolved loads within
    :data:`HOLDS_SYSTEMATIC`, or within :data:`HOLDS_SYSTEMATIC_CONSISTENT` and consistent with 0
    with the grid error, and inside the widened band at :data:`HOLDS_INSIDE` of the loads or more.

    Parameters
    ----------
    row : dict
        A row of ``models.csv`` before the decision (``systematic_low``/``_high`` with their
        verdicts, ``n_loads_low``/``_high``, ``inside_band`` and ``inside_band_total``).

    Returns
    -------
    bool
        False without a resolved load on both branches.
    """
    def finite(key):
        value = row.get(key, math.nan)
        return isinstance(value, (int, float)) and math.isfinite(value)

    measured = finite("inside_band_total")
    inside = row["inside_band_total"] if measured else row.get("inside_band", math.nan)
    if not (isinstance(inside, (int, float)) and inside >= HOLDS_INSIDE):
        return False
    if not all(both_branches(row)):   # a model is said to hold on both branches or not at all
        return False
    for b in ("low", "high"):
        value = abs(row[f"systematic_{b}"])
        verdict = row.get(f"systematic_{b}_total_verdict" if measured else f"systematic_{b}_verdict", "")
        if not (value <= HOLDS_SYSTEMATIC or (value <= HOLDS_SYSTEMATIC_CONSISTENT and verdict == CONSISTENT)):
            return False
    return True


def both_branches(row) -> tuple[bool, bool]:
    """Whether the low and the high branch of a scorecard row have a resolved load and a finite
    systematic deviation (``n_loads_*`` > 0): a row holds only with both (:func:`holds`), and the
    pages say "no: a branch has no resolved load" for the others."""
    def scored(b):
        try:
            loads = float(row.get(f"n_loads_{b}", 0) or 0)
            value = float(row.get(f"systematic_{b}", math.nan))
        except (TypeError, ValueError):
            return False
        return loads > 0 and math.isfinite(value)

    return scored("low"), scored("high")


def _scored(row: dict) -> bool:
    return not row.get("not_modelled", "") and not row.get(OUTSIDE, "")


def decide(rows: list, inputs_of: list, level: float = 0.95) -> list:
    """The decision columns of the rows of *one* combination (module docstring).

    Parameters
    ----------
    rows : list of dict
        The scorecard's rows of one combination, in the registry's order.
    inputs_of : list of (dict or None)
        Per row, :func:`inputs` (the same bootstrap resamples for every row); ``None``: no score.
    level : float
        The confidence level of the paired interval.

    Returns
    -------
    list of dict
        The rows, each with the columns of the module docstring added.
    """
    scores = [score(inp) if inp is not None else (math.nan, None, 0.0) for inp in inputs_of]
    eligible = [i for i, row in enumerate(rows) if _scored(row) and math.isfinite(scores[i][0])]
    held = [holds(row) for row in rows]
    holding = [i for i in eligible if held[i]]
    best = min(holding or eligible, key=lambda i: scores[i][0]) if eligible else None
    out = []
    for i, row in enumerate(rows):
        s, boot, g = scores[i]
        low = high = math.nan
        if i == best:
            decision, low, high = "recommended", 0.0, 0.0
        elif i in eligible:
            _, boot_r, g_r = scores[best]
            low, high = interval(boot - boot_r, level)
            decision = "tied" if low <= 2 * max(g, g_r) else "worse"
        else:
            decision = "not scored"
        measured = bool(inputs_of[i] is not None and inputs_of[i]["measured"])
        out.append({**row, "decision_score": s, "difference_ci_low": low, "difference_ci_high": high,
                    "grid_error_measured": measured, "holds": held[i], "recommended": decision == "recommended",
                    "tied_with_recommended": decision == "tied", "decision": decision})
    tied = ", ".join(r["model"] for r in out if r["decision"] == "tied")
    for r in out:
        r["tied_models"] = tied if r["recommended"] else ""
    return out


def sort(table):
    """The scorecard in the order of its page.

    Parameters
    ----------
    table : pandas.DataFrame
        A scorecard with the decision columns (returned as is without them).

    Returns
    -------
    pandas.DataFrame
        Ordered by combination, then :data:`DECISIONS`, then ``decision_score``, then model
        (index reset).
    """
    if not len(table) or "decision" not in table:
        return table
    order = table["decision"].map({d: i for i, d in enumerate(DECISIONS)})
    keyed = table.assign(_order=order)
    return (keyed.sort_values(["combination", "_order", "decision_score", "model"], kind="stable")
            .drop(columns="_order").reset_index(drop=True))


def matrix(table, models=None):
    """Combinations × models: the cell ``★``/``≈`` and ``S`` as a percentage, ``n.s.`` not scored.

    Parameters
    ----------
    table : pandas.DataFrame
        A scorecard with the decision columns.
    models : sequence of str, optional
        The columns' order (default: the table's order of first appearance).

    Returns
    -------
    pandas.DataFrame
        One row per combination (sorted), one column per model; ``""`` where the model has no row.
    """
    import pandas as pd

    models = list(dict.fromkeys(table["model"])) if models is None else [m for m in models if m in set(table["model"])]
    cells = {}
    for row in table.itertuples(index=False):
        mark = _MARK[row.decision]
        text = "n.s." if row.decision == "not scored" else f"{mark} {100 * row.decision_score:.1f} %".strip()
        cells.setdefault(row.combination, {})[row.model] = text
    return pd.DataFrame([{m: cells[c].get(m, "") for m in models} for c in sorted(cells)],
                        index=pd.Index(sorted(cells), name="combination"))


def grid_note(table, reason: str = NO_COMPANION) -> str:
    """Whether the scores include a measured grid error.

    Parameters
    ----------
    table : pandas.DataFrame
        A scorecard with ``grid_error_measured``.
    reason : str
        Why the study's grid error is not measured
        (:attr:`~roughcontact.study.analysis.grid_error.GridErrorStatement.reason`), said when no
        combination has it.

    Returns
    -------
    str
        One sentence: measured for every combination, for some of them (counted), or NOT
        measured (then S and the ties hold the sampling error only).
    """
    if not len(table) or "grid_error_measured" not in table:
        measured, total = 0, 0
    else:
        per = table.groupby("combination")["grid_error_measured"].any()
        measured, total = int(per.sum()), int(per.size)
    if total and measured == total:
        return ("The grid error is measured (grid.coarse: Richardson's estimate from the companion grid, "
                "grid_error.csv) and included in S and in the ties.")
    if measured:
        return (f"The grid error is measured (grid.coarse) for {measured} of {total} combinations only; on the "
                "others (grid_error_measured false) S and the ties hold the sampling error only.")
    return (f"Grid error NOT measured for this study ({reason}): S and the ties hold the sampling "
            "error only, and a reader cannot tell the grid's share of a deviation.")


def matrix_html(table, models=None, *, grid_reason: str = NO_COMPANION) -> str:
    """The compact matrix of the report's page.

    Parameters
    ----------
    table : pandas.DataFrame
        A scorecard with the decision columns.
    models : sequence of str, optional
        The columns' order (:func:`matrix`).

    Returns
    -------
    str
        An HTML fragment: a heading, :data:`RULE`, :func:`grid_note` and :func:`matrix` as a table
        (★ and ≈ cells shaded), closed by the heading of the long table; ``""`` without decisions.
    """
    if not len(table) or "decision" not in table:
        return ""
    grid = matrix(table, models)
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in ["combination", *grid.columns])
    body = []
    for combination, cells in grid.iterrows():
        tds = []
        for text in cells:
            style = ' style="background:#d6f5d6"' if text.startswith("★") else (
                ' style="background:#eef8ee"' if text.startswith("≈") else "")
            tds.append(f'<td class="number"{style}>{html.escape(text)}</td>')
        body.append(f"<tr><td>{html.escape(str(combination))}</td>{''.join(tds)}</tr>")
    return (f"<h2>Which model: S per combination (★ recommended, ≈ tied, n.s. not scored)</h2>"
            f'<p class="lead">{html.escape(RULE)} {html.escape(grid_note(table, grid_reason))}</p>'
            f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table><h2>Every row</h2>")
