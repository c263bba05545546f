"""A truncated or foreign .nc among the run files: merge stops naming the file and the cause."""
from __future__ import annotations

import subprocess
import sys

import pytest

from test_slurm import REPO, _snakemake, _write_config  # noqa: F401

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow


def _rerun_merge(d):
    cmd = [sys.executable, "-m", "snakemake", "results/stiffness.nc", "-s", str(REPO / "Snakefile"),
           "-d", str(d), "--cores", "1", "--configfile", str(d / "config.yaml")]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=d)


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    d = tmp_path_factory.mktemp("merge")
    _write_config(d)
    _snakemake(d, "--cores", "2")
    return d


def _corrupt(d, how):
    run = sorted((d / "results/runs").rglob("seed1.nc"))[0]
    backup = run.read_bytes()
    if how == "truncated":
        run.write_bytes(backup[: len(backup) // 2])
    else:  # foreign: a valid NetCDF file that is not a run
        import xarray as xr
        xr.Dataset({"temperature": ("time", [1.0, 2.0])}).to_netcdf(run)
    return run, backup


@pytest.mark.parametrize("how", ["truncated", "foreign"])
def test_merge_names_bad_file(finished, how):
    run, backup = _corrupt(finished, how)
    try:
        r = _rerun_merge(finished)
        out = r.stdout + r.stderr
        assert r.returncode != 0, out[-3000:]
        log = (finished / "logs/merge.log").read_text() if (finished / "logs/merge.log").exists() else ""
        text = out + log
        assert run.name in text and run.parent.name in text, text[-3000:]
        assert not (finished / "results/stiffness.nc").exists()
    finally:
        run.write_bytes(backup)
