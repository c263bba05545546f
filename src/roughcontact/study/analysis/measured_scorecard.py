"""The measured scorecard: every model of the registry against the tiles of one scan.

For each kind (sphere radii, the flat tile) and model of :mod:`roughcontact.models.scorecard`
(the predictions of :func:`roughcontact.study.analysis.measured_spectrum.run_spectrum`), over the
resolved loads (mean contact cells over the tiles ≥ ``fit.zeta.min_cells``, the study's one
rule :func:`roughcontact.study.analysis.ensemble.resolved`) where the model has a value:

* ``max_rel_dev = max_F |k_model/k_mean − 1|`` and ``rms_rel_dev``, against the mean over tiles;
* ``inside_band``: the fraction of those loads where the model lies inside the bootstrap
  interval of the mean over tiles (``k_ci_low ≤ k_model ≤ k_ci_high``; NaN with one tile).

``not_modelled`` (:mod:`roughcontact.study.analysis.not_modelled`): the optional axes at which the
merged runs are off the paper's setting (a coordinate of the merged group; a measured run is a
paraboloid without roll-off, cutoff or hardness, so today none) and which the model does not
declare; such a row keeps its deviations but has no ``rank``.

``outside_range``: why the scan's fitted H (``hurst`` of the spectrum fit) lies outside the
model's stated range (:attr:`roughcontact.models.scorecard.Model.ranges`; empty inside): the row
is flagged, keeps its deviations and rank, and is not a model to recommend for this scan.

Stiffnesses are compared in N/m at the same forces (N).
"""
from __future__ import annotations

import math

import numpy as np

from ...models import scorecard as registry
from ..config import axes
from . import not_modelled as unmodelled
from .ensemble import resolved
from ..config.settings import StudySettings

__all__ = ["measured_scorecard", "run_measured_scorecard", "MEASURED_SCORECARD_LEAD"]

#: the lead paragraph of a scan's scorecard page in the report
MEASURED_SCORECARD_LEAD = (
    "Each model of the scorecard predicts the scan's stiffness k(F) from its spectrum fit (H and h_rms "
    "fitted; Greenwood-Tripp and Persson read the measured spectrum itself); max_rel_dev is the largest "
    "|k_model/k_mean - 1| over the resolved loads against the mean over the tiles, rms_rel_dev the rms of "
    "the same deviations, inside_band the fraction of those loads where the model lies inside the bootstrap "
    "interval of the mean over the tiles; not_modelled names the optional axes off the paper's value that "
    "the model does not model (a measured run is at the paper's value of every optional axis, so it is "
    "empty): such a row has no rank; outside_range names why the scan's fitted H lies outside the model's stated "
    "range of validity (the row is flagged, not hidden, and not a model to recommend). The CSV beside this page holds every digit.")


def measured_scorecard(merged: dict, predicted: dict, *, name: str, min_cells: int):
    """One row per (kind, radius, model) of a scan: *merged* the groups of
    :func:`roughcontact.study.analysis.measured_merge.merge_surface`, *predicted* those of
    :func:`roughcontact.study.analysis.measured_spectrum.run_spectrum` (the ``sphere`` and ``flat`` groups)."""
    import pandas as pd

    rows = []
    spectrum = predicted.get("spectrum")
    length = float(spectrum.attrs.get("tile_length", math.nan)) if spectrum is not None else math.nan
    fitted = {"hurst": float(spectrum.attrs.get("hurst", math.nan)) if spectrum is not None else math.nan}
    for kind in ("sphere", "flat"):
        if kind not in merged or kind not in predicted:
            continue
        runs, models = merged[kind], predicted[kind]
        if not np.allclose(runs["force_normalized"].values, models["force_normalized"].values, rtol=1e-12, atol=0):
            raise ValueError(f"{name}: the models' forces are not the runs' forces (rerun measured_spectrum)")
        ensemble = [d for d in runs["stiffness"].dims if d not in ("radius", "force")][0]   # tile or seed
        radii = runs["radius"].values.tolist() if kind == "sphere" else [math.inf]
        for radius in radii:
            pick = {"radius": radius} if kind == "sphere" else {}
            sub, pred = runs.sel(pick), models.sel(pick)
            setting = {a.name: float(sub[a.name]) for a in axes.optional_axes()     # none in today's runs
                       if a.name in sub.coords and sub[a.name].size == 1}
            use = resolved(sub["contact_cells"].mean(ensemble).values, min_cells)
            k_mean, low, high = (sub[v].values for v in ("k_mean", "k_ci_low", "k_ci_high"))
            force = sub["force"].values
            for model in pred["model"].values.tolist():
                k = pred["stiffness"].sel(model=model).values
                ok = use & np.isfinite(k)
                if not ok.any():
                    continue
                dev = k[ok] / k_mean[ok] - 1
                banded = np.isfinite(low[ok]) & np.isfinite(high[ok])
                inside = ((k[ok] >= low[ok]) & (k[ok] <= high[ok]))[banded]
                rows.append({"scan": name, "kind": kind, "radius": radius, "model": model,
                             "max_rel_dev": float(np.abs(dev).max()), "rms_rel_dev": float(np.sqrt(np.mean(dev**2))),
                             "inside_band": float(inside.mean()) if banded.any() else math.nan,
                             "n_loads": int(ok.sum()), "force_min_N": float(force[ok].min()),
                             "force_max_N": float(force[ok].max()), "tiles": int(runs.sizes[ensemble]),
                             unmodelled.COLUMN: unmodelled.not_modelled(model, setting, length) if setting else "",
                             "outside_range": registry.models()[model].outside(fitted)
                             if model in registry.models() else ""})
    table = pd.DataFrame(rows)
    if len(table):
        table["rank"] = unmodelled.rank(table, ["kind", "radius"])
    return table


def run_measured_scorecard(study, name: str, merged_file, spectrum_file, out_csv, out_html) -> None:
    """``measured_scorecard`` rule: the scorecard of one scan as CSV and as an HTML page of the report."""
    from ..files.io import read_groups, write_csv
    from ..report.tables import write_html_table

    table = measured_scorecard(read_groups(merged_file), read_groups(spectrum_file), name=name,
                               min_cells=StudySettings.of(study).fit.zeta.min_cells)
    write_csv(table, out_csv)
    write_html_table(table, out_html, title=f"Model scorecard of the scan {name}", lead=MEASURED_SCORECARD_LEAD,
                     verdict_columns=(), first=("kind", "radius", "model", "rank", unmodelled.COLUMN, "outside_range", "max_rel_dev",
                                                "rms_rel_dev", "inside_band", "n_loads"))
