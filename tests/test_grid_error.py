"""The grid error of an ensemble mean (roughcontact.study.analysis.grid_error) against ensembles built with a
known grid error, Richardson extrapolation against a sequence with a known limit and order, and
grid.realization_of from the configuration to the surface."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from roughcontact import errors, surfaces
from roughcontact.study.config import resolve as config
from roughcontact.study.runs import indent, naming as runs, jobs as settings
from roughcontact.study.analysis.grid_error import (GRID_ERROR_ORDER, GRID_ERROR_SAFETY, estimate, grid_error,
                                                    richardson)
from snakemake_dry import dry_run

ROOT = Path(__file__).resolve().parents[1]

FORCE = np.geomspace(1e-6, 1e-3, 6)
CELLS = np.array([5, 20, 80, 300, 1000, 3000])


def _sphere(k: np.ndarray, cells=CELLS) -> xr.Dataset:
    """A merged sphere group of one combination with stiffness k[seed, force]."""
    axes = {"hurst": [0.7], "radius": [0.5], "exponent": [2.0], "h_rms": [9e-3], "rolloff": [1.0],
            "cutoff": [0.0], "hardness": [np.inf]}
    dims = (*axes, "seed", "force")
    shape = (1,) * len(axes)
    cells = np.broadcast_to(cells, k.shape)
    return xr.Dataset({"stiffness": (dims, k.reshape(shape + k.shape)),
                       "contact_cells": (dims, cells.reshape(shape + k.shape))},
                      coords={**axes, "seed": np.arange(k.shape[0]), "force": FORCE,
                              "force_normalized": ("force", FORCE)})


def _table(coarse, fine):
    return grid_error(coarse, fine, min_cells=20, bootstrap=200, confidence=0.95, ratio=2.0)


def test_known_grid_error_is_recovered():
    """Coarse = fine x (1 + e(F)) seed by seed: the grid error is e to round-off (1e-12)."""
    rng = np.random.default_rng(0)
    fine = 1 + 0.2 * rng.random((10, FORCE.size))
    e = np.linspace(0.15, 0.01, FORCE.size)
    table = _table(_sphere(fine * (1 + e)), _sphere(fine))
    np.testing.assert_allclose(table["grid_error"], e, rtol=1e-12, err_msg="grid error")


def test_paired_interval_of_an_exact_ratio_is_a_point():
    """With the same ratio on every seed, every paired resample gives e: the interval is [e, e]."""
    rng = np.random.default_rng(1)
    fine = 1 + 0.2 * rng.random((10, FORCE.size))
    table = _table(_sphere(fine * 1.05), _sphere(fine))
    np.testing.assert_allclose(table["grid_error_ci_high"] - table["grid_error_ci_low"], 0.0, atol=1e-12,
                               err_msg="interval width")


def test_estimate_is_taken_at_the_far_end_of_the_interval():
    """Coarse = 1.05 × fine on every seed: the interval is the point 0.05, and the table's estimate is
    estimate(0.05) on its ratio (2), F_s · 0.05/(1 − 0.05) with p = 1."""
    rng = np.random.default_rng(1)
    fine = 1 + 0.2 * rng.random((10, FORCE.size))
    table = _table(_sphere(fine * 1.05), _sphere(fine))
    np.testing.assert_allclose(table["grid_error_estimate"], GRID_ERROR_SAFETY * 0.05 / 0.95, rtol=1e-10,
                               err_msg="estimate of an exact 5 % difference")


def test_grid_resolved_compares_the_error_with_the_band():
    """Seeds scattered by 20 % (band ~ +-13 % at 10 seeds) and a grid error of 30 % at the first
    load, 0.1 % elsewhere: only the first load is not resolved by the grid."""
    rng = np.random.default_rng(2)
    fine = 1 + 0.4 * rng.random((10, FORCE.size))
    e = np.array([0.3] + [0.001] * (FORCE.size - 1))
    table = _table(_sphere(fine * (1 + e)), _sphere(fine))
    assert table["grid_resolved"].tolist() == [False] + [True] * (FORCE.size - 1), table[["grid_error", "band"]]


def test_cell_rule_is_reported_beside():
    rng = np.random.default_rng(3)
    fine = 1 + 0.2 * rng.random((4, FORCE.size))
    table = _table(_sphere(fine), _sphere(fine))
    assert table["cell_resolved"].tolist() == [False, True, True, True, True, True], table["cell_resolved"]


def test_one_common_seed_is_an_error():
    fine = np.ones((3, FORCE.size))
    coarse = _sphere(fine).assign_coords(seed=[5, 6, 0])
    with pytest.raises(ValueError, match="share 1 seed"):
        _table(coarse, _sphere(fine))


def test_richardson_recovers_limit_and_order():
    """k(h) = 2 + 0.3 h^1.5 on h = 1/64, 1/128, 1/256: the limit 2 and the order 1.5 exactly."""
    h = np.array([1 / 64, 1 / 128, 1 / 256])
    k = 2 + 0.3 * h**1.5
    limit, order = richardson(k[0], k[1], k[2], 2.0)
    assert float(limit) == pytest.approx(2.0, rel=1e-12), f"limit {limit}"
    assert float(order) == pytest.approx(1.5, rel=1e-10), f"order {order}"


@pytest.mark.parametrize("n, n_coarse", [(65, 33), (64, 32), (385, 193)])
def test_estimate_of_a_power_law_sequence_is_its_exact_error(n, n_coarse):
    """k_n = k∞ + C n^(−p) (p = 1.7): with the true order and F_s = 1 the estimate from the two
    grids is the exact |k_n/k∞ − 1| = C n^(−p)/k∞, to round-off (1e-12)."""
    k_inf, c, p = 2.0, 40.0, 1.7
    k_n, k_c = k_inf + c * n ** -p, k_inf + c * n_coarse ** -p
    value = estimate(k_c / k_n - 1, n / n_coarse, order=p, safety=1.0)
    assert float(value) == pytest.approx(c * n ** -p / k_inf, rel=1e-12), f"estimate {value}"


@pytest.mark.parametrize("true_order", [GRID_ERROR_ORDER, GRID_ERROR_ORDER + 1.0, 3.0])
def test_default_estimate_bounds_the_error_against_a_twice_finer_grid(true_order):
    """A sequence k_n = k∞ + C n^(−q) converging at q ≥ the assumed order, without scatter: the
    default estimate from 385² and its 193² companion is at least |k_385/k_770 − 1| (the error the
    validation measures: for q = 1 it is half the error against k∞, and F_s = 0.75 keeps 3/2 of it)."""
    k_inf, c, n, n_coarse = 1.0, 5.0, 385, 193
    k = {m: k_inf + c * m ** -true_order for m in (n_coarse, n, 2 * n)}
    against_finer = abs(k[n] / k[2 * n] - 1)
    value = float(estimate(k[n_coarse] / k[n] - 1, n / n_coarse))
    assert value >= against_finer, f"estimate {value:.4g} below {against_finer:.4g} (F_s {GRID_ERROR_SAFETY})"


def test_estimate_is_infinite_where_the_companion_is_too_far():
    """a = g/(r^p − 1) ≥ 1 (the coarse grid twice as stiff on r = 2, p = 1): no finite estimate."""
    assert math.isinf(float(estimate(1.0, 2.0, order=1.0))), "a = 1 gives a finite estimate"


def test_estimate_needs_a_finer_grid():
    with pytest.raises(ValueError, match="ratio > 1"):
        estimate(0.1, 1.0)


def test_richardson_refuses_a_non_monotone_sequence():
    limit, order = richardson(1.0, 1.1, 1.05, 2.0)
    assert np.isnan(limit) and np.isnan(order), f"limit {limit}, order {order}"


def test_realization_of_reaches_the_surface():
    cfg = config.resolve_config({"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 1,
                                 "grid": {"n": 33, "realization_of": 65}})
    job = settings.job_settings(cfg, runs.runs(cfg)[0])
    expected = surfaces.rough_sphere(33, radius=0.5, hurst=0.7, h_rms=9e-3, seed=0, realization_of=65)
    assert np.abs(indent.make_surface(job) - expected).max() == 0.0, "the job pressed another surface"


def test_realization_of_a_coarser_grid_is_rejected():
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config({"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 1,
                               "grid": {"n": 65, "realization_of": 33}})
    assert info.value.key == "grid.realization_of", f"key {info.value.key}"


def test_command_line_says_a_missing_study_in_one_line(tmp_path, capsys):
    from roughcontact.study.analysis.grid_error import main

    code = main([str(tmp_path / "coarse"), str(tmp_path / "fine"), "-o", str(tmp_path / "out.csv")])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1, f"exit {code}: {err!r}"
    assert "no stiffness.nc" in err and not (tmp_path / "out.csv").exists(), err


def _dry_dirs(tmp_path, coarse):
    import yaml

    raw = yaml.safe_load((ROOT / "presets" / "tiny.yaml").read_text())
    if coarse is not None:
        raw["grid"]["coarse"] = coarse
    directory = tmp_path / f"coarse{coarse}"
    directory.mkdir()
    (directory / "c.yaml").write_text(yaml.safe_dump(raw))
    return directory


def test_grid_coarse_adds_a_coarse_run_per_run(tmp_path):
    """grid.coarse: snakemake -n plans one indent_coarse job per sphere run (none for the flat
    ones), their merge and the grid error table; without it, none of them."""
    with_coarse, without = _dry_dirs(tmp_path, 33), _dry_dirs(tmp_path, None)
    (rc1, out1), (rc2, out2) = dry_run(ROOT / "Snakefile", "c.yaml", [with_coarse, without])
    assert rc1 == 0 and rc2 == 0, out1[-2000:] + out2[-2000:]
    study = config.study_settings(config.load_config(with_coarse / "c.yaml"))
    blocks = runs.seed_blocks(study.seeds, study.jobs.batch)
    spheres = [combo for combo in runs.combinations(study) if combo["kind"] == "sphere"]
    planned = sum(_count(out1, f"indent_coarse_{b.name}") for b in blocks)
    assert planned == len(spheres) * len(blocks), out1[-3000:]
    assert _count(out1, "grid_error") == 1, "one grid error table"
    assert sum(_count(out2, f"indent_coarse_{b.name}") for b in blocks) == 0, "no coarse runs without grid.coarse"


def _count(out: str, rule: str) -> int:
    """The job count of *rule* in the job stats table of ``snakemake -n``."""
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[0] == rule and parts[1].isdigit():
            return int(parts[1])
    return 0


def test_default_config_measures_the_grid_error():
    """config.yaml resolves to a study with a companion on a coarser grid (the grid error by default)."""
    study = config.study_settings(config.load_config(ROOT / "config.yaml"))
    assert study.grid.coarse is not None and study.grid.coarse < study.grid.n, study.grid


def test_default_companion_presses_the_default_surfaces():
    study = config.study_settings(config.load_config(ROOT / "config.yaml"))
    assert study.coarse_study().grid.realization_of == study.grid.n, study.coarse_study().grid
