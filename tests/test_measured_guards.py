"""The measured scan's scorecard (issue #30 item 6): intervals over the tiles, and a scan outside a
model's stated range (fitted H, bandwidth) marks the model's row and the page says so."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from roughcontact.models import scorecard as registry
from roughcontact.study.analysis.measured_scorecard import measured_scorecard, range_note, scan_values
from roughcontact.study.config.resolve import load_config, study_settings

ROOT = Path(__file__).resolve().parents[1]
FIT = study_settings(load_config(ROOT / "presets" / "tiny.yaml")).fit   # 200 resamples, 95 %
#: the tiles' scatter about k = 1 (relative, per tile and load) and the model's k
SCATTER, MODEL_K = 0.1, 1.2


def _scan(tiles: int, *, hurst=0.8, ci=(0.75, 0.85), tile=256, models=("eq16_paper",)):
    """A scan's merged sphere runs over *tiles* tiles (k = 1 ± SCATTER, seeded, every load resolved)
    and the models' predictions (k = MODEL_K), its spectrum fit's H and cells per tile."""
    force = np.geomspace(1e-6, 1e-3, 5)
    k = 1 + SCATTER * np.random.default_rng(3).standard_normal((1, tiles, force.size))
    dims = ("radius", "tile", "force")
    runs = xr.Dataset({"stiffness": (dims, k), "contact_cells": (dims, np.full(k.shape, 100)),
                       "k_mean": (("radius", "force"), k.mean(1)),
                       **{v: (("radius", "force"), np.full((1, force.size), np.nan)) for v in ("k_ci_low", "k_ci_high")}},
                      coords={"radius": [0.5], "force": force, "force_normalized": ("force", force)})
    pred = xr.Dataset({"stiffness": (("model", "radius", "force"), np.full((len(models), 1, force.size), MODEL_K))},
                      coords={"model": list(models), "radius": [0.5], "force": force,
                              "force_normalized": ("force", force)})
    spectrum = xr.Dataset(attrs={"tile_length": 1.0, "hurst": hurst, "hurst_ci_low": ci[0], "hurst_ci_high": ci[1],
                                 "tile": tile})
    return {"sphere": runs}, {"sphere": pred, "spectrum": spectrum}


@pytest.mark.parametrize("column", ["max_rel_dev", "rms_rel_dev"])
def test_the_tile_interval_holds_the_deviation_from_the_tile_mean(column):
    row = measured_scorecard(*_scan(8), name="scan", min_cells=10, fit=FIT).iloc[0]
    assert row[f"{column}_ci_low"] <= row[column] <= row[f"{column}_ci_high"], row


def test_the_tile_interval_shrinks_with_more_tiles():
    """Four times the tiles: the mean over them scatters half as much, so the interval is about half
    as wide (the bound 0.8 leaves room for the bootstrap's percentiles on 4 tiles)."""
    widths = {}
    for tiles in (4, 16):
        row = measured_scorecard(*_scan(tiles), name="scan", min_cells=10, fit=FIT).iloc[0]
        widths[tiles] = row["max_rel_dev_ci_high"] - row["max_rel_dev_ci_low"]
    assert widths[16] < 0.8 * widths[4], widths


def test_without_the_fit_settings_or_with_one_tile_there_is_no_interval():
    for table in (measured_scorecard(*_scan(8), name="scan", min_cells=10),
                  measured_scorecard(*_scan(1), name="scan", min_cells=10, fit=FIT)):
        assert np.isnan(table["max_rel_dev_ci_low"].iloc[0]), table.iloc[0]


def test_a_scan_fitted_above_h_1_marks_the_rows_and_the_page_says_so():
    """The scan of the issue: fitted H = 1.18 [1.17, 1.20], outside eq. 13's H <= 1 and the
    self-affine range, inside the zeta(H) law's 0.1-1.9."""
    merged, predicted = _scan(4, hurst=1.18, ci=(1.17, 1.20), models=("eq16_paper", "mdr", "eq16_law"))
    table = measured_scorecard(merged, predicted, name="scan", min_cells=10, fit=FIT).set_index("model")
    assert table.loc["eq16_paper", "outside_range"].startswith("hurst = 1.18 outside [0, 1]"), table["outside_range"]
    assert table.loc["mdr", "outside_range"].startswith("hurst = 1.18 outside [0, 1]"), table["outside_range"]
    assert table.loc["eq16_law", "outside_range"] == "", table["outside_range"]
    note = range_note(table.reset_index(), predicted["spectrum"].attrs)
    assert note.startswith("The scan's fitted H = 1.18 [1.17, 1.2], bandwidth 128: OUTSIDE the stated range of 2 "
                           "model(s), eq16_paper, mdr"), note


def test_a_scan_inside_every_range_says_so():
    merged, predicted = _scan(4)
    table = measured_scorecard(merged, predicted, name="scan", min_cells=10, fit=FIT)
    assert range_note(table, predicted["spectrum"].attrs).endswith("inside the stated range of every model scored "
                                                                   "here."), range_note(table, predicted["spectrum"].attrs)


def test_a_scan_narrower_than_a_models_stated_bandwidth_marks_its_row(monkeypatch):
    """A model stating a bandwidth of 256-1024 (none of the registry states one today): a scan of
    tiles of 256² holds wavelengths from its side down to 2 cells, a bandwidth of 128."""
    model = registry.Model("banded", "banded: a test model", lambda force, s: None,
                           ranges=(registry.Range("bandwidth", 256, 1024, "calibrated on 513^2 and 2049^2"),))
    registry.models()
    monkeypatch.setitem(registry.MODELS, "banded", model)
    merged, predicted = _scan(4, models=("banded", "eq16_paper"))
    assert scan_values(predicted["spectrum"].attrs)["bandwidth"] == 128, scan_values(predicted["spectrum"].attrs)
    table = measured_scorecard(merged, predicted, name="scan", min_cells=10, fit=FIT).set_index("model")
    assert table.loc["banded", "outside_range"] == "bandwidth = 128 outside [256, 1024] (calibrated on 513^2 and " \
                                                   "2049^2)", table["outside_range"]
    assert table.loc["eq16_paper", "outside_range"] == "", table["outside_range"]
