"""The pipeline on a real single-node SLURM (slurm-wlm + munge on localhost),
also when the scheduler kills a job: ``scancel`` of a running ``indent`` job,
and a job above its memory limit.  The profile's ``retries: 1`` resubmits it,
the workflow finishes with the results of a local ``--cores 2`` run and leaves
no partial file.

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
    "fit": {"resolved_cells": 5, "zeta": {"max_area_fraction": 0.1},
            "slopes": {"low_max_ratio": 0.3, "high_min_ratio": 5.0}},
    "jobs": {"batch": 1},   # one SLURM job per run (the setting for clusters), run by its seed wildcard
}


def _write_config(d: Path) -> Path:
    import yaml

    text = yaml.safe_dump(TINY).replace("'.inf'", ".inf")
    (d / "config.yaml").write_text(text)
    return d / "config.yaml"


def _snakemake(d: Path, *extra, env=None, timeout=240):
    r = subprocess.run(_command(d, *extra), capture_output=True, text=True, env=env, timeout=timeout, cwd=d)
    assert r.returncode == 0, r.stdout[-4000:] + r.stderr[-4000:]
    return r.stdout + r.stderr


def _command(d: Path, *extra) -> list[str]:
    return [sys.executable, "-m", "snakemake", "results/stiffness.nc", "-s", str(REPO / "Snakefile"),
            "-d", str(d), *extra, "--configfile", str(d / "config.yaml")]


# the profile, on the test cluster: no accounting (squeue), quick first status check, its partition
SLURM_ARGS = ("--profile", str(REPO / "profiles" / "slurm"), "--slurm-status-command", "squeue",
              "--slurm-init-seconds-before-status-checks", "2", "--slurm-no-account",
              "--default-resources", "slurm_partition=debug", "--jobs", "4")
INDENT_JOBS = 4  # (R = 0.5, inf) x 2 seeds


@pytest.fixture(scope="module")
def local(tmp_path_factory) -> Path:
    """The same config through a local ``--cores 2`` run, once per module."""
    d = tmp_path_factory.mktemp("local")
    _write_config(d)
    _snakemake(d, "--cores", "2")
    return d


def _slurm_ids(log: str) -> set[int]:
    ids = {int(m) for m in re.findall(r"SLURM (?:run ID|jobid) (\d+)", log)}
    return ids | {int(m) for m in re.findall(r"external jobid '?(\d+)", log)}


def _assert_same_results(local: Path, remote: Path) -> None:
    from merged import assert_same_numbers

    assert_same_numbers(local / "results/stiffness.nc", remote / "results/stiffness.nc")


def _assert_nothing_partial(local: Path, remote: Path) -> None:
    """No temporary or incomplete file, every run file equal to the local one, nothing left to do."""
    import xarray as xr

    leftovers = sorted(str(p.relative_to(remote)) for p in (remote / "results").rglob(".*.tmp-*"))
    assert leftovers == [], f"partial files left behind: {leftovers}"
    incomplete = remote / ".snakemake" / "incomplete"
    marked = sorted(p.name for p in incomplete.iterdir()) if incomplete.exists() else []
    assert marked == [], f"outputs still marked incomplete: {marked}"
    runs = sorted(p.relative_to(local) for p in (local / "results/runs").rglob("*.nc"))
    assert sorted(p.relative_to(remote) for p in (remote / "results/runs").rglob("*.nc")) == runs, "run files differ"
    for rel in runs:
        with xr.open_dataset(local / rel) as a, xr.open_dataset(remote / rel) as b:
            for name in a.data_vars:
                xr.testing.assert_identical(a[name].drop_attrs(), b[name].drop_attrs())
    dry = subprocess.run(_command(remote, "-n"), capture_output=True, text=True, timeout=120, cwd=remote)
    assert "Nothing to be done" in dry.stdout + dry.stderr, dry.stdout[-2000:] + dry.stderr[-2000:]


def test_pipeline_through_slurm_equals_local(slurm_cluster, local, tmp_path):  # noqa: F811
    remote = tmp_path / "slurm"
    remote.mkdir()
    _write_config(remote)
    t0 = time.monotonic()
    log = _snakemake(remote, *SLURM_ARGS, env=slurm_cluster.env)
    print(f"SLURM pipeline wall time: {time.monotonic() - t0:.1f} s")
    ids = _slurm_ids(log)
    assert len(ids) >= INDENT_JOBS, log[-4000:]  # each indent job is a SLURM job
    states = slurm_cluster.job_states()
    assert all(states[i][1] == "COMPLETED" for i in ids), states
    assert ids <= slurm_cluster.started_job_ids(), slurm_cluster.diagnostics()
    _assert_same_results(local, remote)


# ---------------------------------------------------------------------------
# faults: the scheduler kills a job, the workflow retries it (profile: retries: 1)
def test_cancelled_indent_job_is_retried(slurm_cluster, local, tmp_path):  # noqa: F811
    """scancel one running indent job: SLURM reports CANCELLED, Snakemake resubmits
    it, the workflow finishes with the local results and leaves nothing partial."""
    remote = tmp_path / "slurm"
    remote.mkdir()
    _write_config(remote)
    known = set(slurm_cluster.job_table())
    t0 = time.monotonic()
    proc = subprocess.Popen(_command(remote, *SLURM_ARGS), cwd=remote, env=slurm_cluster.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        victim = None
        while victim is None and proc.poll() is None and time.monotonic() - t0 < 120:
            running = [(jid, job) for jid, job in slurm_cluster.job_table().items()
                       if jid not in known and job["state"] == "RUNNING" and job["comment"].startswith("rule_indent")]
            if running:
                victim, job = running[0]
                comment = job["comment"]
                slurm_cluster.scancel(victim)
            time.sleep(0.2)
        log, _ = proc.communicate(timeout=240)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    print(f"SLURM pipeline with a cancelled job, wall time: {time.monotonic() - t0:.1f} s")
    assert victim is not None, "no running indent job seen to cancel:\n" + log[-4000:]
    assert f"SLURM-job '{victim}' failed" in log, f"Snakemake does not report the cancelled job {victim}:\n{log[-4000:]}"
    assert proc.returncode == 0, f"the workflow did not recover from scancel {victim}:\n" + log[-4000:]
    table = slurm_cluster.job_table()
    assert table[victim]["state"] == "CANCELLED", f"job {victim} ended {table[victim]['state']}, not CANCELLED"
    again = [jid for jid, job in table.items() if jid > victim and job["comment"] == comment]
    assert len(again) == 1, f"{comment} was resubmitted {len(again)} times: {table}"
    assert table[again[0]]["state"] == "COMPLETED", f"the retry of {comment} ended {table[again[0]]['state']}"
    indent = [jid for jid, job in table.items() if jid not in known and job["comment"].startswith("rule_indent")]
    assert len(indent) == INDENT_JOBS + 1, f"{len(indent)} indent submissions, expected {INDENT_JOBS} + 1 retry"
    _assert_same_results(local, remote)
    _assert_nothing_partial(local, remote)


# The first attempt of one indent job gets 60 MB: its Python (Snakemake, numpy) needs more, so
# SLURM kills it (slurmstepd: "exceeded memory limit"); the retry (attempt 2) gets 400 MB.
# The job is a flat run (its run name, the `combo` wildcard, holds the tag R{OOM_RADIUS}).
OOM_SEED, OOM_RADIUS = "1", "inf"
OOM_LIMIT = (f"indent:mem_mb=60 if attempt == 1 and wildcards.seed == '{OOM_SEED}' "
             f"and '_R{OOM_RADIUS}_' in wildcards.combo else 400")


def test_job_over_its_memory_limit_is_retried(slurm_cluster, local, tmp_path):  # noqa: F811
    """One indent job exceeds its memory limit on the first attempt: SLURM kills it,
    Snakemake resubmits it with more memory, the results equal the local run."""
    remote = tmp_path / "slurm"
    remote.mkdir()
    _write_config(remote)
    known = set(slurm_cluster.job_table())
    t0 = time.monotonic()
    log = _snakemake(remote, *SLURM_ARGS, "--set-resources", OOM_LIMIT, env=slurm_cluster.env)
    print(f"SLURM pipeline with a job over its memory limit, wall time: {time.monotonic() - t0:.1f} s")
    table = {jid: job for jid, job in slurm_cluster.job_table().items()
             if jid not in known and job["comment"].startswith("rule_indent")}
    failed = [jid for jid, job in table.items() if job["state"] != "COMPLETED"]
    assert len(failed) == 1, f"expected one failed indent job, got {len(failed)}: {table}"
    first = failed[0]
    values = table[first]["comment"].split("_wildcards_")[1].split("_")
    assert f"R{OOM_RADIUS}" in values and values[-1] == OOM_SEED, f"the wrong job failed: {table[first]}"
    assert table[first]["state"] in ("FAILED", "OUT_OF_MEMORY"), f"first attempt ended {table[first]['state']}"
    again = [jid for jid, job in table.items() if jid > first and job["comment"] == table[first]["comment"]]
    assert len(again) == 1, f"{table[first]['comment']} was resubmitted {len(again)} times: {table}"
    assert table[again[0]]["state"] == "COMPLETED", f"the retry ended {table[again[0]]['state']}"
    assert len(table) == INDENT_JOBS + 1, f"{len(table)} indent submissions, expected {INDENT_JOBS} + 1 retry"
    assert f"SLURM-job '{first}' failed" in log, f"Snakemake does not report the failure of job {first}:\n{log[-4000:]}"
    logs = list((remote / ".snakemake").rglob(f"{first}.log"))
    assert len(logs) == 1, f"no SLURM log of job {first} under .snakemake: {logs}"
    assert "exceeded memory limit" in logs[0].read_text(errors="replace"), \
        f"SLURM's log of the first attempt does not say it exceeded its memory limit:\n{logs[0].read_text()}"
    _assert_same_results(local, remote)
    _assert_nothing_partial(local, remote)
