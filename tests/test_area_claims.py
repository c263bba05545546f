"""Claims (u), (v) and the area scorecard on ensembles built from the area laws themselves (closed forms)."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.models import area as area_models
from roughcontact.models.area import laws
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


def _study(h_rms):
    """One sphere combination on 513² without a cutoff (2 cells per shortest wavelength), 4 seeds."""
    return StudySettings.of(resolve_config({
        "grid": {"n": N}, "hurst": [HURST], "radius": [RADIUS], "h_rms": [h_rms], "seeds": 4,
        "forces": {"sphere": {"from": 1e-6, "to": 4e-2, "count": 13}}, "fit": {"bootstrap": 200}}))


def _slope(h_rms):
    return area_models.rms_slope(Surface(hurst=HURST, h_rms=h_rms, radius=RADIUS, length=1.0, n=N, e_star=1.0))


def _groups(area_per_seed: np.ndarray, h_rms, cells=None) -> dict:
    """A merged sphere group of one combination with the areas *area_per_seed* (seed, force) and
    the contact cells A n²/L² (or *cells*)."""
    seeds = area_per_seed.shape[0]
    cells = np.rint(area_per_seed * N**2).astype(int) if cells is None else cells
    axes = {"hurst": [HURST], "radius": [RADIUS], "exponent": [2.0], "h_rms": [h_rms], "rolloff": [1.0],
            "cutoff": [0.0], "hardness": [math.inf]}
    dims = (*axes, "seed", "force")
    shape = (1,) * len(axes)
    ds = xr.Dataset({"stiffness": (dims, np.ones(shape + area_per_seed.shape)),
                     "contact_area": (dims, area_per_seed.reshape(shape + area_per_seed.shape)),
                     "contact_cells": (dims, cells.reshape(shape + cells.shape))},
                    coords={**axes, "seed": np.arange(seeds), "force": FORCE})
    return {"sphere": ds}


def _rows(letter, h_rms, area=None, cells=None):
    area = _joined(h_rms) if area is None else area
    inputs = ClaimInputs(cross=pd.DataFrame(), replicates=None, zeta=pd.DataFrame(), study=_study(h_rms),
                         groups=_groups(area, h_rms, cells))
    return table_rows(claims()[letter], inputs)


def _joined(h_rms, kappa=2.0, seeds=4):
    """Every seed's area the linear law with *kappa* below F_A (κ = 2) and Hertz above."""
    slope = _slope(h_rms)
    linear = laws.linear_area(FORCE, e_star=1.0, rms_slope=slope, kappa=kappa)
    hertz = laws.hertz_area(FORCE, radius=RADIUS, e_star=1.0)
    f_a = laws.area_crossover_force(radius=RADIUS, e_star=1.0, rms_slope=slope)
    return np.where(FORCE < f_a, linear, hertz)[None, :].repeat(seeds, 0)


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
