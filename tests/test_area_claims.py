"""Claims (u), (v), (w) and the area scorecard on ensembles built from the area laws themselves (closed forms),
and the closed form of the end of the one-asperity regime, F_1."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.models import area as area_models
from roughcontact.models.area import laws, three_regime
from roughcontact.models.scorecard import Surface
from roughcontact.study.analysis import area as area_analysis
from roughcontact.study.claims import ClaimInputs, claims
from roughcontact.study.claims.registry import table_rows
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.config.settings import StudySettings

N, HURST, RADIUS = 513, 0.7, 0.5
#: h_rms of the linear claim (F_A = 0.05 E* L², above the sweep) and of the Hertz claim (F_A = 5e-4)
H_LINEAR, H_HERTZ = 9e-3, 2e-3
FORCE = np.geomspace(1e-6, 4e-2, 13)


def _study(h_rms, cutoff=None, radius=RADIUS):
    """One sphere combination on 513² without a cutoff (2 cells per shortest wavelength) or with
    *cutoff* (length), 4 seeds."""
    return StudySettings.of(resolve_config({
        "grid": {"n": N}, "hurst": [HURST], "radius": [radius], "h_rms": [h_rms], "seeds": 4,
        "cutoff": [cutoff], "forces": {"sphere": {"from": 1e-6, "to": 4e-2, "count": 13}}, "fit": {"bootstrap": 200}}))


def _surface(h_rms, cutoff=None, radius=RADIUS):
    return Surface(hurst=HURST, h_rms=h_rms, radius=radius, length=1.0, n=N, e_star=1.0, cutoff=cutoff)


def _slope(h_rms, cutoff=None):
    return area_models.rms_slope(_surface(h_rms, cutoff))


def _groups(area_per_seed: np.ndarray, h_rms, cells=None, cutoff=None, radius=RADIUS) -> dict:
    """A merged sphere group of one combination with the areas *area_per_seed* (seed, force) and
    the contact cells A n²/L² (or *cells*)."""
    seeds = area_per_seed.shape[0]
    cells = np.rint(area_per_seed * N**2).astype(int) if cells is None else cells
    axes = {"hurst": [HURST], "radius": [radius], "exponent": [2.0], "h_rms": [h_rms], "rolloff": [1.0],
            "cutoff": [cutoff or 0.0], "hardness": [math.inf]}
    dims = (*axes, "seed", "force")
    shape = (1,) * len(axes)
    ds = xr.Dataset({"stiffness": (dims, np.ones(shape + area_per_seed.shape)),
                     "contact_area": (dims, area_per_seed.reshape(shape + area_per_seed.shape)),
                     "contact_cells": (dims, cells.reshape(shape + cells.shape))},
                    coords={**axes, "seed": np.arange(seeds), "force": FORCE})
    return {"sphere": ds}


def _rows(letter, h_rms, area=None, cells=None, cutoff=None, radius=RADIUS):
    area = _joined(h_rms) if area is None else area
    inputs = ClaimInputs(cross=pd.DataFrame(), replicates=None, zeta=pd.DataFrame(),
                         study=_study(h_rms, cutoff, radius), groups=_groups(area, h_rms, cells, cutoff, radius))
    return table_rows(claims()[letter], inputs)


#: per-seed factors of the synthetic ensembles: 1 ± 1 %, in pairs, so that the ensemble mean of an
#: even number of seeds is the law itself (to round-off) and a bootstrap over the seeds has an
#: interval (identical seeds give a point, and a point is no verdict)
PAIRED = 1 + 0.01 * np.array([-1.0, 1.0, -0.5, 0.5, -0.25, 0.25, -0.75, 0.75])


def _seeds(area, seeds):
    """*area* (one path) for *seeds* seeds, each times its :data:`PAIRED` factor."""
    return area[None, :] * PAIRED[:seeds, None]


def _joined(h_rms, kappa=2.0, seeds=4):
    """Every seed's area the linear law with *kappa* below F_A (κ = 2) and Hertz above, times its
    seed's :data:`PAIRED` factor."""
    slope = _slope(h_rms)
    linear = laws.linear_area(FORCE, e_star=1.0, rms_slope=slope, kappa=kappa)
    hertz = laws.hertz_area(FORCE, radius=RADIUS, e_star=1.0)
    f_a = laws.area_crossover_force(radius=RADIUS, e_star=1.0, rms_slope=slope)
    return _seeds(np.where(FORCE < f_a, linear, hertz), seeds)


def test_kappa_of_an_ensemble_on_the_linear_law_is_its_kappa():
    """Areas 2 F/(E* h'): claim (u)'s κ is 2 (to round-off) and consistent."""
    kappa = _rows("u", H_LINEAR)[0]
    assert kappa["measured"] == pytest.approx(2.0, rel=1e-12), "kappa of the linear law"
    assert kappa["verdict"] == "consistent", kappa["reason"]


def test_the_exponent_of_a_linear_area_is_one():
    """Areas ∝ F: the log-log slope of claim (u) is 1 (to round-off)."""
    exponent = _rows("u", H_LINEAR)[1]
    assert exponent["measured"] == pytest.approx(1.0, rel=1e-12), "slope of a linear law"


def test_a_linear_area_with_scatter_is_consistent():
    """Areas ∝ F times 5 % scatter per seed and load (8 seeds, seeded): the slope's interval holds 1
    and κ's lies within 10 % of 2."""
    scatter = 1 + 0.05 * np.random.default_rng(7).standard_normal((8, FORCE.size))
    rows = _rows("u", H_LINEAR, _joined(H_LINEAR, seeds=8) * scatter)
    assert rows[1]["verdict"] == "consistent", rows[1]["reason"]
    assert rows[0]["verdict"] == "consistent", rows[0]["reason"]


def test_an_overestimated_kappa_differs():
    """Areas 3.7 F/(E* h') (the under-resolved value of issue 43): κ = 3.7, 85 % above 2: differs."""
    kappa = _rows("u", H_LINEAR, _joined(H_LINEAR, kappa=3.7))[0]
    assert kappa["measured"] == pytest.approx(3.7, rel=1e-12), "kappa of the law"
    assert kappa["verdict"] == "differs", kappa["reason"]


def test_hertz_claim_on_a_hertzian_ensemble_is_consistent():
    """Areas π a² above F_A: A/(π a²) = 1 (to round-off), consistent."""
    hertz = _rows("v", H_HERTZ)[0]
    assert hertz["measured"] == pytest.approx(1.0, rel=1e-12), "Hertz's area against itself"
    assert hertz["verdict"] == "consistent", hertz["reason"]


def test_under_resolved_loads_give_no_verdict():
    """With every load below the 600 contact cells the area needs at 2 cells per shortest
    wavelength (the grid study), both claims are untested: unresolved, and say what is needed."""
    for letter, h_rms in (("u", H_LINEAR), ("v", H_HERTZ)):
        for r in _rows(letter, h_rms, cells=np.full((4, FORCE.size), 599)):
            assert (r["verdict"], r["untested_because"]) == ("untested", "unresolved"), (letter, r["reason"])
            assert ">= 600 mean contact cells" in r["reason"], r["reason"]


@pytest.mark.parametrize("cutoff_cells, needed", [(2.0, 600), (3.9, 600), (4.0, 280), (8.0, 45), (40.0, 20)])
def test_min_area_cells_by_cells_per_wavelength(cutoff_cells, needed):
    """The measured rule: the entry of the largest tabulated λ_s/Δ not above the grid's."""
    assert area_analysis.min_area_cells(cutoff_cells) == needed


def test_scorecard_ranks_the_law_the_ensemble_follows_first():
    """On an ensemble that is the joined law (κ = 2), linear_hertz has no deviation and ranks first;
    Persson's area, κ = 1.6 at small load, is 20 % low there: max deviation ≥ 1 − √(8/π)/2 − 1e-6."""
    table, curves = area_analysis.area_scorecard(_groups(_joined(H_LINEAR), H_LINEAR), _study(H_LINEAR))
    joined = table[table["model"] == "linear_hertz"].iloc[0]
    persson = table[table["model"] == "persson_area"].iloc[0]
    assert joined["max_rel_dev"] == pytest.approx(0.0, abs=1e-12), "the law against itself"
    assert joined["rank"] == 1, "the exact model ranks first"
    assert persson["max_rel_dev"] >= 1 - math.sqrt(8 / math.pi) / 2 - 1e-6, "Persson's kappa is 1.6, not 2"
    assert set(curves) == {joined["combination"]}, "one curve per combination"


def test_area_rule_writes_its_table_page_and_figure(tmp_path):
    """The area rule's run on a merged file: area_models.csv with one row per area model, the HTML page and
    a PNG of the A(F) figure."""
    from roughcontact.study.files.io import read_csv, write_groups
    from roughcontact.study.rules import area as area_rule

    merged = tmp_path / "stiffness.nc"
    write_groups(merged, _groups(_joined(H_LINEAR), H_LINEAR), {})
    out = tmp_path / "area"
    out.mkdir()
    area_rule.run(_study(H_LINEAR), merged, out / "area_models.csv", out / "area_models.html", out / "area.png")
    table = read_csv(out / "area_models.csv")
    assert sorted(table["model"]) == sorted(area_models.models()), "one row per area model"
    assert "<title>Real contact area: model scorecard</title>" in (out / "area_models.html").read_text(), "its title"
    assert (out / "area.png").read_bytes()[:4] == b"\x89PNG", "the figure is a PNG"


def test_systematic_deviation_weighs_each_load_by_its_inverse_variance():
    """The area scorecard's mean deviation per branch is weighted as the stiffness's: deviations
    +0.1 and +0.3 at two loads whose bootstrap variances of the relative mean are v0 and 9 v0 give
    (0.1/v0 + 0.3/(9 v0))/(1/v0 + 1/(9 v0)) = 0.12 (to 1e-12), not the unweighted 0.2."""
    rng = np.random.default_rng(3)
    noise = rng.standard_normal(400)
    noise = (noise - noise.mean()) / noise.std(ddof=1)
    boot = np.stack([1 + 0.01 * noise, 1 + 0.03 * noise], axis=1)          # (resample, load)
    mean = np.ones(2)
    value = area_analysis._systematic(np.array([1.1, 1.3]), mean, boot, np.array([True, True]), 0.95)[0]
    assert value == pytest.approx(0.12, rel=1e-12)


# --- the end of the one-asperity regime, F_1, and the window of claim (u) -----------------------------

#: the cutoff study's spectrum on 513²: λ_c = L/64 (8 cells per shortest wavelength), h_rms = 2e-2, so that
#: 0.1 F_1 (5e-6) lies above two loads of FORCE and F_1 (5e-5) well below 0.1 F_A (7e-3)
CUTOFF, H_SUMMIT = 1.0 / 64, 2e-2


def _summit():
    """``(R_s, F_1, h′_rms, h″_rms)`` of the cutoff spectrum (:func:`area_analysis.area_context`'s)."""
    surface = _surface(H_SUMMIT, CUTOFF)
    curvature = three_regime.rms_curvature(surface)
    slope = area_models.rms_slope(surface)
    summit = three_regime.SUMMIT / curvature
    return summit, laws.single_asperity_force(summit_radius=summit, e_star=1.0, rms_slope=slope), slope, curvature


def test_at_f1_one_summit_s_hertz_area_equals_the_linear_law_s():
    """At F_1, π (3 F_1 R_s/(4E*))^(2/3) = 2 F_1/(E* h′_rms) (relative 1e-10)."""
    summit, f_1, slope, curvature = _summit()
    one = three_regime.summit_area(f_1, e_star=1.0, rms_curvature=curvature)
    assert one == pytest.approx(laws.linear_area(f_1, e_star=1.0, rms_slope=slope), rel=1e-10)


def test_f1_is_the_hertz_crossover_with_the_summit_radius():
    """F_1 = F_A (R_s/R)² (relative 1e-12): the same closed form, R_s for R."""
    summit, f_1, slope, _ = _summit()
    f_a = laws.area_crossover_force(radius=RADIUS, e_star=1.0, rms_slope=slope)
    assert f_1 == pytest.approx(f_a * (summit / RADIUS) ** 2, rel=1e-12)


def test_f1_vanishes_as_the_curvature_grows():
    """F_1 ∝ 1/h″_rms² at fixed h′_rms: a 1000 times sharper summit lowers it 1e6 times (relative 1e-12);
    without a cutoff h″_rms grows with the grid and the one-asperity regime leaves the sweep."""
    summit, f_1, slope, _ = _summit()
    sharp = laws.single_asperity_force(summit_radius=summit / 1000, e_star=1.0, rms_slope=slope)
    assert sharp == pytest.approx(f_1 * 1e-6, rel=1e-12)


def test_below_f1_the_summit_s_area_is_the_larger():
    """At F_1/8 the one-summit area is 8^(1/3) = 2 times the linear law's (relative 1e-10)."""
    summit, f_1, slope, curvature = _summit()
    ratio = (three_regime.summit_area(f_1 / 8, e_star=1.0, rms_curvature=curvature)
             / laws.linear_area(f_1 / 8, e_star=1.0, rms_slope=slope))
    assert ratio == pytest.approx(2.0, rel=1e-10)


def _three_regimes(kappa=2.0, seeds=4):
    """Every seed's area one summit's Hertz area below F_1 (A ∝ F^(2/3)), κ F/(E* h′) from F_1 to F_A,
    Hertz above, on the cutoff spectrum."""
    _, f_1, slope, curvature = _summit()
    one = three_regime.summit_area(FORCE, e_star=1.0, rms_curvature=curvature)
    linear = laws.linear_area(FORCE, e_star=1.0, rms_slope=slope, kappa=kappa)
    hertz = laws.hertz_area(FORCE, radius=RADIUS, e_star=1.0)
    f_a = laws.area_crossover_force(radius=RADIUS, e_star=1.0, rms_slope=slope)
    area = np.where(FORCE < f_1, one, np.where(FORCE < f_a, linear, hertz))
    return _seeds(area, seeds)


def _cutoff_rows(letter, area):
    """Claim *letter* on the cutoff spectrum, every load resolved (1000 contact cells)."""
    return _rows(letter, H_SUMMIT, area, cells=np.full(area.shape, 1000), cutoff=CUTOFF)


def test_linear_claim_skips_the_one_asperity_regime():
    """Areas ∝ F^(2/3) below F_1 and 2F/(E* h′) above: (u)'s κ is 2 (relative 1e-12), consistent (the
    five loads below F_1, whose κ is 2.3 to 7.4, are left out)."""
    kappa = _cutoff_rows("u", _three_regimes())[0]
    assert kappa["measured"] == pytest.approx(2.0, rel=1e-12), kappa["loads"]
    assert kappa["verdict"] == "consistent", kappa["reason"]


def test_linear_claim_exponent_above_f1_is_one():
    """The same ensemble: (u)'s exponent over F_1 ≤ F ≤ 0.1 F_A is 1 (relative 1e-12)."""
    exponent = _cutoff_rows("u", _three_regimes())[1]
    assert exponent["measured"] == pytest.approx(1.0, rel=1e-12), exponent["loads"]


def test_linear_claim_with_kappa_three_differs():
    """Areas 3F/(E* h′) above F_1: κ = 3 (relative 1e-12), 50 % above 2: differs."""
    kappa = _cutoff_rows("u", _three_regimes(kappa=3.0))[0]
    assert kappa["measured"] == pytest.approx(3.0, rel=1e-12), kappa["loads"]
    assert kappa["verdict"] == "differs", kappa["reason"]


def test_the_window_states_f1():
    """The row names F_1 and its formula."""
    kappa = _cutoff_rows("u", _three_regimes())[0]
    _, f_1, _, _ = _summit()
    assert f"F_1 = {f_1:.3g} E* L^2" in kappa["loads"], kappa["loads"]


def test_single_asperity_claim_on_a_summit_s_hertz_area_has_exponent_two_thirds():
    """Areas π (3F R_s/(4E*))^(2/3) below F_1: (w)'s exponent over F ≤ 0.1 F_1 is 2/3 (relative 1e-12)."""
    exponent = _cutoff_rows("w", _three_regimes())[0]
    assert exponent["measured"] == pytest.approx(2.0 / 3.0, rel=1e-12), exponent["loads"]


def test_single_asperity_claim_with_scatter_is_consistent():
    """The same areas times 5 % scatter per seed and load (8 seeds, seeded): (w)'s interval holds 2/3."""
    scatter = 1 + 0.05 * np.random.default_rng(11).standard_normal((8, FORCE.size))
    exponent = _cutoff_rows("w", _three_regimes(seeds=8) * scatter)[0]
    assert exponent["verdict"] == "consistent", exponent["reason"]


def test_single_asperity_claim_on_a_linear_area_differs():
    """Areas 2F/(E* h′) at every load: (w)'s exponent is 1 (relative 1e-12): differs from 2/3."""
    slope = _slope(H_SUMMIT, CUTOFF)
    area = _seeds(laws.linear_area(FORCE, e_star=1.0, rms_slope=slope), 4)
    exponent = _cutoff_rows("w", area)[0]
    assert exponent["measured"] == pytest.approx(1.0, rel=1e-12), exponent["loads"]
    assert exponent["verdict"] == "differs", exponent["reason"]


def test_a_sphere_with_no_linear_regime_is_not_swept():
    """R = 0.03 on the cutoff spectrum (R_s = 0.013): R/R_s < √10, F_1 ≥ 0.1 F_A, the window of (u) is
    empty: both rows untested: not swept, naming the empty window."""
    radius = 0.03
    area = laws.hertz_area(FORCE, radius=radius, e_star=1.0)[None, :].repeat(4, 0)
    rows = _rows("u", H_SUMMIT, area, cells=np.full(area.shape, 1000), cutoff=CUTOFF, radius=radius)
    for r in rows:
        assert (r["verdict"], r["untested_because"]) == ("untested", "not swept"), r["reason"]
        assert "is empty" in r["reason"], r["reason"]
