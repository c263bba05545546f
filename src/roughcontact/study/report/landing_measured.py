"""The landing page's section on the measured scans (``topography``): per scan its fitted spectrum
(``results/measured_spectrum/<scan>.csv``) and, per surface kind and radius, the best-ranked model of
its scorecard (``results/measured_scorecard/<scan>.csv``, rank 1: the smallest largest deviation
``max_rel_dev`` among the scored rows). A sweep of measured scans only (``hurst`` empty) gets a
landing page of this section under an answer that says the paper's claims were not tested.

The measured spectra (``spectrum``) get a section of their own: per spectrum, its seeded surfaces'
stiffness per kind and radius (``results/spectrum_merge/<spectrum>.nc``: the loads, the range of
the mean k, the loads resolved by ``fit.resolved_cells`` mean contact cells) and its k(F) figure
(``results/spectrum_figures/<spectrum>/stiffness.png``). A sweep of spectra only gets a landing
page of that section under the same answer.
"""
from __future__ import annotations

import html
import math

from ..analysis.ensemble import resolved
from .summary import _CELL, _STYLE, _absent, _table, fmt
from .tables import stamp

__all__ = ["NO_GENERATED", "measured_section", "spectrum_section", "measured_only_html"]

#: the answer of a sweep without generated surfaces
NO_GENERATED = ("the sweep presses measured surfaces only (hurst is empty): the paper's claims, which are "
                "about generated self-affine surfaces, are not tested; each measured surface's own results follow")


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


def _spectrum_rows(groups: dict, resolved_cells: float) -> list:
    """One row per kind and radius of a spectrum's merged file (*groups* ``{kind: Dataset}``)."""
    rows = []
    for kind, ds in groups.items():
        radii = [float(r) for r in ds["radius"].values] if "radius" in ds.dims else [math.inf]
        for radius in radii:
            one = ds.sel(radius=radius) if "radius" in ds.dims else ds
            force, k = one["force"].values, one["k_mean"].values
            count = int(resolved(one["contact_cells"].mean("seed").values, resolved_cells).sum())
            unit_f = html.escape(str(one["force"].attrs.get("units", "")))
            unit_k = html.escape(str(one["k_mean"].attrs.get("units", "")))
            rows.append([html.escape(kind), _radius(radius), str(one.sizes["seed"]),
                         f"{fmt(force.min())} … {fmt(force.max())} {unit_f}",
                         f"{fmt(float(k.min()))} … {fmt(float(k.max()))} {unit_k}", f"{count} of {len(force)}"])
    return rows


def spectrum_section(spectra: dict, resolved_cells: float) -> str:
    """The HTML of the measured spectra: *spectra* ``{name: (groups, figure path or None)}``, the
    groups of ``results/spectrum_merge/<name>.nc`` (``{kind: Dataset}``); a load is resolved
    when its mean contact cells over the seeds reach *resolved_cells* (``fit.resolved_cells``)."""
    from .summary import _png_data_uri

    parts = ["<h2>Measured spectra: the stiffness of their seeded surfaces</h2>"]
    for name, (groups, figure) in spectra.items():
        parts.append(f"<h3>Spectrum {html.escape(str(name))}</h3>")
        rows = _spectrum_rows(groups, resolved_cells)
        if rows:
            parts.append(_table(["kind", "radius", "seeds", "loads F", "mean k", "resolved loads"], rows))
        else:
            parts.append(_absent("the spectrum's merged file holds no run"))
        if figure is not None:
            parts.append(f'<img alt="k(F) of {html.escape(str(name))}" style="max-width: 700px; width: 100%;" '
                         f'src="{_png_data_uri(figure)}">')
    return "\n".join(parts)


def measured_only_html(scans: dict, spectra: str = "") -> str:
    """The landing page's fragment of a sweep of measured surfaces only (module docstring): the
    scans' section of *scans* and the spectra's HTML *spectra* (:func:`spectrum_section`)."""
    return "\n".join([f'<div class="rc-summary" style="{_STYLE}">',
                      "<h2>Answer: do the paper's claims hold?</h2>",
                      f"<p>Not tested: {html.escape(NO_GENERATED)}.</p>",
                      measured_section(scans) if scans else "",
                      spectra,
                      f'<p style="color:#555; font-size: 11px;">{stamp()}</p>',
                      "</div>"]) + "\n"
