"""The scorecard's decision: one stated rule picks the recommended model of each combination.

Rule (:data:`RULE`). For a model ``m`` of a sphere combination, with ``s_{m,b}`` its systematic
deviation on branch ``b`` (``systematic_low``/``systematic_high``: the inverse-variance weighted
mean of ``k_model/k_BEM − 1`` below/above the crossover force, :mod:`roughcontact.study.scorecard`)
and ``g_b`` the grid error of that branch (``grid_error_low``/``grid_error_high``, measured with
``grid.coarse``; 0 where it is not measured, and then every table and page says so),

    S_m = max_b ( |s_{m,b}| + g_b )          (``decision_score``; over the branches with resolved loads)

is the largest error the model can have on either branch that neither the seeds' sampling nor
the grid explains away. Among the *scored* rows of the combination (``not_modelled`` and
``outside_range`` empty, ``S_m`` finite) the recommended model ``r`` minimises ``S_m`` (the
registry's order breaks an exact tie). Another scored model ``m`` is *tied* with ``r`` when its
disadvantage is not significant: with ``D_j = S_m^(j) − S_r^(j)`` over the bootstrap's resamples
``j`` of the seeds (the *same* resamples for both models: a paired bootstrap) and
``[D_low, D_high]`` its percentile interval at the study's confidence level,

    tied  ⇔  D_low ≤ 2 max(ĝ_m, ĝ_r),      ĝ = max_b g_b,

since a shift of the reference by at most ``g`` changes a difference of two absolute deviations
by at most ``2g``. Otherwise it is ``worse``. A row that is not scored (not modelled, outside its
model's stated range, :attr:`roughcontact.models.scorecard.Model.ranges`, or without a score) is
``not scored`` and never recommended.

Columns added to ``models.csv``: ``outside_range`` (why the combination lies outside the model's
stated range; empty inside), ``decision_score`` (``S_m``), ``difference_ci_low`` /
``difference_ci_high`` (the paired interval of ``S_m − S_r``; 0 for ``r``), ``grid_error_measured``
(bool: a finite grid error on a branch), ``recommended`` (bool, exactly one row per combination
with a scored model), ``tied_with_recommended`` (bool), ``tied_models`` (on the recommended row:
the tied models, comma-separated) and ``decision`` (``recommended``, ``tied``, ``worse``,
``not scored``); ``rank`` (by ``max_rel_dev``) is kept. :func:`sort` orders the table by
combination, then decision, then score; :func:`matrix_html` is the compact matrix above the long
table of the report's page.
"""
from __future__ import annotations

import html
import math

import numpy as np

from .statistics import interval

__all__ = ["RULE", "DECISIONS", "OUTSIDE", "score", "decide", "sort", "matrix", "matrix_html", "grid_note"]

#: the column naming why a row lies outside its model's stated range
OUTSIDE = "outside_range"
#: the values of the ``decision`` column, in the order of the sorted table
DECISIONS = ("recommended", "tied", "worse", "not scored")
#: the rule in one sentence, for the page's lead and the guide
RULE = ("Decision rule: per combination, the recommended model (★) minimises S = max over the two branches of "
        "(|systematic deviation| + grid error of the branch) among the scored rows (not not_modelled, not "
        "outside_range); a model is tied (≈) with it when the lower end of the paired bootstrap-over-seeds "
        "interval of S_model − S_recommended is at most twice the larger grid error, else worse.")
_MARK = {"recommended": "★", "tied": "≈", "worse": "", "not scored": "n.s."}


def _number(value) -> float:
    try:
        value = float(value)
    except (TypeError, ValueError):
        return math.nan
    return value


def score(row: dict, replicates: dict | None = None):
    """``S`` of one scorecard row and its bootstrap replicates (module docstring).

    Parameters
    ----------
    row : dict
        A row of the scorecard with ``systematic_low``/``systematic_high``, ``n_loads_low``/
        ``n_loads_high`` and, where measured, ``grid_error_low``/``grid_error_high``.
    replicates : dict of str to numpy.ndarray, optional
        Branch -> the systematic deviation on each bootstrap resample (the same resamples for
        every model of the combination).

    Returns
    -------
    tuple of (float, numpy.ndarray or None, float)
        ``S`` (NaN without a branch with resolved loads), its replicates (``None`` without
        *replicates*) and ``ĝ = max_b g_b`` (0 where not measured).
    """
    terms, boot, g_max = [], [], 0.0
    for branch in ("low", "high"):
        value = _number(row.get(f"systematic_{branch}"))
        if not math.isfinite(value) or _number(row.get(f"n_loads_{branch}", 1)) < 1:
            continue
        g = _number(row.get(f"grid_error_{branch}"))
        g = g if math.isfinite(g) else 0.0
        g_max = max(g_max, g)
        terms.append(abs(value) + g)
        if replicates is not None and branch in replicates:
            boot.append(np.abs(np.asarray(replicates[branch], dtype=float)) + g)
    if not terms:
        return math.nan, None, g_max
    return max(terms), (np.max(boot, axis=0) if boot and len(boot) == len(terms) else None), g_max


def _scored(row: dict) -> bool:
    return not row.get("not_modelled", "") and not row.get(OUTSIDE, "")


def decide(rows: list, replicates: list | None = None, level: float = 0.95) -> list:
    """The decision columns of the rows of *one* combination (module docstring).

    Parameters
    ----------
    rows : list of dict
        The scorecard's rows of one combination, in the registry's order.
    replicates : list of (dict or None), optional
        Per row, :func:`score`'s *replicates* (branch -> systematic deviation per resample).
        Without them (or for a pair without), a model is tied when the intervals
        ``[systematic_*_ci_low, systematic_*_ci_high]`` give overlapping score intervals.
    level : float
        The confidence level of the paired interval.

    Returns
    -------
    list of dict
        The rows, each with the columns of the module docstring added.
    """
    replicates = replicates if replicates is not None else [None] * len(rows)
    scores = [score(row, boot) for row, boot in zip(rows, replicates)]
    eligible = [i for i, row in enumerate(rows) if _scored(row) and math.isfinite(scores[i][0])]
    best = min(eligible, key=lambda i: scores[i][0]) if eligible else None
    out = []
    for i, row in enumerate(rows):
        s, boot, g = scores[i]
        low = high = math.nan
        if i == best:
            decision, low, high = "recommended", 0.0, 0.0
        elif i in eligible:
            s_r, boot_r, g_r = scores[best]
            if boot is not None and boot_r is not None:
                low, high = interval(boot - boot_r, level)
            else:                                   # no replicates: the score intervals' overlap
                low = _score_bound(row, "low") - _score_bound(rows[best], "high")
                high = _score_bound(row, "high") - _score_bound(rows[best], "low")
            decision = "tied" if low <= 2 * max(g, g_r) else "worse"
        else:
            decision = "not scored"
        measured = any(math.isfinite(_number(row.get(f"grid_error_{b}"))) for b in ("low", "high"))
        out.append({**row, "decision_score": s, "difference_ci_low": low, "difference_ci_high": high,
                    "grid_error_measured": measured, "recommended": decision == "recommended",
                    "tied_with_recommended": decision == "tied", "decision": decision})
    tied = ", ".join(r["model"] for r in out if r["decision"] == "tied")
    for r in out:
        r["tied_models"] = tied if r["recommended"] else ""
    return out


def _score_bound(row: dict, end: str) -> float:
    """The low or high end of ``S``'s interval from the branches' intervals (no replicates)."""
    bounds = []
    for branch in ("low", "high"):
        lo, hi = (_number(row.get(f"systematic_{branch}_ci_{e}")) for e in ("low", "high"))
        if not (math.isfinite(lo) and math.isfinite(hi)):
            continue
        g = _number(row.get(f"grid_error_{branch}"))
        g = g if math.isfinite(g) else 0.0
        smallest = 0.0 if lo <= 0 <= hi else min(abs(lo), abs(hi))
        bounds.append((smallest if end == "low" else max(abs(lo), abs(hi))) + g)
    return max(bounds) if bounds else math.nan


def sort(table):
    """*table* ordered by combination, then :data:`DECISIONS`, then ``decision_score`` (index reset)."""
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


def grid_note(table) -> str:
    """One sentence: whether the scores include a measured grid error (all, none or some combinations)."""
    if not len(table) or "grid_error_measured" not in table:
        measured, total = 0, 0
    else:
        per = table.groupby("combination")["grid_error_measured"].any()
        measured, total = int(per.sum()), int(per.size)
    if total and measured == total:
        return "The grid error is measured (grid.coarse) and included in S and in the ties."
    if measured:
        return (f"The grid error is measured (grid.coarse) for {measured} of {total} combinations only; on the "
                "others (grid_error_measured false) S and the ties hold the sampling error only.")
    return ("The grid error is NOT measured for this study (no grid.coarse): S and the ties hold the sampling "
            "error only, and a reader cannot tell the grid's share of a deviation.")


def matrix_html(table, models=None) -> str:
    """:func:`matrix` as an HTML fragment (a heading, the rule, :func:`grid_note` and the table)."""
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
            f'<p class="lead">{html.escape(RULE)} {html.escape(grid_note(table))}</p>'
            f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table><h2>Every row</h2>")
