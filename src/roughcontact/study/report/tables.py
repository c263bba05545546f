"""Result tables as self-contained HTML pages, for the report: verdicts readable on the page.

Snakemake's report shows an HTML result inside the page (an ``iframe``), where a CSV result is
only offered as a download; :func:`write_html_table` turns a table such as ``claims.csv`` into
such a page, one row per table row, with the verdict cells colour-coded. The page carries its
provenance (package version, git commit, date) in a footer and needs no script or network.
"""
from __future__ import annotations

import html
import math
import numbers

from ..files import provenance

__all__ = ["DIGITS", "VERDICT_COLOURS", "TABLE_PAGES", "csv_to_html", "html_table", "write_html_table", "verdict_word",
           "verdict_cell", "stamp"]

#: significant digits of every number shown on a page (the CSV files keep every digit)
DIGITS = 4

#: background colour of a verdict cell, by the verdict's first word (``error``: the claim's estimate raised)
VERDICT_COLOURS = {"consistent": "#d6f5d6", "differs": "#f8d0d0", "untested": "#e6e6e6", "error": "#f5d76e"}

_STYLE = """
body { font-family: system-ui, sans-serif; font-size: 13px; margin: 12px; }
h1 { font-size: 16px; }
p.lead { max-width: 70em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #bbb; padding: 3px 6px; text-align: left; vertical-align: top; }
th { background: #f2f2f2; position: sticky; top: 0; }
td.text { min-width: 14em; }
td.number { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
footer { margin-top: 1em; color: #555; font-size: 11px; }
"""


def _cell_text(value) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return f"{value:.{DIGITS}g}"
    return str(value)


def verdict_word(text) -> str:
    """The verdict word a verdict cell is coloured by: the first word of *text* (``""`` for no text)."""
    return str(text).split(":")[0].split(" ")[0] if isinstance(text, str) else ""


def verdict_cell(text, style: str = "") -> str:
    """A ``<td>`` of the verdict *text* (escaped), coloured by :data:`VERDICT_COLOURS` and of the class
    ``verdict-<word>``; *style*: further CSS of the cell."""
    word = html.escape(verdict_word(text))
    colour = VERDICT_COLOURS.get(word, "#ffffff")
    shown = html.escape(text) if isinstance(text, str) else ""
    return f'<td class="verdict-{word}" style="{style}background:{colour}">{shown}</td>'


def stamp() -> str:
    """The provenance line under a page (escaped): package version, git commit, time written."""
    attrs = provenance.provenance_attrs()
    return (f"roughcontact {html.escape(str(attrs['roughcontact_version']))}, git commit "
            f"{html.escape(str(attrs['git_commit']))}, written {html.escape(str(attrs['created_utc']))}")


def html_table(rows, *, title: str, lead: str, verdict_columns=("verdict",), first=(), above: str = "") -> str:
    """One HTML page: *title*, a *lead* paragraph and *rows* (a pandas DataFrame) as a table.

    *above*: an HTML fragment, trusted and written as is, between the lead and the table (the
    scorecard's decision matrix, :func:`roughcontact.study.analysis.decision.matrix_html`); the table of
    *rows* has the class ``rows``, so a reader (or a test) counts its rows apart from such a fragment.

    The columns named in *first* come first, in that order, then the others. Cells of the
    *verdict_columns* are coloured by :data:`VERDICT_COLOURS` and carry the class
    ``verdict-<word>``; numbers are shown with four significant digits (the CSV beside the
    page keeps every digit).
    """
    rows = rows[[c for c in first if c in rows.columns] + [c for c in rows.columns if c not in first]]
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in rows.columns)
    body = []
    for record in rows.itertuples(index=False):
        cells = []
        for column, value in zip(rows.columns, record):
            text = html.escape(_cell_text(value))
            if column in verdict_columns:
                cells.append(verdict_cell(_cell_text(value)))
            elif isinstance(value, numbers.Real) and not isinstance(value, bool):
                cells.append(f'<td class="number">{text}</td>')
            else:
                wide = ' class="text"' if len(text) > 40 else ""
                cells.append(f"<td{wide}>{text}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    footer = stamp()
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{html.escape(title)}</title>'
            f"<style>{_STYLE}</style></head><body><h1>{html.escape(title)}</h1>"
            f'<p class="lead">{html.escape(lead)}</p>{above}'
            f'<table class="rows"><thead><tr>{head}</tr></thead><tbody>{"".join(body)}</tbody></table>'
            f"<footer>{footer}</footer></body></html>\n")


def write_html_table(rows, path, **kwargs) -> None:
    """:func:`html_table` written to *path* atomically (temp file, then rename)."""
    provenance.write_text(html_table(rows, **kwargs), path)


#: the report's page of each CSV table the workflow writes: its title and lead paragraph
TABLE_PAGES = {
    "zeta": ("zeta(H)", "zeta(H) of eq. 11 fitted per Hurst exponent with its bootstrap-over-seeds interval, "
                        "against 1.7/(H+1) (eq. 13). Every digit: results/zeta.csv."),
    "crossover": ("Crossover force", "Per sphere combination: the crossover force measured by fitting eq. 16 with "
                                     "its 95 % interval against eq. 17, the slopes below and above it and the "
                                     "verdicts. Every digit: results/crossover.csv."),
    "exponents": ("Local exponents", "The local exponent d ln k / d ln F along the load path per combination. "
                                     "Every digit: results/exponents.csv."),
    "grid_error": ("Grid error", "The stiffness on grid.coarse against the study's grid at every load, and "
                                 "the estimate of the study grid's error from it (grid_error_estimate). "
                                 "Every digit: results/grid_error.csv."),
    "fine_reference": ("Fine reference", "The study's stiffness at the small loads against the same surfaces on "
                                         "grid.fine: study_grid_error k_n/k_N - 1 with its interval, the fine "
                                         "grid's own error estimate, grid_error_estimate (their bound, used by "
                                         "the model scorecard at these loads), the reference stiffness "
                                         "(Richardson's where the three grids are monotone) and the loads where "
                                         "one asperity carries the load (single_asperity). Every digit: "
                                         "results/fine_reference.csv."),
    "tangential": ("Tangential stiffness per load",
                   "Per sphere combination, Poisson ratio and load: the ensemble's full-stick k_t/k_n with its 95 % "
                   "bootstrap-over-seeds interval against Mindlin's 2(1-nu)/(2-nu), and the load's branch (fractal: "
                   "resolved and below the crossover force F_tr; Hertz: above). Every digit: "
                   "results/tangential/tangential.csv."),
    "pull_off": ("Pull-off", "The pull-off force of the adhesive runs over JKR's with the interval over seeds. "
                             "Every digit: results/adhesion/pull_off.csv."),
    "stickiness": ("Stickiness", "Pastewka & Robbins' stickiness: the loading slope dF/dA per (H, N) with its "
                                 "interval over seeds. Every digit: results/stickiness/stickiness.csv."),
    "spectrum_fit": ("Spectrum fit", "The self-affine fit of the scan's spectrum over its tiles: H, h_rms and the "
                                     "rms slope with intervals. Every digit: the CSV file beside this page in "
                                     "results/measured_spectrum/."),
}


def not_measured(reason: str) -> str:
    """What a table without a row says instead: ``Not measured, because <reason>.``"""
    return f"Not measured, because {reason}."


def csv_to_html(csv_path, html_path, table: str) -> None:
    """The CSV table *csv_path* as the report's page *html_path* (:func:`write_html_table`,
    title and lead of :data:`TABLE_PAGES` [*table*]); the CSV stays as it is. A table without a row
    says why in its lead ("Not measured, because …": :func:`roughcontact.study.files.io.read_csv`)."""
    from ..files.io import REASON, read_csv

    rows = read_csv(csv_path, keep_default_na=False, na_values=[""])
    title, lead = TABLE_PAGES[table]
    if not len(rows):
        lead = f"{not_measured(rows.attrs[REASON])} {lead}"
    verdicts = tuple(c for c in rows.columns if str(c) == "verdict" or str(c).endswith("_verdict")
                     or str(c).startswith("verdict_"))
    write_html_table(rows, html_path, title=title, lead=lead, verdict_columns=verdicts)
