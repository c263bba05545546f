"""The scorecard's deviations against ensembles built from a model itself (closed forms)."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.models import paper
from roughcontact.study.analysis import scorecard
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.config.settings import StudySettings

#: the study the groups stand for: one sphere combination on 129², 20 cells, 200 resamples, 95 %
CFG = StudySettings.of(resolve_config({
    "grid": {"n": 129}, "hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 4,
    "forces": {"sphere": {"from": 1e-6, "to": 1e-2, "count": 9}},
    "fit": {"resolved_cells": 20, "bootstrap": 200, "slopes": {"high_min_ratio": 3.0}}}))
HURST, RADIUS, H_RMS, ZETA = 0.7, 0.5, 9e-3, 1.05
FORCE = np.geomspace(1e-6, 1e-2, 9)


def _groups(scale_per_seed: np.ndarray) -> dict:
    """A merged sphere group of one combination whose seed s has k = scale[s] × eq. 16 (fitted ζ)."""
    k16 = paper.stiffness_from_force(FORCE, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=1.0, e_star=1.0,
                                     zeta=ZETA)
    seeds = len(scale_per_seed)
    k = scale_per_seed[:, None] * k16[None, :]
    cells = np.where(FORCE >= 1e-5, 100, 5)[None, :].repeat(seeds, 0)   # loads below 1e-5 are not resolved
    axes = {"hurst": [HURST], "radius": [RADIUS], "exponent": [2.0], "h_rms": [H_RMS], "rolloff": [1.0],
            "cutoff": [0.0], "hardness": [math.inf]}
    dims = (*axes, "seed", "force")
    shape = (1,) * len(axes)
    ds = xr.Dataset({"stiffness": (dims, k.reshape(shape + k.shape)),
                     "contact_cells": (dims, cells.reshape(shape + cells.shape))},
                    coords={**axes, "seed": np.arange(seeds), "force": FORCE})
    return {"sphere": ds}


def _row(table, model):
    return table[table["model"] == model].iloc[0]


def test_a_model_equal_to_the_ensemble_has_no_deviation():
    table, _ = scorecard.scorecard(_groups(np.ones(4)), pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    row = _row(table, "eq16_fitted")
    assert row["max_rel_dev"] == pytest.approx(0.0, abs=1e-12), "eq16_fitted against itself"
    assert row["n_loads"] == int((FORCE >= 1e-5).sum()), "the unresolved loads are left out"
    assert row["rank"] == 1, "the exact model ranks first"


def test_a_uniform_offset_gives_its_relative_deviation():
    """Every seed 10 % stiffer than eq. 16: |k16/(1.1 k16) − 1| = 1/11 at every load, exactly,
    and every bootstrap resample has the same mean, so the interval is that point."""
    table, curves = scorecard.scorecard(_groups(np.full(5, 1.1)), pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    row = _row(table, "eq16_fitted")
    assert row["max_rel_dev"] == pytest.approx(1 / 11, rel=1e-12), "max deviation of a 10 % offset"
    assert row["rms_rel_dev"] == pytest.approx(1 / 11, rel=1e-12), "rms deviation of a 10 % offset"
    assert row["max_rel_dev_ci_low"] == pytest.approx(1 / 11, rel=1e-12), "interval of identical seeds"
    band = curves["H0.7_R0.5_h0.009"]
    assert float(np.abs(band["band_high"]).max()) == pytest.approx(0.0, abs=1e-12), "no scatter, no band"


def test_the_interval_widens_with_the_scatter_of_the_seeds():
    rng = np.random.default_rng(3)
    table, _ = scorecard.scorecard(_groups(1 + 0.1 * rng.standard_normal(20)),
                                   pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    row = _row(table, "eq16_fitted")
    assert row["max_rel_dev_ci_low"] <= row["max_rel_dev"] <= row["max_rel_dev_ci_high"], "point inside its interval"
    assert row["max_rel_dev_ci_high"] - row["max_rel_dev_ci_low"] > 0.01, "20 seeds of 10 % scatter: a real interval"


def test_models_that_do_not_apply_have_no_row():
    groups = _groups(np.ones(3))
    groups["sphere"] = groups["sphere"].assign_coords(cutoff=[0.05])
    table, _ = scorecard.scorecard(groups, pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    assert "greenwood_tripp" not in set(table["model"]), "GT on a spectrum with a cutoff"
    assert {"eq16_paper", "eq16_fitted"} <= set(table["model"]), set(table["model"])


def _constant_offset_table(scale):
    return scorecard.scorecard(_groups(scale), pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)[0]


@pytest.mark.parametrize("branch", ["low", "high"])
def test_systematic_deviation_of_a_constant_offset(branch):
    """Seeds at 1.08 ... 1.12 x eq. 16: eq16_fitted lies 1/mean - 1 below the ensemble mean at every
    load, so its weighted mean deviation on either branch is that constant (to round-off)."""
    scale = np.linspace(1.08, 1.12, 8)
    row = _row(_constant_offset_table(scale), "eq16_fitted")
    assert row[f"systematic_{branch}"] == pytest.approx(1 / scale.mean() - 1, rel=1e-12), f"{branch} branch"


def test_significant_systematic_deviation_differs_from_zero():
    row = _row(_constant_offset_table(np.linspace(1.08, 1.12, 8)), "eq16_fitted")
    assert row["systematic_high_verdict"] == "differs", row[["systematic_high", "systematic_high_ci_low",
                                                              "systematic_high_ci_high"]].to_dict()


def test_branches_split_at_the_crossover_force():
    """Resolved loads (F >= 1e-5) below and above eq. 17's F_tr with the fitted zeta."""
    row = _row(_constant_offset_table(np.linspace(1.08, 1.12, 8)), "eq16_fitted")
    f_tr = paper.crossover_force(RADIUS, hurst=HURST, h_rms=H_RMS, length=1.0, e_star=1.0, zeta=ZETA)
    resolved = FORCE >= 1e-5
    assert (row["n_loads_low"], row["n_loads_high"]) == (int((resolved & (FORCE < f_tr)).sum()),
                                                         int((resolved & (FORCE >= f_tr)).sum())), "branch sizes"


def test_a_model_equal_to_the_ensemble_mean_is_inside_its_band():
    """Seeds at 1 +- 5 % x eq. 16 (mean exactly eq. 16): eq16_fitted deviates by 0, inside the band."""
    row = _row(_constant_offset_table(1 + 0.05 * np.array([1.0, -1.0] * 4)), "eq16_fitted")
    assert row["inside_band"] == 1.0, f"inside_band {row['inside_band']}"


def test_a_model_off_a_sharp_ensemble_is_outside_its_band():
    """Every seed at 1.2 x eq. 16 (no scatter: the band is [0, 0]): eq16_fitted is 1/1.2 - 1 off."""
    row = _row(_constant_offset_table(np.full(4, 1.2)), "eq16_fitted")
    assert row["inside_band"] == 0.0, f"inside_band {row['inside_band']}"


def _grid_table(g: float) -> pd.DataFrame:
    """A grid error table (study.analysis.grid_error) of the one combination: k_coarse/k − 1 = g at every load."""
    return pd.DataFrame({"hurst": HURST, "radius": RADIUS, "exponent": 2.0, "h_rms": H_RMS, "rolloff": 1.0,
                         "cutoff": 0.0, "hardness": math.inf, "force_normalized": FORCE, "grid_error": g})


def _with_grid(scale, g):
    zeta = pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]})
    return _row(scorecard.scorecard(_groups(scale), zeta, CFG, _grid_table(g))[0], "eq16_fitted")


def test_grid_error_columns_are_nan_without_a_grid_error():
    row = _row(_constant_offset_table(np.ones(4)), "eq16_fitted")
    assert math.isnan(row["grid_error_max"]), "no grid.coarse: the grid-error column is NaN"


def test_the_row_says_why_its_grid_error_is_not_measured():
    row = _row(_constant_offset_table(np.ones(4)), "eq16_fitted")
    assert row["grid_error_note"] == scorecard.NOT_MEASURED, row["grid_error_note"]


def test_the_total_verdict_says_the_grid_error_is_not_measured():
    row = _row(_constant_offset_table(np.ones(4)), "eq16_fitted")
    assert row["systematic_high_total_verdict"] == "untested: grid error not measured", row.to_dict()


def test_the_estimate_is_read_before_the_raw_difference():
    """A table with grid_error = 30 % and its estimate 4 %: the scorecard's grid error is the estimate."""
    zeta = pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]})
    table = _grid_table(0.3).assign(grid_error_estimate=0.04)
    row = _row(scorecard.scorecard(_groups(np.ones(4)), zeta, CFG, table)[0], "eq16_fitted")
    assert row["grid_error_max"] == pytest.approx(0.04, rel=1e-12), "the estimate"


def test_grid_error_max_is_the_largest_bound():
    """g = −4 % at every load: the largest |g| over the resolved loads is 0.04 (to round-off)."""
    assert _with_grid(np.ones(4), -0.04)["grid_error_max"] == pytest.approx(0.04, rel=1e-12), "|g|"


def test_grid_error_explains_an_offset_the_band_does_not():
    """Seeds at 1.08 ... 1.12 × eq. 16 (a −9.1 % model deviation, band ±1 %): outside the sampling band
    at every load and a significant systematic deviation; with a grid error of 12 % at every load the
    widened band, √(1 %² + 12 %²), holds it and the verdict with the grid error is consistent."""
    row = _with_grid(np.linspace(1.08, 1.12, 8), 0.12)
    assert row["inside_band"] == pytest.approx(0.0, abs=1e-12), "outside the sampling band"
    assert row["inside_band_total"] == pytest.approx(1.0, abs=1e-12), "inside the band with the grid error"
    assert row["systematic_high_total_verdict"] == "consistent", row.to_dict()


def test_small_grid_error_leaves_a_model_error():
    """The same offset with a 1 % grid error: still a model error (differs) with the grid error added."""
    row = _with_grid(np.linspace(1.08, 1.12, 8), 0.01)
    assert row["systematic_high_total_verdict"] == "differs", row.to_dict()
    assert row["grid_resolved"] == pytest.approx(0.0, abs=1e-12), "1 % is more than half a ±1 % band"
