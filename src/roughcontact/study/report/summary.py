"""The report's landing page: the answer first (verdicts, headline numbers, Fig. 3).

:func:`write_summary` turns ``claims.csv``, ``crossover.csv``, ``zeta.csv``, ``models.csv`` and
one Fig. 3 PNG into an HTML fragment (``results/summary.html``); the report's landing text
(``workflow/report/workflow.rst``) inlines that fragment when the report holds it, so the
verdict counts per claim, the crossover force against eq. 17, ζ(H) against eq. 13, the
recommended model per sphere combination (with whether its grid error is measured,
:func:`roughcontact.study.analysis.decision.grid_note`) and Fig. 3 are on the first page, without a click.
Numbers are shown with four significant digits; the CSV files keep every digit.
"""
from __future__ import annotations

import base64
import html
import math

from ..analysis import decision
from ..analysis.statistics import VERDICTS
from ..files import provenance
from .tables import DIGITS, VERDICT_COLOURS, stamp, verdict_cell, verdict_word

__all__ = ["DIGITS", "NO_RECOMMENDATION", "fmt", "summary_html", "write_summary", "recommended_models"]

_STYLE = "font-family: system-ui, sans-serif; font-size: 13px;"
_TABLE = 'style="border-collapse: collapse; margin: 4px 0 12px 0;"'
_CELL = "border: 1px solid #bbb; padding: 2px 6px; text-align: left;"


def fmt(value, digits: int = DIGITS) -> str:
    """*value* with *digits* significant digits ("" for None or NaN, ``inf`` as is)."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        return "" if value is None else str(value)
    if math.isnan(x):
        return ""
    return f"{x:.{digits}g}"


def _interval(low, high) -> str:
    return f"[{fmt(low)}, {fmt(high)}]" if fmt(low) and fmt(high) else "—"


def _value_interval(value, low, high) -> str:
    """*value* [*low*, *high*]; the value alone without an interval, "—" without a value."""
    if not fmt(value):
        return "—"
    return f"{fmt(value)} {_interval(low, high)}" if fmt(low) and fmt(high) else fmt(value)


def _verdict_cell(text) -> str:
    return verdict_cell(text, style=f"{_CELL} ")


def _table(header, rows) -> str:
    head = "".join(f'<th style="{_CELL} background:#f2f2f2">{html.escape(h)}</th>' for h in header)
    body = "\n".join("<tr>" + "".join(cell if cell.startswith("<td") else f'<td style="{_CELL}">{cell}</td>'
                                      for cell in row) + "</tr>" for row in rows)
    return f"<table {_TABLE}><thead><tr>{head}</tr></thead><tbody>\n{body}\n</tbody></table>"


def _combination(row) -> str:
    parts = [f"H = {fmt(row['hurst'])}", f"R = {fmt(row['radius'])}", f"h_rms = {fmt(row['h_rms'])}"]
    return html.escape(", ".join(parts))


def verdict_counts(claims):
    """Per claim: its statement (the first row's) and the count of each verdict word."""
    out = []
    for claim, rows in claims.groupby("claim", sort=False):
        words = [verdict_word(v) for v in rows["verdict"]]
        out.append((str(claim), str(rows["statement"].iloc[0]), {w: words.count(w) for w in VERDICTS}))
    return out


#: the model column of a combination whose scorecard recommends no model (no scored row)
NO_RECOMMENDATION = "none (no scored model)"


def recommended_models(models):
    """One row of *models* (``models.csv``) per sphere combination: the recommended model.

    The ``recommended`` column decides where the table has one (true on the recommended row,
    or the recommended model's name; no true row: :data:`NO_RECOMMENDATION`, its numbers
    empty); else the rank-1 model (the smallest ``max_rel_dev``)."""
    rows = []
    for _, group in models.groupby("combination", sort=False):
        if "recommended" in group.columns:
            flags = group["recommended"].astype(str).str.strip().str.lower()
            if set(flags) <= {"true", "false", "1", "0", "nan", "", "none"}:
                chosen = group[flags.isin(("true", "1"))]
            else:  # the recommended model's name
                chosen = group[group["model"].astype(str).str.lower().isin(set(flags))]
            if len(chosen):
                rows.append(chosen.iloc[0])
            else:
                empty = group.iloc[0].copy()
                for column in empty.index:
                    if column == "model":
                        empty[column] = NO_RECOMMENDATION
                    elif column in ("max_rel_dev", "rms_rel_dev") or column.startswith("systematic_"):
                        empty[column] = float("nan") if not column.endswith("_verdict") else ""
                rows.append(empty)
            continue
        ranked = group.sort_values(["rank", "max_rel_dev"] if "rank" in group.columns else ["max_rel_dev"])
        rows.append(ranked.iloc[0])
    return rows


def _png_data_uri(path) -> str:
    with open(path, "rb") as fh:
        # in lines of 76 characters: the landing text is reST (docutils limits a line to 10000
        # characters); a URL's parser drops the newlines
        return "data:image/png;base64,\n" + base64.encodebytes(fh.read()).decode("ascii").strip()


def summary_html(claims, crossover, zeta, models, fig3_png, *, fig3_title: str = "") -> str:
    """The landing page's fragment (module docstring) from the four tables (pandas DataFrames)
    and the path of one Fig. 3 PNG."""
    parts = [f'<div class="rc-summary" style="{_STYLE}">']
    # 1. the verdicts per claim
    counts = verdict_counts(claims)
    total = {w: sum(c[w] for _, _, c in counts) for w in VERDICTS}
    parts.append("<h2>Answer: the paper's claims</h2>")
    parts.append("<p>" + ", ".join(f"<b>{total[w]}</b> {w}" for w in VERDICTS if total[w] or w != "error")
                 + " (rows of the claims table, one per claim and combination it is tested on).</p>")
    rows = []
    for claim, statement, c in counts:
        short = statement if len(statement) <= 110 else statement[:107] + "..."
        rows.append([html.escape(claim), html.escape(short)]
                    + [(f'<td class="verdict-{w}" style="{_CELL} background:{VERDICT_COLOURS[w]}">{c[w]} {w}</td>'
                        if c[w] else "") for w in VERDICTS if total[w] or w != "error"])
    parts.append(_table(["claim", "statement"] + [w for w in VERDICTS if total[w] or w != "error"], rows))
    # 2. Fig. 3
    if fig3_png is not None:
        parts.append(f"<h2>Fig. 3: stiffness against force{html.escape(fig3_title)}</h2>")
        parts.append(f'<img class="rc-fig3" alt="Fig. 3" style="max-width: 900px; width: 100%;" '
                     f'src="{_png_data_uri(fig3_png)}">')
    # 3. the crossover force against eq. 17
    parts.append("<h2>Crossover force F_tr / (E* L²): measured (95 % interval) against eq. 17</h2>")
    rows = []
    for _, r in crossover.iterrows():
        rows.append([_combination(r), fmt(r.get("Ftr_measured")) or "—", _interval(r.get("Ftr_ci_low"), r.get("Ftr_ci_high")),
                     fmt(r.get("Ftr_pred_fit")), fmt(r.get("Ftr_pred_estimate")), _verdict_cell(r.get("verdict_fit"))])
    parts.append(_table(["combination", "F_tr measured", "95 % interval", "eq. 17, fitted ζ",
                         "eq. 17, ζ = 1.7/(H+1)", "verdict"], rows))
    # 4. zeta(H) against eq. 13
    parts.append("<h2>ζ(H) fitted against eq. 13, 1.7/(H+1)</h2>")
    rows = [[fmt(r["hurst"]), fmt(r["zeta"]), _interval(r["zeta_ci_low"], r["zeta_ci_high"]), fmt(r["zeta_estimate"]),
             html.escape(str(r.get("source", "")))] for _, r in zeta.iterrows()]
    parts.append(_table(["H", "ζ fitted", "95 % interval", "eq. 13", "source"], rows))
    # 5. the recommended model per sphere combination
    parts.append("<h2>Recommended model per sphere combination</h2>")
    basis = ("the scorecard's decision (its recommended column; the model scorecard gives the rule)"
             if "recommended" in models.columns else "rank 1: the smallest largest deviation max_rel_dev")
    parts.append(f"<p>Chosen by {html.escape(basis)}; whether it holds ({html.escape(decision.HOLDS_CRITERION)}); "
                 "the systematic deviation of k from the ensemble below and above the crossover force (mean "
                 "relative deviation, 95 % interval, verdict).</p>")
    if len(models):
        parts.append(f"<p>{html.escape(decision.grid_note(models))}</p>")
    rows = []
    for r in recommended_models(models):
        rows.append([_combination(r), f'<td class="model" style="{_CELL}"><b>{html.escape(str(r["model"]))}</b></td>',
                     _holds(r.get("holds")), fmt(r.get("max_rel_dev")),
                     _value_interval(r.get("systematic_low"), r.get("systematic_low_ci_low"), r.get("systematic_low_ci_high")),
                     _verdict_cell(r.get("systematic_low_verdict")),
                     _value_interval(r.get("systematic_high"), r.get("systematic_high_ci_low"), r.get("systematic_high_ci_high")),
                     _verdict_cell(r.get("systematic_high_verdict"))])
    parts.append(_table(["combination", "model", "holds", "max_rel_dev", "systematic, F < F_tr", "verdict",
                         "systematic, F > F_tr", "verdict"], rows))
    parts.append(f'<p style="color:#555; font-size: 11px;">{stamp()}</p>')
    parts.append("</div>")
    return "\n".join(parts) + "\n"


def _holds(value) -> str:
    """The ``holds`` cell: yes, no, or a dash for a table without the column."""
    text = str(value).strip().lower()
    return {"true": "yes", "false": "no"}.get(text, "—")


def _read(path):
    import pandas as pd

    return pd.read_csv(path, keep_default_na=False, na_values=[""])


def write_summary(cfg, claims_csv, crossover_csv, zeta_csv, models_csv, figure_paths, out_html) -> None:
    """``summary`` rule: the landing page's fragment to *out_html* (atomic). *figure_paths* are
    the ``figures`` rule's outputs, in the order of :func:`~roughcontact.study.report.figures.figure_specs`;
    the Fig. 3 shown is the one of the combination Figs. 1, 2 and 4 show."""
    from .figures import figure_specs, shown_combination

    specs = figure_specs(cfg)
    paths = list(figure_paths)
    target = shown_combination(cfg)
    fig3 = [(spec, path) for spec, path in zip(specs, paths) if spec["key"][0] == "fig3"]
    chosen = next((sp for sp in fig3 if sp[0]["key"][1]["name"] == target), fig3[0] if fig3 else None)
    title = ""
    if chosen is not None:
        labels = chosen[0]["labels"]
        title = f" (H = {labels['H']}, R = {labels['R']}, h_rms = {labels['h_rms']}; the others: category " \
                f"\"Fig. 3 stiffness vs force\")"
    text = summary_html(_read(claims_csv), _read(crossover_csv), _read(zeta_csv), _read(models_csv),
                        chosen[1] if chosen else None, fig3_title=title)
    provenance.write_text(text, out_html)
