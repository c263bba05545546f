"""The landing page's section on the measured scans (``topography``): per scan its fitted spectrum
(``results/measured_spectrum/<scan>.csv``) and, per surface kind and radius, the best-ranked model of
its scorecard (``results/measured_scorecard/<scan>.csv``, rank 1: the smallest largest deviation
``max_rel_dev`` among the scored rows). A sweep of measured scans only (``hurst`` empty) gets a
landing page of this section under an answer that says the paper's claims were not tested.
"""
from __future__ import annotations

import html
import math

from .summary import _CELL, _STYLE, _absent, _table, fmt
from .tables import stamp

__all__ = ["NO_GENERATED", "measured_section", "measured_only_html"]

#: the answer of a sweep without generated surfaces
NO_GENERATED = ("the sweep presses measured surfaces only (hurst is empty): the paper's claims, which are "
                "about generated self-affine surfaces, are not tested; each scan's own scorecard follows")


def _radius(value) -> str:
    """A radius in the scan's length unit (``flat`` for a nominally flat surface)."""
    r = float(value)
    return "flat" if math.isinf(r) else fmt(r)


def _best_rows(table):
    """The rank-1 row of every (kind, radius) of a scan's scorecard, in the table's order."""
    if not len(table) or "rank" not in table.columns:
        return []
    ranked = table[table["rank"].astype(str).str.strip().isin(("1", "1.0"))]
    return [group.iloc[0] for _, group in ranked.groupby(["kind", "radius"], sort=False)]


def measured_section(scans: dict) -> str:
    """The HTML of the measured scans: *scans* ``{name: (fit, scorecard)}``, each a DataFrame
    (``measured_spectrum`` and ``measured_scorecard`` tables, possibly empty)."""
    parts = ["<h2>Measured scans: the spectrum fitted and the best model</h2>"]
    for name, (fit, scorecard) in scans.items():
        parts.append(f"<h3>Scan {html.escape(str(name))}</h3>")
        if len(fit):
            r = fit.iloc[0]
            unit = html.escape(str(r.get("unit", "")))
            parts.append(f"<p>H = {fmt(r.get('hurst'))} [{fmt(r.get('hurst_ci_low'))}, {fmt(r.get('hurst_ci_high'))}], "
                         f"h_rms = {fmt(r.get('h_rms'))} {unit}, over {html.escape(str(r.get('tiles', '')))} tiles "
                         "(the scan's spectrum fit; its table holds every digit).</p>")
        best = _best_rows(scorecard)
        if best:
            rows = [[html.escape(str(r["kind"])), _radius(r["radius"]),
                     f'<td class="model" style="{_CELL}"><b>{html.escape(str(r["model"]))}</b></td>',
                     fmt(r.get("max_rel_dev")), fmt(r.get("rms_rel_dev")), fmt(r.get("inside_band")),
                     html.escape(str(r.get("n_loads", "")))] for r in best]
            parts.append(_table(["kind", "radius", "best model (rank 1)", "max_rel_dev", "rms_rel_dev",
                                 "inside_band", "loads"], rows))
        else:
            parts.append(_absent("no model has a resolved load of this scan to be scored on"))
    return "\n".join(parts)


def measured_only_html(scans: dict) -> str:
    """The landing page's fragment of a sweep of measured scans only (module docstring)."""
    return "\n".join([f'<div class="rc-summary" style="{_STYLE}">',
                      "<h2>Answer: do the paper's claims hold?</h2>",
                      f"<p>Not tested: {html.escape(NO_GENERATED)}.</p>",
                      measured_section(scans),
                      f'<p style="color:#555; font-size: 11px;">{stamp()}</p>',
                      "</div>"]) + "\n"
