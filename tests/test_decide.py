"""The scorecard's decision (roughcontact.study.analysis.decision): recommended, tied, worse, not scored."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.models import paper
from roughcontact.models import scorecard as registry
from roughcontact.study.analysis import decision, scorecard
from roughcontact.study.report import scorecard as report_scorecard
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.analysis.statistics import bootstrap_indices
from roughcontact.study.config.settings import StudySettings

FORCE = np.geomspace(1e-5, 1e-2, 6)
K_SHAPE = FORCE ** 0.6          # any positive stiffness curve: the decision reads ratios only
LEVEL = 0.95


def _ensemble(scatter: float, seeds: int = 6, seed: int = 1):
    """k per seed and load (seed s scaled by 1 + scatter·N(0, 1)) and its bootstrap means."""
    rng = np.random.default_rng(seed)
    k = (1 + scatter * rng.standard_normal(seeds))[:, None] * K_SHAPE[None, :]
    k_boot = k[bootstrap_indices(seeds, 400)].mean(1)
    return k, k_boot


def _row(name, factor, k, k_boot, combination="c", g=None, **extra):
    """A scorecard row of a model ``factor × k̄`` on one branch (every load above the crossover) and
    the decision's inputs; *g*: a grid error at every load (``None``: not measured)."""
    k_mean = k.mean(0)
    use = np.ones(FORCE.size, dtype=bool)
    row = {"model": name, "combination": combination, "not_modelled": "", decision.OUTSIDE: "", **extra}
    grid = None if g is None else np.full(FORCE.size, g)
    return row, decision.inputs(factor * k_mean, k_mean, k_boot, use, {"low": ~use, "high": use}, grid)


def _decide(*specs, scatter=0.0):
    k, k_boot = _ensemble(scatter)
    built = [_row(name, factor, k, k_boot, **extra) for name, factor, extra in specs]
    rows = decision.decide([r for r, _ in built], [b for _, b in built], LEVEL)
    return {r["model"]: r for r in rows}


def test_the_exact_model_is_recommended():
    rows = _decide(("exact", 1.0, {}), ("off", 1.1, {}), scatter=0.05)
    assert rows["exact"]["decision"] == "recommended", rows["exact"]


def test_a_model_10_percent_off_is_not_tied_with_the_exact_one():
    rows = _decide(("exact", 1.0, {}), ("off", 1.1, {}), scatter=0.05)
    assert rows["off"]["decision"] == "worse", rows["off"]


def test_the_score_of_a_uniform_offset_is_the_offset():
    """Identical seeds: k̄ on every resample, so S = |1.1 − 1| = 0.1 exactly."""
    rows = _decide(("exact", 1.0, {}), ("off", 1.1, {}))
    assert rows["off"]["decision_score"] == pytest.approx(0.1, rel=1e-12), "S of a 10 % offset"


def test_the_paired_difference_of_identical_seeds_is_a_point():
    rows = _decide(("exact", 1.0, {}), ("off", 1.1, {}))
    assert rows["off"]["difference_ci_low"] == pytest.approx(0.1, rel=1e-12), "D = 0.1 on every resample"


def test_two_models_within_the_sampling_band_are_tied():
    """10 % scatter over 6 seeds: a band of several per cent; +0.2 % and −0.3 % are inside it."""
    rows = _decide(("a", 1.002, {}), ("b", 0.997, {}), scatter=0.10)
    assert {rows["a"]["decision"], rows["b"]["decision"]} == {"recommended", "tied"}, rows


def test_a_grid_error_larger_than_half_the_difference_ties_them():
    """D = 0.1 and ĝ = 0.06: D_low = 0.1 ≤ 2ĝ = 0.12, the grid could swap the two."""
    rows = _decide(("exact", 1.0, {"g": 0.06}), ("off", 1.1, {"g": 0.06}))
    assert rows["off"]["decision"] == "tied", rows["off"]


def test_the_grid_error_is_added_to_the_score():
    rows = _decide(("exact", 1.0, {"g": 0.06}), ("off", 1.1, {"g": -0.06}))
    assert rows["off"]["decision_score"] == pytest.approx(0.16, rel=1e-12), "|0.1| + |−0.06| at every load"


def test_the_grid_error_is_said_measured_or_not():
    rows = _decide(("exact", 1.0, {"g": 0.01}), ("off", 1.1, {}))
    assert [rows["exact"]["grid_error_measured"], rows["off"]["grid_error_measured"]] == [True, False]


@pytest.mark.parametrize("column, text", [("not_modelled", "hardness = 0.5"),
                                          (decision.OUTSIDE, "hurst = 1.4 outside [0, 1]")])
def test_an_unscored_row_is_never_recommended(column, text):
    """The exact model is not modelled / out of range: the 10 % model is recommended instead."""
    rows = _decide(("exact", 1.0, {column: text}), ("off", 1.1, {}))
    assert rows["exact"]["decision"] == "not scored", rows["exact"]
    assert rows["off"]["recommended"], rows["off"]


def test_no_scored_row_no_recommendation():
    rows = _decide(("exact", 1.0, {"not_modelled": "cutoff = 0.1"}))
    assert not rows["exact"]["recommended"], rows["exact"]


def test_a_row_without_inputs_is_not_scored():
    k, k_boot = _ensemble(0.0)
    rows = decision.decide([_row("exact", 1.0, k, k_boot)[0], _row("off", 1.1, k, k_boot)[0]],
                           [None, _row("off", 1.1, k, k_boot)[1]], LEVEL)
    assert rows[0]["decision"] == "not scored", rows[0]


def _small_load_miss():
    """Exact at the Hertz end, 50 % off at the smallest load (2 % scatter of the seeds)."""
    k, k_boot = _ensemble(0.02)
    k_mean = k.mean(0)
    use = np.ones(FORCE.size, dtype=bool)
    branches = {"low": ~use, "high": use}
    off = k_mean * np.where(np.arange(FORCE.size) == 0, 1.5, 1.0)
    rows = decision.decide([{"model": "exact", "combination": "c"}, {"model": "off", "combination": "c"}],
                           [decision.inputs(k_mean, k_mean, k_boot, use, branches),
                            decision.inputs(off, k_mean, k_boot, use, branches)], LEVEL)
    return rows


def test_a_miss_at_one_small_load_counts_in_the_rms():
    """Every resolved load counts alike: S = 0.5/√6 (an inverse-variance weighted mean, dominated by
    the precise large loads, would hide it)."""
    rows = _small_load_miss()
    assert rows[1]["decision_score"] == pytest.approx(0.5 / math.sqrt(FORCE.size), rel=1e-12), "rms of one 50 %"


def test_a_miss_at_one_small_load_is_worse():
    rows = _small_load_miss()
    assert rows[1]["decision"] == "worse", rows[1]


def test_the_sorted_table_puts_the_recommended_row_first():
    rows = _decide(("off", 1.1, {}), ("exact", 1.0, {}), ("far", 1.3, {}))
    table = decision.sort(pd.DataFrame(list(rows.values())))
    assert list(table["model"]) == ["exact", "off", "far"], table


def test_the_matrix_marks_the_recommended_model():
    rows = _decide(("exact", 1.0, {}), ("off", 1.1, {}))
    cells = decision.matrix(pd.DataFrame(list(rows.values())))
    assert cells.loc["c", "exact"] == "★ 0.0 %", cells


def test_a_range_names_why_a_value_is_outside():
    model = registry.Model("m", "m", lambda f, s: None, ranges=(registry.Range("hurst", 0.0, 1.0, "src"),))
    assert model.outside({"hurst": 1.4}) == "hurst = 1.4 outside [0, 1] (src)"


def test_a_value_inside_the_range_is_not_flagged():
    model = registry.Model("m", "m", lambda f, s: None, ranges=(registry.Range("hurst", 0.0, 1.0),))
    assert model.outside({"hurst": 1.0, "radius": 3.0}) == ""


# --- end to end: the scorecard of one synthetic combination at H = 1.4 ---------------------------

HURST, RADIUS, H_RMS, ZETA = 1.4, 0.5, 9e-3, 0.8
CFG = StudySettings.of(resolve_config({
    "grid": {"n": 129}, "hurst": [HURST], "radius": [RADIUS], "h_rms": [H_RMS], "seeds": 4,
    "forces": {"sphere": {"from": 1e-5, "to": 1e-2, "count": 6}},
    "fit": {"resolved_cells": 20, "bootstrap": 200, "slopes": {"high_min_ratio": 3.0}}}))


def _table(hurst, g=None):
    """The scorecard of one combination whose every seed equals eq. 16 with the fitted ζ (eq16_fitted
    exact); *g*: a grid error ``k_coarse/k − 1 = g`` at every load (``None``: not measured)."""
    k16 = paper.stiffness_from_force(FORCE, radius=RADIUS, hurst=hurst, h_rms=H_RMS, length=1.0, e_star=1.0,
                                     zeta=ZETA)
    k = np.repeat(k16[None, :], 4, 0)
    cells = np.full_like(k, 100)
    coords = {"hurst": [hurst], "radius": [RADIUS], "exponent": [2.0], "h_rms": [H_RMS], "rolloff": [1.0],
              "cutoff": [0.0], "hardness": [math.inf]}
    dims = (*coords, "seed", "force")
    shape = (1,) * len(coords)
    ds = xr.Dataset({"stiffness": (dims, k.reshape(shape + k.shape)),
                     "contact_cells": (dims, cells.reshape(shape + cells.shape))},
                    coords={**coords, "seed": np.arange(4), "force": FORCE})
    grid = None if g is None else pd.DataFrame({**{a: v[0] for a, v in coords.items()}, "force_normalized": FORCE,
                                                "grid_error": g})
    table, _ = scorecard.scorecard({"sphere": ds}, pd.DataFrame({"hurst": [hurst], "zeta": [ZETA]}), CFG, grid)
    return table


@pytest.fixture(scope="module")
def out_of_range_table():
    """eq16_fitted is exact, but H = 1.4 lies outside its stated range."""
    return _table(HURST)


@pytest.fixture(scope="module")
def grid_table():
    """H = 0.7 (inside every self-affine range) with a 5 % grid error at every load."""
    return _table(0.7, 0.05)


def test_the_exact_model_with_a_grid_error_is_recommended(grid_table):
    row = grid_table[grid_table["recommended"]].iloc[0]
    assert row["model"] == "eq16_fitted", grid_table[["model", "decision", "decision_score"]]


def test_the_score_of_the_exact_model_is_the_grid_error(grid_table):
    """No systematic deviation, |g| = 0.05 at every load: S = 0 + 0.05."""
    row = grid_table[grid_table["model"] == "eq16_fitted"].iloc[0]
    assert row["decision_score"] == pytest.approx(0.05, rel=1e-12), row["decision_score"]


def test_a_measured_grid_error_is_said_so(grid_table):
    assert bool(grid_table["grid_error_measured"].all()), grid_table["grid_error_measured"]


def test_an_unmeasured_grid_error_is_said_so(out_of_range_table):
    assert not bool(out_of_range_table["grid_error_measured"].any()), out_of_range_table["grid_error_measured"]


def test_the_page_says_the_grid_error_is_not_measured(out_of_range_table):
    assert "NOT measured" in report_scorecard.scorecard_lead(out_of_range_table), "lead"


def test_the_exact_model_outside_its_range_is_flagged(out_of_range_table):
    row = out_of_range_table[out_of_range_table["model"] == "eq16_fitted"].iloc[0]
    assert row[decision.OUTSIDE].startswith("hurst = 1.4 outside [0, 1]"), row[decision.OUTSIDE]


def test_the_exact_model_outside_its_range_is_not_recommended(out_of_range_table):
    row = out_of_range_table[out_of_range_table["model"] == "eq16_fitted"].iloc[0]
    assert row["decision"] == "not scored", row["decision"]


def test_exactly_one_row_is_recommended(out_of_range_table):
    assert int(out_of_range_table["recommended"].sum()) == 1, out_of_range_table[["model", "decision"]]


def test_the_recommended_row_is_a_scored_one(out_of_range_table):
    row = out_of_range_table[out_of_range_table["recommended"]].iloc[0]
    assert row[decision.OUTSIDE] == "" and row["not_modelled"] == "", row


# --- the "which model when" table of the models guide --------------------------------------------

def test_the_guide_holds_the_table_the_committed_pages_give():
    from roughcontact.study.report import which_model

    assert which_model.update_guide(check=True), "rerun: PYTHONPATH=src python -m roughcontact.study.report.which_model"


def test_each_committed_combination_with_a_scored_model_has_one_recommendation():
    from roughcontact.study.report import which_model

    decided = which_model.decide_pages(which_model.read_pages())
    scored = decided[decided["decision"] != "not scored"]
    counts = scored.groupby(["preset", "combination"])["decision"].apply(lambda d: int((d == "recommended").sum()))
    assert set(counts) == {1}, counts[counts != 1]


def test_a_committed_row_above_h_1_is_not_scored():
    from roughcontact.study.report import which_model

    decided = which_model.decide_pages(which_model.read_pages())
    rows = decided[decided["combination"].str.startswith("H1.4_") & (decided["model"] == "eq16_paper")]
    assert len(rows) and set(rows["decision"]) == {"not scored"}, rows[["combination", "decision"]]


def _scan(hurst):
    """A scan's merged runs (k = 1) and eq16_paper's prediction (k = 1.2), its fit at *hurst*."""
    force = np.geomspace(1e-6, 1e-3, 4)
    runs = xr.Dataset({"stiffness": (("radius", "tile", "force"), np.ones((1, 3, 4))),
                       "contact_cells": (("radius", "tile", "force"), np.full((1, 3, 4), 100)),
                       **{v: (("radius", "force"), np.ones((1, 4))) for v in ("k_mean", "k_ci_low", "k_ci_high")}},
                      coords={"radius": [0.5], "force": force, "force_normalized": ("force", force)})
    models = xr.Dataset({"stiffness": (("model", "radius", "force"), np.full((1, 1, 4), 1.2))},
                        coords={"model": ["eq16_paper"], "radius": [0.5], "force": force,
                                "force_normalized": ("force", force)})
    return {"sphere": runs}, {"sphere": models, "spectrum": xr.Dataset(attrs={"tile_length": 1.0, "hurst": hurst})}


def test_a_scan_fitted_above_h_1_flags_the_self_affine_model():
    from roughcontact.study.analysis.measured_scorecard import measured_scorecard

    table = measured_scorecard(*_scan(1.3), name="scan", min_cells=10)
    assert table["outside_range"].iloc[0].startswith("hurst = 1.3 outside [0, 1]"), table["outside_range"].iloc[0]


def test_a_scan_fitted_inside_the_range_is_not_flagged():
    from roughcontact.study.analysis.measured_scorecard import measured_scorecard

    table = measured_scorecard(*_scan(0.8), name="scan", min_cells=10)
    assert table["outside_range"].iloc[0] == "", table["outside_range"].iloc[0]


def test_the_page_shows_the_matrix_above_the_long_table(out_of_range_table):
    from roughcontact.study.report.tables import html_table

    page = html_table(out_of_range_table, title="t", lead="l", above=decision.matrix_html(out_of_range_table))
    assert page.index("★") < page.index("<h2>Every row</h2>"), "the recommended mark above the rows"


def test_the_matrix_marks_the_out_of_range_model_not_scored(out_of_range_table):
    cells = decision.matrix(out_of_range_table)
    assert cells.iloc[0]["eq16_fitted"] == "n.s.", cells


def test_the_recommended_row_lists_the_tied_models():
    rows = _decide(("a", 1.002, {}), ("b", 0.997, {}), ("far", 1.5, {}), scatter=0.10)
    best = [r for r in rows.values() if r["recommended"]][0]
    assert best["tied_models"] == next(m for m in ("a", "b") if m != best["model"]), best


def test_a_grid_table_without_this_combination_is_not_measured():
    rows = _decide(("exact", 1.0, {"g": math.nan}), ("off", 1.1, {"g": math.nan}))
    assert not rows["exact"]["grid_error_measured"], rows["exact"]


def _branch_row(systematic, verdict="consistent", inside=0.9, measured=True):
    """A row with both branches resolved, each of the given systematic deviation and verdict."""
    row = {"inside_band": inside}
    for b in ("low", "high"):
        row.update({f"n_loads_{b}": 5, f"systematic_{b}": systematic, f"systematic_{b}_verdict": verdict})
        if measured:
            row[f"systematic_{b}_total_verdict"] = verdict
    if measured:
        row["inside_band_total"] = inside
    return row


def test_within_three_percent_holds():
    assert decision.holds(_branch_row(0.029, verdict="differs")), "2.9 %, significant but within 3 %"


def test_within_five_percent_and_consistent_holds():
    assert decision.holds(_branch_row(0.045)), "4.5 %, consistent with 0 with the grid error"


def test_within_five_percent_but_significant_does_not_hold():
    assert not decision.holds(_branch_row(0.045, verdict="differs")), "4.5 %, significant"


def test_outside_the_band_at_a_quarter_of_the_loads_does_not_hold():
    assert not decision.holds(_branch_row(0.01, inside=0.75)), "inside at 75 % < 80 %"


def test_without_a_grid_error_the_sampling_verdict_decides():
    assert not decision.holds(_branch_row(0.045, verdict="differs", measured=False)), "no total verdict"


def test_one_resolved_branch_does_not_hold():
    """Within 1 % on the high branch, no resolved load on the low one: a model holds on both or not
    at all (models.csv and the pages say the same)."""
    row = {**_branch_row(0.01), "n_loads_low": 0, "systematic_low": math.nan}
    assert not decision.holds(row), "one branch"


def test_no_resolved_branch_does_not_hold():
    assert not decision.holds({"n_loads_low": 0, "n_loads_high": 0, "inside_band": 1.0}), "no branch"


def test_a_model_that_holds_is_recommended_over_a_lower_score():
    """'low_s' has the smaller S but does not hold (outside the band at half the loads); 'holds' is
    recommended."""
    rows = _decide(("low_s", 1.01, {**_branch_row(0.01, inside=0.5)}),
                   ("holds", 1.02, {**_branch_row(0.02, inside=0.9)}))
    assert rows["holds"]["decision"] == "recommended", (rows["holds"]["decision"], rows["low_s"]["decision"])


def test_without_a_holding_model_the_lowest_score_is_recommended():
    rows = _decide(("low_s", 1.01, {**_branch_row(0.01, inside=0.5)}),
                   ("high_s", 1.02, {**_branch_row(0.02, inside=0.5)}))
    assert rows["low_s"]["decision"] == "recommended", rows["low_s"]
