"""The fine reference of the small loads (grid.fine; roughcontact.study.analysis.fine_reference).

Closed forms: a sequence k_n = k_inf (1 + C h) with h = L/n (first order) on three grids of ratio
2 is extrapolated by Richardson to k_inf exactly, with order 1 (to rounding, 1e-12); a load whose
largest patch holds at least SINGLE_ASPERITY_SHARE of the contact is single-asperity."""
from __future__ import annotations

import copy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml

from roughcontact import errors
from roughcontact.study.analysis.fine_reference import SINGLE_ASPERITY_SHARE, combined_grid_error, fine_reference
from roughcontact.study.config import resolve as config
from roughcontact.study.config.companions import fine_config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.runs import jobs, naming

REPO = Path(__file__).resolve().parents[1]

GOOD = {"grid": {"n": 97, "length": 1.0, "coarse": 49, "fine": 193}, "hurst": [0.7], "radius": [0.5],
        "h_rms": [9e-3], "seeds": 4, "forces": {"sphere": {"from": 1e-5, "to": 1e-2, "count": 10}},
        "fit": {"resolved_cells": 10, "bootstrap": 200}}


def _with(grid=None, **changes):
    cfg = copy.deepcopy(GOOD)
    cfg["grid"].update(grid or {})
    cfg.update(changes)
    return cfg


@pytest.mark.parametrize("cfg,named", [
    (_with(grid={"fine": 97}), "grid.fine"),
    (_with(grid={"fine": 65}), "grid.fine"),
    (_with(grid={"fine": 193, "realization_of": 129}), "grid.realization_of"),
    (_with(grid={"fine": None, "fine_to": 1e-4}), "grid.fine_to"),
    (_with(grid={"fine_to": 1e-5}), "grid.fine_to"),     # below the path's second load
    (_with(grid={"fine_to": 1.0}), "grid.fine_to"),
    (_with(radius=[float("inf")], forces={"flat": {"from": 1e-5, "to": 1e-4, "count": 4}}), "grid.fine"),
], ids=["equal", "coarser", "realization-coarser", "to-without-fine", "to-too-small", "to-too-large", "no-sphere"])
def test_bad_fine_grid_rejected_with_one_line(cfg, named):
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(cfg)
    assert "\n" not in str(err.value) and named in str(err.value) and "allowed" in str(err.value), str(err.value)


def test_without_fine_grid_the_resolved_grid_is_unchanged():
    grid = config.resolve_config(yaml.safe_load((REPO / "config.yaml").read_text()))["grid"]
    assert set(grid) == {"n", "length", "coarse"}


def test_the_study_presses_the_surfaces_of_the_fine_grid():
    study = StudySettings.of(config.resolve_config(_with()))
    assert jobs.job_settings(study, naming.runs(study)[0]).realization_of == 193


def test_fine_loads_are_the_first_loads_of_the_study_path():
    resolved = config.resolve_config(_with(grid={"fine_to": 2e-4}))
    study, fine = StudySettings.of(resolved), StudySettings.of(fine_config(resolved))
    path, short = study.forces["sphere"].normalized(), fine.forces["sphere"].normalized()
    assert short[-1] <= 2e-4 < path[len(short)]
    np.testing.assert_allclose(short, path[:len(short)], rtol=1e-12)


def test_fine_runs_count_their_patches_on_their_own_surfaces():
    fine = StudySettings.of(fine_config(config.resolve_config(_with())))
    record = jobs.job_settings(fine, naming.runs(fine)[0]).record()
    assert (record["n"], record.get("realization_of"), record["patches"]) == (193, None, True)


def _ds(n: int, k_inf, cells, largest, seeds=4, loads=3):
    """A merged sphere Dataset whose k is k_inf (1 + 2 L/n) exactly for every seed."""
    dims = ("hurst", "radius", "h_rms", "seed", "force")
    force = np.geomspace(1e-5, 1e-4, loads)
    k = np.broadcast_to(np.asarray(k_inf) * (1 + 2.0 / n), (1, 1, 1, seeds, loads)).copy()
    k *= 1 + 1e-3 * np.arange(seeds)[None, None, None, :, None]   # seeds differ, the error does not
    return xr.Dataset({"stiffness": (dims, k), "contact_cells": (dims, np.full(k.shape, cells)),
                       "largest_patch_cells": (dims, np.full(k.shape, largest))},
                      coords={"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seed": np.arange(seeds),
                              "force": force, "force_normalized": ("force", force)})


def _table():
    k_inf = np.array([1.0, 2.0, 3.0])
    return fine_reference(_ds(100, k_inf, 40, 36), _ds(200, k_inf, 160, 100), _ds(50, k_inf, 10, 10), n=100,
                          n_fine=200, n_coarse=50, min_cells=5, bootstrap=100, confidence=0.95)


def test_richardson_recovers_the_continuum_stiffness():
    """The ensemble mean's continuum value: k_inf times the mean seed factor, 1 + 1.5e-3."""
    np.testing.assert_allclose(_table()["richardson_stiffness"], np.array([1.0, 2.0, 3.0]) * 1.0015, rtol=1e-12)


def test_richardson_order_is_one():
    np.testing.assert_allclose(_table()["richardson_order"], 1.0, rtol=1e-12)


def test_single_asperity_share_is_measured():
    table = _table()
    assert table["largest_patch_share"].iloc[0] == pytest.approx(100 / 160, rel=1e-12)
    assert not table["single_asperity"].any() and 100 / 160 < SINGLE_ASPERITY_SHARE


def test_single_asperity_is_the_leading_run_of_loads_only():
    """Shares 0.9, 0.85, 0.5, 0.95: the first two loads; the last (a merged contact) is not."""
    k_inf = np.array([1.0, 2.0, 3.0, 4.0])
    fine = _ds(200, k_inf, 100, 0, loads=4)
    fine["largest_patch_cells"][...] = np.array([90, 85, 50, 95])
    table = fine_reference(_ds(100, k_inf, 40, 36, loads=4), fine, None, n=100, n_fine=200, min_cells=5,
                           bootstrap=100, confidence=0.95)
    assert table["single_asperity"].tolist() == [True, True, False, False]


def _companion_tables():
    """A coarse companion's and a fine reference's rows at one shared load, with the columns both
    tables have whose values differ between them (contact cells on the finer grid, the grid ratio)."""
    coarse = pd.DataFrame({"hurst": [0.7, 0.7], "force_normalized": [1e-5, 1e-3], "grid_error_estimate": [0.5, 0.02],
                           "grid_error": [0.4, 0.01], "contact_cells_fine": [12.0, 900.0], "grid_ratio": [2.0, 2.0]})
    fine = pd.DataFrame({"hurst": [0.7], "force_normalized": [1e-5], "grid_error_estimate": [0.03],
                         "study_grid_error": [0.02], "band": [0.1], "contact_cells_fine": [48.0], "grid_ratio": [2.0]})
    return coarse, fine


def test_the_fine_reference_replaces_the_coarse_grid_error_at_its_loads():
    combined = combined_grid_error(*_companion_tables()).sort_values("force_normalized")
    assert combined["grid_error_estimate"].tolist() == [0.03, 0.02]


def test_the_combined_grid_error_has_one_row_per_load():
    assert len(combined_grid_error(*_companion_tables())) == 2


@pytest.mark.workflow
def test_pipeline_writes_the_fine_reference(tmp_path):
    (tmp_path / "fine.yaml").write_text(yaml.safe_dump(_with(grid={"fine_to": 5e-5})))
    r = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(tmp_path),
                        "--configfile", str(tmp_path / "fine.yaml"), "--cores", "2", "-q"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    table = pd.read_csv(tmp_path / "results" / "fine_reference.csv")
    assert len(table) == 3 and (table["fine_grid_n"] == 193).all()
    assert (pd.read_csv(tmp_path / "results" / "models.csv")["grid_error_measured"]).all()
