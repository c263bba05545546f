"""Local exponents against power laws, and claims (l) and (m) against tables built for them."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from roughcontact.study.analysis import exponents
from roughcontact.study.report import exponents as report_exponents
from roughcontact.study.claims.exponents import exponent_rows
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.analysis.statistics import bootstrap_indices

FORCE = np.geomspace(1e-6, 1e-2, 13)


def _ensemble(beta, scatter, seeds=12, seed=0):
    rng = np.random.default_rng(seed)
    return (1 + scatter * rng.standard_normal((seeds, 1))) * FORCE[None, :] ** beta


@pytest.mark.parametrize("beta", [1 / 3, 1 / 1.7, 1.0])
def test_a_power_law_has_its_exponent_at_every_resolved_load(beta):
    """k = c F^β with seed-to-seed scatter in c only: ln k̄ = ln c̄ + β ln F, so every window
    gives β to round-off and every resample too (a point interval)."""
    k = _ensemble(beta, 0.1)
    cells = np.full(k.shape, 100)
    cells[:, :3] = 5                                   # the first three loads are not resolved
    value, low, high = exponents.local_exponents(FORCE, k, cells, window=3, min_cells=20,
                                                 indices=bootstrap_indices(12, 200), level=0.95)
    inside = np.isfinite(value)
    assert inside.sum() == len(FORCE) - 3 - 2, f"{inside.sum()} windows: not centred on the 3 unresolved loads, the first resolved one or the last"
    assert np.allclose(value[inside], beta, rtol=0, atol=1e-12), f"local exponents {value[inside]} for {beta}"
    assert np.allclose(high[inside] - low[inside], 0, atol=1e-12), "a pure power law has no interval"


def test_the_interval_contains_the_exponent_of_a_noisy_law():
    """Independent 5 % noise per seed and load: the 95 % interval of a 3-load window contains β
    at most loads (the bootstrap's coverage; 20 seeds)."""
    rng = np.random.default_rng(4)
    k = FORCE[None, :] ** 0.6 * (1 + 0.05 * rng.standard_normal((20, FORCE.size)))
    value, low, high = exponents.local_exponents(FORCE, k, np.full(k.shape, 100), window=3, min_cells=20,
                                                 indices=bootstrap_indices(20, 400), level=0.95)
    inside = np.isfinite(value)
    covered = ((low <= 0.6) & (high >= 0.6))[inside].mean()
    assert covered >= 0.8, f"the interval covers 0.6 at {covered:.0%} of the loads"


def _cfg(rolloff):
    """The study the tables stand for: flat and sphere runs of H = 0.8 on 129², 8 seeds."""
    return StudySettings.of(resolve_config({
        "grid": {"n": 129}, "seeds": 8, "hurst": [0.8], "h_rms": [9e-3], "radius": [0.5, math.inf],
        "rolloff": rolloff, "forces": {"sphere": {"from": 1e-6, "to": 1e-2, "count": 13},
                                       "flat": {"from": 1e-6, "to": 1e-4, "count": 13}}}))


def _table(values, ci):
    return pd.DataFrame({"kind": "flat", "hurst": 0.8, "radius": math.inf, "exponent": 2.0, "h_rms": 9e-3,
                         "rolloff": 0.25, "cutoff": 0.0, "hardness": math.inf, "force": FORCE[:len(values)],
                         "local_exponent": values, "ci_low": np.array(values) - ci, "ci_high": np.array(values) + ci})


ZETA = pd.DataFrame({"hurst": [0.8], "exponent": [0.56], "exponent_ci_low": [0.55], "exponent_ci_high": [0.57],
                     "source": ["flat"], "n_seeds": [8], "window": ["contact cells >= 20"]})


def _claim(rows, letter):
    found = [r for r in rows if r["claim"] == letter]
    assert len(found) == 1, f"{len(found)} rows of claim ({letter})"
    return found[0]


def test_claim_l_is_consistent_where_an_interval_reaches_one():
    rows = exponent_rows(_table([0.6, 0.9, 0.97, 0.8], 0.05), ZETA, _cfg([None, 0.25]))
    row = _claim(rows, "l")
    assert row["verdict"] == "consistent", row
    assert row["measured"] == pytest.approx(0.97), "the largest local exponent"


def test_claim_l_differs_where_every_interval_stays_below_one():
    row = _claim(exponent_rows(_table([0.6, 0.7, 0.65], 0.05), ZETA, _cfg([None, 0.25])), "l")
    assert row["verdict"] == "differs", row


def test_claim_l_is_untested_without_a_rolloff():
    row = _claim(exponent_rows(_table([0.6], 0.05), ZETA, _cfg([None])), "l")
    assert row["verdict"] == "untested" and "roll-off" in row["reason"], row


def test_claim_m_compares_the_free_exponent_with_the_prl_law():
    """0.77 − 0.26 H at H = 0.8 is 0.562, inside (0.55, 0.57)."""
    row = _claim(exponent_rows(pd.DataFrame(), ZETA, _cfg([None])), "m")
    assert row["paper_value"] == pytest.approx(0.562, abs=1e-12), "PRL 2012 interpolated at H = 0.8"
    assert row["verdict"] == "consistent", row


def test_the_figure_draws_flat_surfaces_that_have_no_radius():
    """Flat rows carry NaN radius and body exponent; every (H, roll-off) is still a curve."""
    flat = pd.concat([_table([0.6, 0.7], 0.05).assign(radius=np.nan, exponent=np.nan, rolloff=r)
                      for r in (0.25, 1.0)])
    drawn = report_exponents.curves(flat, "flat")
    assert len(drawn) == 2, f"{len(drawn)} curves for two roll-offs"
    assert all("rolloff" in label for label, _ in drawn), [label for label, _ in drawn]
