"""Studies kept apart: a second study never replaces the first's run files or tables.

In a scratch checkout (Snakefile, workflow, package, profiles) the default study of its
``config.yaml`` runs (``snakemake --cores 2``: ``results/``); then the README's "Other sweeps"
command, ``snakemake --cores 2 --configfile presets/NAME.yaml``, with a preset whose run files
have the very names of the default's (the same sphere on another grid) runs in
``studies/NAME/`` and its report (``--report results/report.html``) goes there too, the first
study's files byte for byte and mtime for mtime as they were. Forced into the first study's
directory (``--directory .``) the preset is refused before any job, in one line naming both
config files and the ``--directory`` to use. (The record and the check themselves:
``tests/test_study_directory.py``.)
"""
from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr
import yaml

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]

#: the default study: one sphere, two seeds, on 33²
DEFAULT = {"grid": {"n": 33, "length": 1.0, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [9.0e-3],
           "seeds": 2, "forces": {"sphere": {"from": 1.0e-4, "to": 1.0e-2, "count": 6}},
           "fit": {"resolved_cells": 5, "bootstrap": 50}}
#: the preset: the same runs, by name, on 65²
PRESET = {**DEFAULT, "grid": {"n": 65, "length": 1.0, "coarse": None}}
RUN = "results/runs/H0.7_R0.5_h0.009/seed0.nc"


def _snakemake(where: Path, *args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(where / "src")}
    return subprocess.run([sys.executable, "-m", "snakemake", *args], cwd=where, env=env, capture_output=True,
                          text=True, timeout=900)


def _ok(done: subprocess.CompletedProcess) -> subprocess.CompletedProcess:
    assert done.returncode == 0, f"snakemake failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


def _files(where: Path) -> dict:
    """``{path: (sha256, mtime_ns)}`` of every file of the study in *where* (results/, logs/)."""
    return {str(p.relative_to(where)): (hashlib.sha256(p.read_bytes()).hexdigest(), p.stat().st_mtime_ns)
            for folder in ("results", "logs") for p in sorted((where / folder).rglob("*")) if p.is_file()}


def _grid(path: Path) -> int:
    with xr.open_dataset(path, engine="netcdf4") as ds:
        return int(ds.attrs["grid_n"])


@pytest.fixture(scope="module")
def checkout(tmp_path_factory):
    """A scratch checkout whose default study ran; its files before the preset; the preset run and
    its report (the README's commands); the preset forced beside the default study."""
    where = tmp_path_factory.mktemp("apart")
    ignore = shutil.ignore_patterns("__pycache__", "*.egg-info")
    for folder in ("src", "workflow", "envs", "profiles"):
        shutil.copytree(ROOT / folder, where / folder, ignore=ignore)
    shutil.copy(ROOT / "Snakefile", where / "Snakefile")
    (where / "config.yaml").write_text(yaml.safe_dump(DEFAULT))
    (where / "presets").mkdir()
    (where / "presets" / "other.yaml").write_text(yaml.safe_dump(PRESET))
    _ok(_snakemake(where, "--cores", "2"))
    first = _files(where)
    preset = _ok(_snakemake(where, "--cores", "2", "--configfile", "presets/other.yaml"))
    _ok(_snakemake(where, "--configfile", "presets/other.yaml", "--report", "results/report.html"))
    after_preset = _files(where)
    forced = _snakemake(where, "--cores", "2", "--configfile", "presets/other.yaml", "--directory", ".")
    return where, first, preset, after_preset, forced


def test_the_preset_runs_in_a_directory_named_for_it(checkout):
    where, _, preset, _, _ = checkout
    study = where / "studies" / "other"
    assert _grid(study / RUN) == 65 and _grid(where / RUN) == 33
    assert (study / "results" / "claims.csv").is_file() and (study / "results" / "models.csv").is_file()
    assert (study / "results" / "report.html").is_file() and not (where / "results" / "report.html").exists()
    assert (study / "results" / "configfile.txt").read_text() == "presets/other.yaml\n"
    assert (where / "results" / "configfile.txt").read_text() == "config.yaml\n"
    assert "This study runs in studies/other/" in preset.stderr


def test_the_first_study_is_left_byte_for_byte(checkout):
    _, first, _, after_preset, _ = checkout
    assert RUN in first and "results/claims.csv" in first and "results/models.csv" in first
    assert after_preset == first


def test_the_preset_beside_the_first_study_is_refused_in_one_line(checkout):
    where, first, _, _, forced = checkout
    assert forced.returncode != 0
    lines = [line for line in (forced.stdout + forced.stderr).splitlines() if "Not overwriting" in line]
    assert len(lines) == 1, forced.stderr[-3000:]
    assert (f"{where}/results/ holds the study of config.yaml, this run's config is presets/other.yaml; "
            f"run it in a directory of its own (--directory {where}/studies/other)") in lines[0]
    assert _files(where) == first


def test_the_default_study_is_still_done(checkout):
    where, *_ = checkout
    dry = _ok(_snakemake(where, "-n"))
    assert "Nothing to be done" in dry.stdout + dry.stderr
