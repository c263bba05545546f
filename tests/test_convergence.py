"""Grid convergence tables (study.analysis.convergence) on synthetic studies with a known stiffness ratio."""
import numpy as np
import pytest
import xarray as xr

from roughcontact.study.analysis import convergence
from roughcontact.study.files.io import write_groups

FORCES = np.array([1e-6, 1e-5, 1e-4])


def _study(root, n, scale, seeds):
    """A study directory whose sphere stiffness is scale · F^(1/3) times a per-seed factor
    that averages to exactly 1 (so the ensemble-mean ratio of two studies is the ratio of scales)."""
    factor = 1 + 0.2 * np.linspace(-1, 1, seeds)
    k = scale * factor[:, None] * FORCES[None, :] ** (1 / 3)
    shape = ("hurst", "radius", "seed", "force")
    ds = xr.Dataset({"stiffness": (shape, k[None, None]),
                     "contact_cells": (shape, np.full((1, 1, seeds, FORCES.size), 50))},
                    coords={"hurst": [0.7], "radius": [0.5], "seed": np.arange(seeds), "force": FORCES})
    (root / f"n{n}" / "results").mkdir(parents=True)  # parents: the "a"/"b" roots of one test
    write_groups(root / f"n{n}" / "results" / "stiffness.nc", {"sphere": ds}, {"grid_n": n})
    return root / f"n{n}"


def test_ratio_to_finest_is_the_ratio_of_scales(tmp_path):
    studies = [_study(tmp_path, 257, 1.1, 5), _study(tmp_path, 1025, 1.0, 8)]
    table = convergence.stiffness_ratios(studies, resamples=200)
    coarse = table[table["n"] == 257]["ratio_to_finest_minus_1"].to_numpy()
    assert coarse == pytest.approx(0.1, abs=1e-12), "ensemble means 1.1 and 1.0 at every load"


def test_finest_grid_has_no_rows(tmp_path):
    studies = [_study(tmp_path, 257, 1.1, 5), _study(tmp_path, 1025, 1.0, 8)]
    table = convergence.stiffness_ratios(studies, resamples=200)
    assert set(table["n"]) == {257}, "the finest grid is the reference, not compared with itself"


def test_two_studies_on_one_grid_rejected(tmp_path):
    studies = [_study(tmp_path / "a", 257, 1.1, 5), _study(tmp_path / "b", 257, 1.0, 8)]
    with pytest.raises(ValueError, match="two studies on 257"):
        convergence.stiffness_ratios(studies)


def test_interval_holds_the_ratio(tmp_path):
    studies = [_study(tmp_path, 257, 1.1, 5), _study(tmp_path, 1025, 1.0, 8)]
    row = convergence.stiffness_ratios(studies, resamples=400).iloc[0]
    assert row["ci_low"] <= 0.1 <= row["ci_high"], f"interval {row['ci_low']}..{row['ci_high']}"


def test_two_combinations_rejected(tmp_path):
    study = _study(tmp_path, 257, 1.0, 3)
    path = study / "results" / "stiffness.nc"
    ds = xr.open_datatree(path)["sphere"].to_dataset().load()
    two = xr.concat([ds, ds.assign_coords(hurst=[0.3])], dim="hurst")
    write_groups(path, {"sphere": two}, {"grid_n": 257})
    with pytest.raises(ValueError, match="one sphere combination"):
        convergence.stiffness_ratios([study, _study(tmp_path, 513, 1.0, 3)])


def test_against_eq16_of_eq16_itself_is_zero(tmp_path):
    # a study whose every seed is eq. 16 (zeta = 1.7/(H+1)) at its loads: deviation 0 at every load
    from roughcontact.models import paper

    k16 = paper.stiffness_from_force(FORCES, radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    shape = ("hurst", "radius", "h_rms", "seed", "force")
    ds = xr.Dataset({"stiffness": (shape, np.broadcast_to(k16, (1, 1, 1, 4, FORCES.size)).copy()),
                     "contact_cells": (shape, np.full((1, 1, 1, 4, FORCES.size), 50))},
                    coords={"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seed": np.arange(4), "force": FORCES})
    (tmp_path / "results").mkdir()
    write_groups(tmp_path / "results" / "stiffness.nc", {"sphere": ds}, {"grid_n": 257})
    table = convergence.against_eq16([tmp_path], resamples=50)
    assert table["k_over_eq16_minus_1"].abs().max() == pytest.approx(0.0, abs=1e-12), "eq. 16 against itself"


@pytest.mark.parametrize("target, first", [(300.0, False), (2.0, True)])
def test_force_at_cells_of_a_power_law(target, first):
    """Mean contact cells c = 1000 (F/1e-4)^0.8 at F = 1e-6, 1e-5, 1e-4: the force at which c reaches the
    target is 1e-4 (target/1000)^(1/0.8) exactly, whether it lies between the loads (log-log interpolation
    of a power law is exact) or below the first one (extrapolated with the first two loads' slope)."""
    cells = 1000 * (FORCES / 1e-4) ** 0.8
    force, extrapolated = convergence._force_at_cells(FORCES, cells, target)
    assert force == pytest.approx(1e-4 * (target / 1000) ** 1.25, rel=1e-12), "force at the target cells"
    assert extrapolated is first, "extrapolated only below the first load"


def test_force_at_cells_never_reached_is_nan():
    force, _ = convergence._force_at_cells(FORCES, np.array([1.0, 2.0, 3.0]), 20.0)
    assert np.isnan(force), "no load has 20 cells"
