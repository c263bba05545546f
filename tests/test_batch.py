"""Batched indent jobs (``jobs.batch``): the runs of one job written one file each, the same bytes
of data as one run per job; a failure midway leaves the finished runs valid and nothing partial;
the blocks of seeds and the config key."""
from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr

from roughcontact.errors import ConfigError, IndentError
from roughcontact.study.config.resolve import load_config, resolve_config, study_settings
from roughcontact.study.files import io as study_io
from roughcontact.study.rules import indent
from roughcontact.study.runs import jobs, naming

ROOT = Path(__file__).resolve().parents[1]
TINY = ROOT / "presets/tiny.yaml"


def _tiny_runs():
    """Three runs of presets/tiny.yaml (65²): a sphere and a flat surface of seed 0, a sphere of seed 1."""
    study = study_settings(load_config(TINY))
    pick = [{"hurst": 0.8, "radius": 0.5, "h_rms": 9e-3, "seed": 0},
            {"hurst": 0.5, "radius": float("inf"), "h_rms": 2e-2, "seed": 0},
            {"hurst": 0.8, "radius": 0.5, "h_rms": 9e-3, "seed": 1}]
    return pick, [jobs.job_settings(study, run) for run in pick]


def _assert_same_data(a: Path, b: Path) -> None:
    """Every variable and coordinate of the two run files equal at tolerance 0 (values, dtypes,
    dimensions and attributes); the global attributes equal except the creation time."""
    with xr.open_dataset(a) as x, xr.open_dataset(b) as y:
        assert sorted(x.variables) == sorted(y.variables), f"{a.name}: variables"
        for name in x.variables:
            xr.testing.assert_identical(x[name], y[name])
        differ = {k for k in set(x.attrs) | set(y.attrs) if x.attrs.get(k) != y.attrs.get(k)}
        assert differ <= {"created_utc"}, f"{a.name}: global attributes differ: {sorted(differ)}"


def test_a_batch_writes_the_files_of_one_run_jobs(tmp_path):
    """The runs of one batch (one process, one after another) against each run alone in a fresh
    interpreter (`roughcontact indent`, what a one-run job runs): the same data, bit for bit."""
    pick, settings = _tiny_runs()
    batch = [tmp_path / f"batch{i}.nc" for i in range(len(pick))]
    indent.run(settings, outputs=batch, logs=[tmp_path / f"batch{i}.log" for i in range(len(pick))])
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    for i, run in enumerate(pick):
        alone = tmp_path / f"alone{i}.nc"
        done = subprocess.run([sys.executable, "-m", "roughcontact.cli", "indent", "--config", str(TINY),
                               "--hurst", str(run["hurst"]), "--radius", str(run["radius"]), "--h-rms",
                               str(run["h_rms"]), "--seed", str(run["seed"]), "-o", str(alone), "-q"],
                              capture_output=True, text=True, env=env, timeout=120)
        assert done.returncode == 0, done.stderr
        _assert_same_data(batch[i], alone)


def test_a_failure_midway_leaves_the_finished_runs_valid_and_nothing_partial(tmp_path):
    """The second of three runs cannot converge (maxiter 1): the first file is complete and valid
    (it reads back against its own settings), the second and third leave no file and no temporary
    file, the error names the failing run and carries its log, which has the traceback."""
    _, settings = _tiny_runs()
    settings[1] = dataclasses.replace(settings[1], maxiter=1)
    outputs = [tmp_path / f"run{i}.nc" for i in range(3)]
    logs = [tmp_path / f"run{i}.log" for i in range(3)]
    with pytest.raises(IndentError, match="did not converge") as info:
        indent.run(settings, outputs=outputs, logs=logs)
    assert "seed = 0" in str(info.value) and "R = inf" in str(info.value), str(info.value)
    assert info.value.run_log == logs[1], "the failing run's log"
    assert "Traceback" in logs[1].read_text(), "the details in the log"
    study_io.read_run(outputs[0], settings[0])   # complete and valid: raises otherwise
    assert [p.name for p in sorted(tmp_path.iterdir()) if p.suffix != ".log"] == ["run0.nc"], \
        "only the finished run's file, nothing partial"


def test_the_indent_rule_refuses_unequal_lists(tmp_path):
    _, settings = _tiny_runs()
    with pytest.raises(ValueError, match="3 runs, 2 outputs"):
        indent.run(settings, outputs=[tmp_path / "a.nc", tmp_path / "b.nc"])


def test_seed_blocks_group_seeds_by_value():
    blocks = naming.seed_blocks([7, 0, 1, 5, 6, 12], 6)
    assert [b.seeds for b in blocks] == [(0, 1, 5), (6, 7), (12,)]


def test_seed_blocks_name_their_range():
    assert [b.name for b in naming.seed_blocks(range(8), 6)] == ["seeds0_5", "seeds6_11"]


def test_a_new_seed_changes_only_its_block():
    """What reruns when a seed is added: only the job of the new seed's block (its outputs and
    params change); every other block keeps its seeds."""
    before = naming.seed_blocks(range(10), 4)
    after = naming.seed_blocks(range(11), 4)
    assert before[:2] == after[:2] and before[2].seeds == (8, 9) and after[2].seeds == (8, 9, 10)


def test_batch_one_is_a_job_per_seed():
    assert [b.seeds for b in naming.seed_blocks([3, 1, 2], 1)] == [(1,), (2,), (3,)]


def test_batch_defaults_to_the_schemas_value():
    study = study_settings(load_config(ROOT / "config.yaml"))
    assert study.jobs.batch == 6


def test_batch_runtime_grows_with_the_runs():
    study = study_settings(load_config(ROOT / "config.yaml"))
    assert naming.indent_resources(study, 600)["runtime"] > naming.indent_resources(study)["runtime"]


def test_batch_memory_is_that_of_one_run():
    """The runs of a job follow one another: one is alive at a time."""
    study = study_settings(load_config(ROOT / "config.yaml"))
    assert naming.indent_resources(study, 60)["mem_mb"] == naming.indent_resources(study)["mem_mb"]


def test_batch_priority_is_the_jobs_expected_cost():
    """The longest jobs first: a sphere block (19 loads) before a flat one (10) on the same grid,
    the 193² companion's block after both, more runs before fewer; an integer (Snakemake's priority)."""
    study = study_settings(load_config(ROOT / "config.yaml"))
    sphere = naming.indent_priority(study, "H0.7_R0.5_h0.009", 6)
    flat = naming.indent_priority(study, "H0.7_Rinf_h0.009", 6)
    coarse = naming.indent_priority(study.coarse_study(), "H0.7_R0.5_h0.009", 6)
    assert sphere > flat > coarse >= 1
    assert naming.indent_priority(study, "H0.7_R0.5_h0.009", 1) < sphere
    assert all(isinstance(p, int) for p in (sphere, flat, coarse))


@pytest.mark.parametrize("value", [0, -1, 1.5, "all", None])
def test_a_bad_batch_is_one_line_naming_the_key(value):
    raw = {**load_config(TINY), "jobs": {"batch": value}}
    with pytest.raises(ConfigError) as info:
        resolve_config(raw)
    text = str(info.value)
    assert "jobs.batch" in text and "\n" not in text, text


def test_an_unknown_key_of_jobs_is_one_line_naming_it():
    raw = {**load_config(TINY), "jobs": {"bacth": 2}}
    with pytest.raises(ConfigError, match="bacth") as info:
        resolve_config(raw)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("n, measured_gb", [(2049, 0.43), (4097, 1.42), (8193, 4.67)])
def test_declared_memory_follows_the_measured_peak(n, measured_gb):
    """An indent job's mem_mb against the peak RSS measured for one seed of the default sphere's 27 loads
    (benchmarks/RESULTS.md section 11, 2026-11-29): above it with room for the interpreter's imports
    (at least 1.3×), and not so far above that a cluster holds memory idle (at most 3×)."""
    from roughcontact.study.config import resolve_config

    study = resolve_config({"grid": {"n": n, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [9e-3],
                            "seeds": 1})
    declared_gb = naming.indent_resources(study)["mem_mb"] / 1000
    assert 1.3 * measured_gb <= declared_gb <= 3 * measured_gb


@pytest.mark.parametrize("n, solve_seconds", [(2049, 68.1), (4097, 327.6), (8193, 1883.8)])
def test_declared_runtime_follows_the_measured_wall(n, solve_seconds):
    """An indent job's runtime (minutes) against one seed of the default sphere's 27 loads (benchmarks/RESULTS.md
    section 11, 2026-11-29, a loaded machine): the solves took ``solve_seconds`` and the punch stiffness of every
    state 0.43–0.66× as long again (``large_grid.py --stiffness`` on 513²–2049²). The declaration covers a day twice
    as slow (at least 2× the slowest reading) and does not hold a cluster's slot for ever (at most 6× the fastest)."""
    from roughcontact.study.config import resolve_config

    study = resolve_config({"grid": {"n": n, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [9e-3],
                            "seeds": 1, "forces": {"sphere": {"from": 1e-7, "to": 2e-2, "count": 27}}})
    declared = naming.indent_resources(study)["runtime"] * 60
    assert declared >= 2 * 1.66 * solve_seconds, "declared runtime below twice the measured wall"
    assert declared <= 6 * 1.43 * solve_seconds, "declared runtime far above the measured wall"


def test_a_8193_sweep_of_50_seeds_is_submitted_as_it_is(tmp_path):
    """Issue 41 item 4: a SLURM user submits 8193² × 50 seeds without editing resources. The dry run through
    the SLURM profile plans the 9 + 9 indent jobs (the grid and its 4097² companion, 6 seeds per job), and every
    job's request fits a common cluster node and limit: at most 16 GB and 24 h (10.5 GB and 14.2 h; one run
    measured 31 min and 4.67 GB on a loaded machine, benchmarks/RESULTS.md section 11)."""
    pytest.importorskip("snakemake_executor_plugin_slurm")
    import subprocess
    import sys

    import yaml

    sweep = {"grid": {"n": 8193}, "hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 50}
    (tmp_path / "big.yaml").write_text(yaml.safe_dump(sweep))
    proc = subprocess.run([sys.executable, "-m", "snakemake", "-n", "--profile", str(ROOT / "profiles" / "slurm"),
                           "--configfile", str(tmp_path / "big.yaml"), "--directory", str(tmp_path)],
                          cwd=ROOT, capture_output=True, text=True, timeout=300)
    out = proc.stdout + proc.stderr
    assert proc.returncode == 0, out[-3000:]
    planned = [line.split() for line in out.splitlines() if line.startswith("indent")]
    assert sum(int(count) for _, count in {tuple(p) for p in planned}) == 18, out[-3000:]
    study = study_settings(sweep)
    for grid in (study, study.coarse_study()):
        request = naming.indent_resources(grid, 6)
        assert request["mem_mb"] <= 16000, f"{request} asks more than a 16 GB node"
        assert request["runtime"] <= 24 * 60, f"{request} asks more than 24 h"
