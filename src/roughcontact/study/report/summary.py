"""The report's landing page: the answer first (verdicts, headline numbers, Fig. 3).

:func:`write_summary` turns ``claims.csv``, ``crossover.csv``, ``zeta.csv``, ``models.csv`` and
one Fig. 3 PNG into an HTML fragment (``results/summary.html``); the report's landing text
(``workflow/report/workflow.rst``) inlines that fragment when the report holds it, so one
sentence answering whether the paper's claims hold (:mod:`roughcontact.study.report.answer`), the
verdict counts per comparison, the crossover force against eq. 17 (each prediction next to its
verdict), ζ(H) against eq. 13, the
recommended model per sphere combination (with whether its grid error is measured,
:func:`roughcontact.study.analysis.decision.grid_note`) and Fig. 3 are on the first page, without a click.
Numbers are shown with four significant digits; the CSV files keep every digit. A table without
a row (a flat-only sweep has no crossover and no scorecard) reads "Not measured, because …".
"""
from __future__ import annotations

import base64
import html
import math

from ..analysis import decision
from ..analysis.crossover import NO_SPHERE
from ..analysis.grid_error import NO_COMPANION
from ..claims import NO_CLAIM
from ..config import axes
from ..analysis.statistics import VERDICTS
from ..files import provenance
from ..files.io import NO_ROW, REASON, read_csv
from . import answer
from .tables import DIGITS, VERDICT_COLOURS, not_measured, stamp, verdict_cell

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


def _combination(row, length: float = 1.0) -> str:
    """The combination of a table row, named by the axis registry: H, R (``flat`` for ``inf``) and
    h_rms, then every optional axis off the paper's setting (its name and coordinate)."""
    radius = row.get("radius")
    shape = "flat" if radius is not None and fmt(radius) == "inf" else f"R = {fmt(radius)}"
    parts = [f"H = {fmt(row.get('hurst'))}", shape, f"h_rms = {fmt(row.get('h_rms'))}"]
    parts += [f"{name} = {fmt(value)}" for name, value in axes.off_paper(row, length).items()]
    return html.escape(", ".join(parts))


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


def _absent(text: str) -> str:
    """A table that has no row: "Not measured, because …" in place of the table."""
    return f'<p class="rc-absent"><i>{html.escape(not_measured(text))}</i></p>'


def _holds(row) -> str:
    """The ``holds`` cell, read from the row's ``holds`` column: yes, or no (with "a branch has no
    resolved load" where that is why, :func:`~roughcontact.study.analysis.decision.both_branches`);
    a dash for a row without a model or a table without the column."""
    if str(row.get("model")) == NO_RECOMMENDATION:
        return "—"
    text = str(row.get("holds")).strip().lower()
    if text not in ("true", "false"):
        return "—"
    if text == "true":
        return "yes"
    has_counts = all(row.get(c) is not None for c in ("n_loads_low", "n_loads_high"))
    return "no: a branch has no resolved load" if has_counts and not all(decision.both_branches(row)) else "no"


def _why_empty(kind: str, size, table=None) -> str:
    """Why the table *kind* (crossover, zeta, models) has no row: its writer's reason
    (``table.attrs["reason"]``, :func:`roughcontact.study.files.io.write_csv`), else from the study's size."""
    reason = getattr(table, "attrs", {}).get(REASON)
    if reason and reason != NO_ROW:
        return str(reason)
    if kind in ("crossover", "models"):
        if size is not None and not size.spheres:
            return NO_SPHERE
        return "no sphere combination has a resolved load on either branch"
    if size is not None and not size.flats:
        return "the sweep has no nominally flat surface and no sphere's fractal branch gave a fit of ζ"
    return "no flat combination has enough resolved loads for a fit of ζ"


def summary_html(claims, crossover, zeta, models, fig3_png, *, fig3_title: str = "", size=None,
                 length: float = 1.0, extra: str = "") -> str:
    """The landing page's fragment (module docstring) from the four tables (pandas DataFrames, any of
    them possibly empty), the path of one Fig. 3 PNG (or ``None``), the study's
    :class:`~roughcontact.study.report.answer.StudySize` (or ``None``) and ``grid.length``; *extra*:
    HTML of further sections, after the recommended models (the measured scans')."""
    parts = [f'<div class="rc-summary" style="{_STYLE}">']
    # 1. the answer, then the tallies per comparison
    found = answer.comparisons(claims)
    parts.append("<h2>Answer: do the paper's claims hold?</h2>")
    parts.append(answer.answer_html(found, size))
    shown = [w for w in VERDICTS if w != "error" or any(c.counts.get(w) for c in found)]
    if found:
        rows = []
        for c in found:
            short = c.statement if len(c.statement) <= 110 else c.statement[:107] + "..."
            cells = []
            for w in shown:
                note = f" ({c.untested_because})" if w == "untested" and c.untested_because else ""
                cells.append(f'<td class="verdict-{w}" style="{_CELL} background:{VERDICT_COLOURS[w]}">'
                             f"{c.counts[w]} {w}{html.escape(note)}</td>" if c.counts.get(w) else "")
            rows.append([html.escape(c.claim), html.escape(short)] + cells)
        parts.append("<p>One row per comparison (a claim letter may hold several), counting the combinations "
                     "it is tested on.</p>")
        parts.append(_table(["claim", "comparison"] + shown, rows))
    else:
        parts.append(_absent(NO_CLAIM))
    # 2. Fig. 3
    if fig3_png is not None:
        parts.append(f"<h2>Fig. 3: stiffness against force{html.escape(fig3_title)}</h2>")
        parts.append(f'<img class="rc-fig3" alt="Fig. 3" style="max-width: 900px; width: 100%;" '
                     f'src="{_png_data_uri(fig3_png)}">')
    # 3. the crossover force against eq. 17, each prediction with its own verdict
    parts.append("<h2>Crossover force F_tr / (E* L²): measured (95 % interval) against eq. 17</h2>")
    if len(crossover):
        rows = [[_combination(r, length), _value_interval(r.get("Ftr_measured"), r.get("Ftr_ci_low"), r.get("Ftr_ci_high")),
                 fmt(r.get("Ftr_pred_estimate")), _verdict_cell(r.get("verdict_estimate")),
                 fmt(r.get("Ftr_pred_fit")), _verdict_cell(r.get("verdict_fit"))] for _, r in crossover.iterrows()]
        parts.append(_table(["combination", "F_tr measured [95 % interval]", "eq. 17, ζ = 1.7/(H+1)", "verdict",
                             "eq. 17, fitted ζ", "verdict"], rows))
    else:
        parts.append(_absent(_why_empty("crossover", size, crossover)))
    # 4. zeta(H) against eq. 13
    parts.append("<h2>ζ(H) fitted against eq. 13, 1.7/(H+1)</h2>")
    if len(zeta):
        rows = [[fmt(r["hurst"]), _value_interval(r.get("zeta"), r.get("zeta_ci_low"), r.get("zeta_ci_high")),
                 fmt(r.get("zeta_estimate")), html.escape(str(r.get("source", "")))] for _, r in zeta.iterrows()]
        parts.append(_table(["H", "ζ fitted [95 % interval]", "eq. 13", "source"], rows))
    else:
        parts.append(_absent(_why_empty("zeta", size, zeta)))
    # 5. the recommended model per sphere combination
    parts.append("<h2>Recommended model per sphere combination</h2>")
    if len(models):
        basis = ("the scorecard's decision (its recommended column; the model scorecard gives the rule)"
                 if "recommended" in models.columns else "rank 1: the smallest largest deviation max_rel_dev")
        parts.append(f"<p>Chosen by {html.escape(basis)}; whether it holds ({html.escape(decision.HOLDS_CRITERION)}; "
                     "only where both branches have a resolved load); the systematic deviation of k from the "
                     "ensemble below and above the crossover force (mean relative deviation, 95 % interval, "
                     "verdict).</p>")
        grid = size.grid_error if size is not None else None
        reason = grid.why_not if grid is not None else NO_COMPANION
        parts.append(f"<p>{html.escape(decision.grid_note(models, reason))}</p>")
        rows = []
        for r in recommended_models(models):
            rows.append([_combination(r, length),
                         f'<td class="model" style="{_CELL}"><b>{html.escape(str(r["model"]))}</b></td>',
                         html.escape(_holds(r)), fmt(r.get("max_rel_dev")),
                         _value_interval(r.get("systematic_low"), r.get("systematic_low_ci_low"),
                                         r.get("systematic_low_ci_high")),
                         _verdict_cell(r.get("systematic_low_verdict")),
                         _value_interval(r.get("systematic_high"), r.get("systematic_high_ci_low"),
                                         r.get("systematic_high_ci_high")),
                         _verdict_cell(r.get("systematic_high_verdict"))])
        parts.append(_table(["combination", "model", "holds", "max_rel_dev", "systematic, F < F_tr", "verdict",
                             "systematic, F > F_tr", "verdict"], rows))
    else:
        parts.append(_absent(_why_empty("models", size, models)))
    if extra:
        parts.append(extra)
    parts.append(f'<p style="color:#555; font-size: 11px;">{stamp()}</p>')
    parts.append("</div>")
    return "\n".join(parts) + "\n"


def _read(path):
    """The table at *path* (:func:`roughcontact.study.files.io.read_csv`): an empty DataFrame, with
    its writer's reason in ``attrs["reason"]``, for a table without a row."""
    return read_csv(path, keep_default_na=False, na_values=[""])


def write_summary(cfg, claims_csv, crossover_csv, zeta_csv, models_csv, figure_paths, out_html, *,
                  grid_error_csv=None, extra: str = "") -> None:
    """``summary`` rule: the landing page's fragment to *out_html* (atomic). *cfg* is the resolved
    configuration; *figure_paths* are the ``figures`` rule's outputs, in the order of
    :func:`~roughcontact.study.report.figures.figure_specs`; the Fig. 3 shown is the one of the
    combination Figs. 1, 2 and 4 show; *grid_error_csv*: ``grid_error.csv`` (``None`` without
    ``grid.coarse``), the one statement of the grid error every mention reads; *extra*: HTML of
    further sections (:func:`summary_html`)."""
    from ..analysis.grid_error import statement
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
                        chosen[1] if chosen else None, fig3_title=title, size=answer.StudySize.of(cfg, statement(
                            read_csv(grid_error_csv) if grid_error_csv else None, cfg["grid"].get("coarse"))),
                        length=float(cfg["grid"]["length"]), extra=extra)
    provenance.write_text(text, out_html)
