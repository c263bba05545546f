"""The measured scorecard: every model of the registry against the tiles of one scan.

For each kind (sphere radii, the flat tile) and model of :mod:`roughcontact.models.scorecard`
(the predictions of :func:`roughcontact.study.analysis.measured_spectrum.spectrum_groups`), over the
resolved loads (mean contact cells over the tiles ≥ ``fit.resolved_cells``, the study's one
rule :func:`roughcontact.study.analysis.ensemble.resolved`) where the model has a value:

* ``max_rel_dev = max_F |k_model/k_mean − 1|`` and ``rms_rel_dev``, against the mean over tiles;
* ``inside_band``: the fraction of those loads where the model lies inside the bootstrap
  interval of the mean over tiles (``k_ci_low ≤ k_model ≤ k_ci_high``; NaN with one tile);
* ``max_rel_dev_ci_low/high`` and ``rms_rel_dev_ci_low/high``: their percentile intervals over the
  tiles, as the generated scorecard's over seeds (:mod:`roughcontact.study.analysis.scorecard`): the
  mean over tiles recomputed on every bootstrap resample of the tiles (``fit.bootstrap``
  resamples, level ``fit.confidence``, :mod:`roughcontact.study.analysis.statistics`; the model
  is deterministic); NaN with one tile or without the fit settings.

``not_modelled`` (:mod:`roughcontact.study.analysis.not_modelled`): the optional axes at which the
merged runs are off the paper's setting (a coordinate of the merged group; a measured run is a
paraboloid without roll-off, cutoff or hardness, so today none) and which the model does not
declare; such a row keeps its deviations but has no ``rank``.

``outside_range``: why the scan lies outside the model's stated range
(:attr:`roughcontact.models.scorecard.Model.ranges`; empty inside), from :func:`scan_values`: its
fitted H (``hurst`` of the spectrum fit) and its ``bandwidth``, the ratio of the largest to the
smallest wavelength a tile holds, its side over the Nyquist wavelength ``2Δx`` (``tile/2``, as
``n/2`` for a generated surface rough down to the grid without roll-off or cutoff). The row is
flagged, keeps its deviations and rank, and is not a model to recommend for this scan; the page's
lead says in words which models the scan lies outside of (:func:`range_note`).

Stiffnesses are compared in N/m at the same forces (N).
"""
from __future__ import annotations

import math

import numpy as np

from ...models import scorecard as registry
from ..config import axes
from . import not_modelled as unmodelled
from .ensemble import resolved
from .statistics import bootstrap_indices, interval

__all__ = ["measured_scorecard", "MEASURED_SCORECARD_LEAD", "scan_values", "range_note",
           "outside_range"]

#: the lead paragraph of a scan's scorecard page in the report
MEASURED_SCORECARD_LEAD = (
    "Each model of the scorecard predicts the scan's stiffness k(F) from its spectrum fit (H and h_rms "
    "fitted; Greenwood-Tripp and Persson read the measured spectrum itself); max_rel_dev is the largest "
    "|k_model/k_mean - 1| over the resolved loads against the mean over the tiles, rms_rel_dev the rms of "
    "the same deviations, each with its 95 % bootstrap-over-tiles interval (_ci_low, _ci_high), inside_band "
    "the fraction of those loads where the model lies inside the bootstrap "
    "interval of the mean over the tiles; not_modelled names the optional axes off the paper's value that "
    "the model does not model (a measured run is at the paper's value of every optional axis, so it is "
    "empty): such a row has no rank; outside_range names why the scan's fitted H or its bandwidth (the tile's "
    "side over twice the cell) lies outside the model's stated range of validity (the row is flagged, not hidden, "
    "and not a model to recommend). The CSV beside this page holds every digit.")


def scan_values(spectrum_attrs) -> dict:
    """What a model's stated ranges are checked against for a scan (module docstring): ``hurst``,
    the fitted H, and ``bandwidth``, the tile's side over the Nyquist wavelength (``tile/2``); NaN
    (not checked) where the spectrum's attributes lack them."""
    attrs = dict(spectrum_attrs or {})
    tile = float(attrs.get("tile", math.nan))
    return {"hurst": float(attrs.get("hurst", math.nan)), "bandwidth": tile / 2}


def outside_range(model: str, values: dict) -> str:
    """Why the scan of :func:`scan_values` *values* lies outside *model*'s stated range (``""``: inside,
    or a model not in the registry)."""
    known = registry.models().get(model)
    return known.outside(values) if known is not None else ""


def range_note(table, spectrum_attrs) -> str:
    """The scorecard page's sentence on the models' stated ranges: the scan's fitted H with its
    interval and its bandwidth, and which models' rows are flagged (``outside_range``)."""
    attrs = dict(spectrum_attrs or {})
    values = scan_values(attrs)
    low, high = (float(attrs.get(f"hurst_ci_{end}", math.nan)) for end in ("low", "high"))
    where = (f"The scan's fitted H = {values['hurst']:.4g}"
             + (f" [{low:.4g}, {high:.4g}]" if math.isfinite(low) and math.isfinite(high) else "")
             + (f", bandwidth {values['bandwidth']:.4g}" if math.isfinite(values["bandwidth"]) else ""))
    flagged = table[table["outside_range"].fillna("") != ""] if len(table) and "outside_range" in table else table
    if not len(flagged):
        return f"{where}: inside the stated range of every model scored here."
    names = list(dict.fromkeys(flagged["model"]))
    reasons = "; ".join(f"{m}: {flagged.loc[flagged['model'] == m, 'outside_range'].iloc[0]}" for m in names)
    return (f"{where}: OUTSIDE the stated range of {len(names)} model(s), {', '.join(names)} ({reasons}). Their rows "
            "are flagged in outside_range: their deviations and ranks are kept, but they are not models to recommend "
            "for this scan.")


def measured_scorecard(merged: dict, predicted: dict, *, name: str, min_cells: int, fit=None):
    """One row per (kind, radius, model) of a scan: *merged* the groups of
    :func:`roughcontact.study.analysis.measured_merge.merge_surface`, *predicted* those of
    :func:`roughcontact.study.analysis.measured_spectrum.spectrum_groups` (the ``sphere`` and ``flat`` groups);
    *fit*: the bootstrap's settings (:class:`~roughcontact.study.config.settings.ZetaFitSettings`,
    ``bootstrap`` and ``confidence``) for the intervals over tiles (``None``: NaN intervals)."""
    import pandas as pd

    rows = []
    spectrum = predicted.get("spectrum")
    length = float(spectrum.attrs.get("tile_length", math.nan)) if spectrum is not None else math.nan
    values = scan_values(spectrum.attrs if spectrum is not None else {})
    for kind in ("sphere", "flat"):
        if kind not in merged or kind not in predicted:
            continue
        runs, models = merged[kind], predicted[kind]
        if not np.allclose(runs["force_normalized"].values, models["force_normalized"].values, rtol=1e-12, atol=0):
            raise ValueError(f"{name}: the models' forces are not the runs' forces (rerun measured_spectrum)")
        ensemble = [d for d in runs["stiffness"].dims if d not in ("radius", "force")][0]   # tile or seed
        count = runs.sizes[ensemble]
        indices = bootstrap_indices(count, fit.bootstrap) if fit is not None and count > 1 else None
        radii = runs["radius"].values.tolist() if kind == "sphere" else [math.inf]
        for radius in radii:
            pick = {"radius": radius} if kind == "sphere" else {}
            sub, pred = runs.sel(pick), models.sel(pick)
            setting = {a.name: float(sub[a.name]) for a in axes.optional_axes(normal=True)  # none in today's runs
                       if a.name in sub.coords and sub[a.name].size == 1}
            use = resolved(sub["contact_cells"].mean(ensemble).values, min_cells)
            k_mean, low, high = (sub[v].values for v in ("k_mean", "k_ci_low", "k_ci_high"))
            # the mean over the tiles on every resample of the tiles: (resample, force)
            k_boot = (sub["stiffness"].transpose(ensemble, "force").values[indices].mean(1)
                      if indices is not None else None)
            force = sub["force"].values
            for model in pred["model"].values.tolist():
                k = pred["stiffness"].sel(model=model).values
                ok = use & np.isfinite(k)
                if not ok.any():
                    continue
                dev = k[ok] / k_mean[ok] - 1
                banded = np.isfinite(low[ok]) & np.isfinite(high[ok])
                inside = ((k[ok] >= low[ok]) & (k[ok] <= high[ok]))[banded]
                spread = {f"{c}_ci_{e}": math.nan for c in ("max_rel_dev", "rms_rel_dev") for e in ("low", "high")}
                if k_boot is not None:
                    boot = k[ok] / k_boot[:, ok] - 1
                    for column, samples in (("max_rel_dev", np.abs(boot).max(-1)),
                                            ("rms_rel_dev", np.sqrt(np.mean(boot**2, -1)))):
                        spread[f"{column}_ci_low"], spread[f"{column}_ci_high"] = interval(samples, fit.confidence)
                rows.append({"scan": name, "kind": kind, "radius": radius, "model": model,
                             "max_rel_dev": float(np.abs(dev).max()), "rms_rel_dev": float(np.sqrt(np.mean(dev**2))),
                             "inside_band": float(inside.mean()) if banded.any() else math.nan,
                             "n_loads": int(ok.sum()), "force_min_N": float(force[ok].min()),
                             "force_max_N": float(force[ok].max()), "tiles": int(count),
                             unmodelled.COLUMN: unmodelled.not_modelled(model, setting, length) if setting else "",
                             "outside_range": outside_range(model, values), **spread})
    table = pd.DataFrame(rows) if rows else pd.DataFrame(columns=[
        "scan", "kind", "radius", "model", "max_rel_dev", "rms_rel_dev", "inside_band", "n_loads", "force_min_N",
        "force_max_N", "tiles", unmodelled.COLUMN, "outside_range", "rank"])
    if len(table):
        table["rank"] = unmodelled.rank(table, ["kind", "radius"])
    return table
