"""Interrupt a running `snakemake` (SIGTERM, then SIGKILL) part way, rerun: it completes,
finished runs are not recomputed, and the merged dataset equals an uninterrupted run."""
from __future__ import annotations

import copy
import os
import re
import signal
import subprocess
import sys
import time
from base64 import urlsafe_b64decode
from pathlib import Path

import pytest
import yaml

from merged import assert_same_numbers
from test_slurm import REPO, TINY, _snakemake

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

CFG = copy.deepcopy(TINY)
CFG["seeds"] = 5  # 10 runs
CFG["jobs"] = {"batch": 2}  # in 6 jobs: seeds 0-1, 2-3 and 4 of each radius


def _write(d):
    d.mkdir()
    (d / "config.yaml").write_text(yaml.safe_dump(CFG).replace("'.inf'", ".inf"))


def _recorded(run: Path) -> set[str]:
    """Run files Snakemake has recorded as finished: a metadata record and no
    incomplete marker (both keyed by the base64 of the output path)."""
    def decoded(name):
        try:
            return urlsafe_b64decode(name).decode()
        except ValueError:  # not a record (binascii.Error and UnicodeDecodeError are ValueErrors)
            return None

    def keys(sub):
        d = run / ".snakemake" / sub
        return {decoded(f.name) for f in d.glob("*") if f.is_file()} - {None} if d.is_dir() else set()
    return {k for k in keys("metadata") - keys("incomplete") if k.startswith("results/runs/")}


def test_interrupt_and_resume(tmp_path):
    ref, run = tmp_path / "ref", tmp_path / "run"
    _write(ref)
    _write(run)
    _snakemake(ref, "--cores", "2")

    cmd = [sys.executable, "-m", "snakemake", "results/stiffness.nc", "-s", str(REPO / "Snakefile"),
           "-d", str(run), "--cores", "2", "--configfile", str(run / "config.yaml")]
    p = subprocess.Popen(cmd, cwd=run, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         start_new_session=True)
    try:
        end = time.monotonic() + 60
        # kill once two runs (a job of two) are recorded finished: a file renamed into place a
        # moment before Snakemake records its job is (rightly) recomputed on resume, and so are
        # the finished runs of an unfinished job
        while time.monotonic() < end and len(_recorded(run)) < 2:
            time.sleep(0.1)
        recorded = _recorded(run)
        p.send_signal(signal.SIGTERM)
        time.sleep(1.0)
        os.killpg(p.pid, signal.SIGKILL)  # snakemake (and its jobs) as a crash would
        p.wait(timeout=10)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    assert len(recorded) >= 2, ("no two runs recorded in .snakemake/metadata within 60 s "
                                f"(recorded: {sorted(recorded)}; Snakemake's file persistence backend assumed)")
    present = {f: f.stat().st_mtime_ns for f in run.glob("results/runs/*/*.nc")}
    assert len(present) < 10, f"interrupt was not part way: all {len(present)} runs present"
    assert not (run / "results/stiffness.nc").exists()

    # a SIGKILLed snakemake leaves its lock: the documented `--unlock`, then rerun
    _snakemake(run, "--unlock")
    # the dry run says which runs it would redo; the others are finished and must survive
    # (the job blocks, which the workflow profile's quiet console leaves out, list the outputs)
    dry = _snakemake(run, "-n", "--rerun-incomplete", "--workflow-profile", "none")
    planned = {path for line in dry.splitlines() if "output:" in line
               for path in re.findall(r"results/runs/[^,\s]+\.nc", line)}
    done = {f: m for f, m in present.items() if str(f.relative_to(run)) not in planned}
    assert len(done) >= 2, f"fewer than two finished run survived the interrupt (present: {sorted(present)}, planned: {sorted(planned)})"
    _snakemake(run, "--cores", "2", "--rerun-incomplete")
    for f, mtime in done.items():
        assert f.stat().st_mtime_ns == mtime, f"{f} was recomputed"
    assert len(list(run.glob("results/runs/*/*.nc"))) == 10
    assert_same_numbers(ref / "results/stiffness.nc", run / "results/stiffness.nc")


def test_hard_kill_then_the_same_command_again(tmp_path):
    """SIGKILL to snakemake's process group part way (its locks and incomplete markers left behind),
    then the very same command: it completes (the default profile's rerun-incomplete, and
    roughcontact.study.files.locks removes the locks no live Snakemake holds), with every run and
    the merged file; while the run is alive its locks are kept."""
    from roughcontact.study.files import locks

    run = tmp_path / "run"
    _write(run)
    cmd = [sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(run), "--cores", "2",
           "--configfile", str(run / "config.yaml")]
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    p = subprocess.Popen(cmd, cwd=run, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env,
                         start_new_session=True)
    try:
        end = time.monotonic() + 90
        while time.monotonic() < end and not list(run.glob("results/runs/*/*.nc")):
            time.sleep(0.1)
        held = sorted((run / ".snakemake/locks").glob("*.lock"))
        kept = locks.stale_locks(run)   # snakemake is alive in run/: none of its locks is stale
        os.killpg(p.pid, signal.SIGKILL)
        p.wait(timeout=10)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    assert held, "the run took no lock before its first run file (or finished none within 90 s)"
    assert kept == [], f"the locks of a live run were called stale: {kept}"
    assert list((run / ".snakemake/locks").glob("*.lock")), "the kill left no lock: the test kills nothing"
    assert not (run / "results/stiffness.nc").exists(), "the kill was not part way"
    again = subprocess.run(cmd, cwd=run, capture_output=True, text=True, env=env, timeout=300)
    assert again.returncode == 0, again.stdout[-3000:] + again.stderr[-3000:]
    assert len(list(run.glob("results/runs/*/*.nc"))) == 10
    assert (run / "results/stiffness.nc").is_file() and (run / "results/summary.html").is_file()
    assert not list((run / ".snakemake/locks").glob("*.lock"))


def test_stale_locks_are_those_no_live_snakemake_holds(tmp_path, monkeypatch):
    """study.files.locks: locks in a directory no Snakemake process works in are stale (Linux); kept
    with ROUGHCONTACT_KEEP_LOCKS=1; a Snakemake process is told by its command line."""
    from roughcontact.study.files import locks

    assert locks._is_snakemake(["/usr/bin/python3", "-m", "snakemake", "--cores", "2"])
    assert locks._is_snakemake(["/usr/local/bin/snakemake", "--cores", "2"])
    assert not locks._is_snakemake(["python", "-m", "pytest", "tests/test_snakemake.py"])
    (tmp_path / ".snakemake" / "locks").mkdir(parents=True)
    lock = tmp_path / ".snakemake" / "locks" / "0.input.lock"
    lock.write_text("results/stiffness.nc\n")
    if locks.snakemake_processes(tmp_path) is None:
        assert locks.stale_locks(tmp_path) == []   # no /proc: every lock is kept
        return
    monkeypatch.setenv(locks.KEEP_LOCKS, "1")
    assert locks.clear_stale_locks(tmp_path) == [] and lock.exists()
    monkeypatch.delenv(locks.KEEP_LOCKS)
    assert locks.clear_stale_locks(tmp_path) == [str(lock)] and not lock.exists()
