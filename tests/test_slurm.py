"""The pipeline on a real single-node SLURM (slurm-wlm + munge on localhost).

Select with ``pytest -m slurm``, leave out with ``-m "not slurm"``; runs by
default.  Skipped, with the reason, on a machine without root or apt-get
(see tests/slurm_cluster.py).
"""

from __future__ import annotations

import pytest

from slurm_cluster import slurm_cluster  # noqa: F401  (fixture)

pytestmark = pytest.mark.slurm


def test_trivial_job_runs_through_slurm(slurm_cluster, tmp_path):  # noqa: F811
    out = tmp_path / "job-%j.out"
    jid = slurm_cluster.sbatch("--wrap", "echo job=$SLURM_JOB_ID node=$SLURMD_NODENAME; srun true",
                               "-o", str(out), "--cpus-per-task=1", "--mem=100",
                               cwd=tmp_path)
    assert slurm_cluster.wait_job(jid) == "COMPLETED"
    assert (tmp_path / f"job-{jid}.out").read_text().split() == [f"job={jid}", "node=localhost"]
    assert jid in slurm_cluster.started_job_ids()


# ---------------------------------------------------------------------------
# the pipeline through SLURM vs. a local --cores 2 run of the same config
import copy  # noqa: E402
import math  # noqa: E402
import re  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

REPO = Path(__file__).resolve().parents[1]

TINY = {
    "grid": {"n": 65, "length": 1.0},
    "e_star": 1.0,
    "hurst": [0.7],
    "radius": [0.5, ".inf"],
    "h_rms": [9e-3],
    "seeds": 2,
    "forces": {"sphere": {"from": 1e-6, "to": 1e-2, "count": 6},
               "flat": {"from": 1e-5, "to": 1e-4, "count": 4}},
    "solver": {"tol": 1e-8, "stiffness": "punch"},
    "fit": {"zeta": {"min_cells": 5, "max_area_fraction": 0.1},
            "slopes": {"low_max_ratio": 0.3, "high_min_ratio": 5.0}},
}


def _write_config(d: Path) -> Path:
    import yaml

    text = yaml.safe_dump(TINY).replace("'.inf'", ".inf")
    (d / "config.yaml").write_text(text)
    return d / "config.yaml"


def _snakemake(d: Path, *extra, env=None, timeout=240):
    cmd = [sys.executable, "-m", "snakemake", "results/stiffness.nc", "-s", str(REPO / "Snakefile"),
           "-d", str(d), *extra, "--configfile", str(d / "config.yaml")]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout, cwd=d)
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-4000:]
    return r.stdout + r.stderr


def test_pipeline_through_slurm_equals_local(slurm_cluster, tmp_path):  # noqa: F811
    import xarray as xr

    local, remote = tmp_path / "local", tmp_path / "slurm"
    for d in (local, remote):
        d.mkdir()
        _write_config(d)
    _snakemake(local, "--cores", "2")
    t0 = time.monotonic()
    log = _snakemake(remote, "--profile", str(REPO / "profiles" / "slurm"),
                     "--slurm-status-command", "squeue", "--slurm-init-seconds-before-status-checks", "2",
                     "--slurm-no-account", "--default-resources", "slurm_partition=debug",
                     "--jobs", "4", env=slurm_cluster.env)
    wall = time.monotonic() - t0
    print(f"SLURM pipeline wall time: {wall:.1f} s")
    ids = {int(m) for m in re.findall(r"SLURM (?:run ID|jobid) (\d+)", log)}
    ids |= {int(m) for m in re.findall(r"external jobid '?(\d+)", log)}
    assert len(ids) >= 4, log[-4000:]  # 4 indent jobs, each a SLURM job
    states = slurm_cluster.job_states()
    assert all(states[i][1] == "COMPLETED" for i in ids), states
    assert ids <= slurm_cluster.started_job_ids()
    with xr.open_dataset(local / "results/stiffness.nc") as a, xr.open_dataset(remote / "results/stiffness.nc") as b:
        for name in a.data_vars:
            xr.testing.assert_identical(a[name].drop_attrs(), b[name].drop_attrs())
