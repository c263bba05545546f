"""Quantities and histograms added to a finished study, through the real ``snakemake``: the study's
own runs (and only they: not the grid error's coarse companions) are planned again, because their
settings changed (Snakemake's params trigger); once rerun, the merged file keeps the quantities and
the histograms, and the report's figure of one load's histograms is drawn. (Where Snakemake does
not rerun them, the merge names the stale runs: tests/test_histograms.py.)"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
#: two seeds of one sphere on 65², the grid error's companions on 33² (grid.coarse's default)
BASE = {"grid": {"n": 65, "length": 1.0}, "hurst": [0.7], "radius": [0.5], "h_rms": [2.0e-2], "seeds": 2,
        "forces": {"sphere": {"from": 1.0e-4, "to": 1.0e-2, "count": 5}}}
MORE = {**BASE, "fields": {"quantities": ["mean_gap", "largest_patch_area"],
                           "histograms": {"at": [1.0e-3, 1.0e-2], "bins": 16}}}


def _snakemake(where: Path, config: dict, *args: str) -> str:
    path = where / "config.yaml"
    path.write_text(yaml.safe_dump(config))
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    done = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "--cores", "2",
                           "--configfile", str(path), *args], cwd=where, env=env, capture_output=True, text=True,
                          timeout=900)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return done.stdout + done.stderr


def _planned(text: str) -> dict:
    """``{rule: jobs}`` of the job stats table of a dry run."""
    rows = {}
    for line in text.split("Job stats:", 1)[-1].splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit() and parts[0] != "total":
            rows[parts[0]] = int(parts[1])
    return rows


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    """BASE run to the end, the dry run of MORE in the same directory, then MORE run."""
    where = tmp_path_factory.mktemp("added")
    _snakemake(where, BASE, "-q")
    coarse = {p: p.stat().st_mtime_ns for p in (where / "results" / "indent_coarse").rglob("*.nc")}
    own = {p: p.stat().st_mtime_ns for p in (where / "results" / "runs").rglob("*.nc")}
    planned = _planned(_snakemake(where, MORE, "-n"))
    _snakemake(where, MORE, "-q")
    return where, coarse, own, planned


def test_adding_them_plans_the_study_s_runs(study):
    *_, planned = study
    assert [r for r in planned if r.startswith("indent") and "coarse" not in r], planned


def test_adding_them_recomputes_each_of_the_study_s_runs(study):
    _, _, own, _ = study
    assert (len(own), [p.name for p, t in own.items() if p.stat().st_mtime_ns == t]) == (2, [])


def test_adding_them_reruns_no_coarse_companion(study):
    where, coarse, _, planned = study
    assert (len(coarse), [r for r in planned if "coarse" in r and r.startswith("indent")],
            {p: p.stat().st_mtime_ns for p in coarse} == coarse) == (2, [], True), planned


def test_the_merged_file_keeps_the_histograms_of_both_loads(study):
    import xarray as xr

    where, *_ = study
    with xr.open_dataset(where / "results" / "stiffness.nc", group="sphere") as ds:
        assert ds["pressure_histogram"].sizes["histogram_load"] == 2
        assert np.allclose(ds["histogram_force_normalized"].values, [1e-3, 1e-2], rtol=1e-9)
        counted = ds["pressure_histogram"].sum("pressure_bin").values
        cells = ds["contact_cells"].isel(force=ds["histogram_load"].values).values
        assert np.array_equal(counted, cells)
        assert np.isfinite(ds["mean_gap"].values).all()


def test_the_report_draws_one_load_s_histograms(study):
    where, *_ = study
    png = where / "results" / "figures" / "histograms.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
