"""One YAML, one study (issue 40 item 2): a file given with ``--configfile`` is the whole sweep over
the schema's defaults, run from the repository or with ``--directory``; a grid names its own
grid-error companion, ``(n + 1)/2`` unless ``grid.coarse`` says otherwise."""
from __future__ import annotations

import contextlib
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from roughcontact.study.config import resolve_config
from roughcontact.study.config.companions import coarse_config, default_coarse

ROOT = Path(__file__).resolve().parents[1]
SWEEP = {"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 1}


@pytest.mark.parametrize(("n", "coarse"), [(385, 193), (257, 129), (256, 128), (65, 33), (33, 17), (31, None)])
def test_the_default_companion_halves_the_resolution(n, coarse):
    assert default_coarse(n) == coarse


def test_a_grid_without_coarse_gets_its_companion():
    cfg = resolve_config({**SWEEP, "grid": {"n": 257}})
    assert cfg["grid"]["coarse"] == 129


def test_coarse_null_turns_the_companion_off():
    cfg = resolve_config({**SWEEP, "grid": {"n": 257, "coarse": None}})
    assert cfg["grid"]["coarse"] is None


def test_the_companion_has_no_companion_of_its_own():
    cfg = resolve_config({**SWEEP, "grid": {"n": 257}})
    companion = resolve_config(coarse_config(cfg))
    assert (companion["grid"]["n"], companion["grid"]["coarse"]) == (129, None)


def _jobs(args, cwd) -> dict:
    """``rule: count`` of a dry run's job table."""
    out = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-n", *args], cwd=cwd,
                         capture_output=True, text=True, timeout=300, check=True).stdout
    table = out[out.index("Job stats"):]
    return dict(re.findall(r"^(\w+)\s+(\d+)$", table, flags=re.M))


def test_one_yaml_is_one_study_with_or_without_directory(tmp_path):
    """The same file run from the repository root (its study in studies/<stem>/) and with
    --directory: the same jobs (the 257² grid's companion on 129², no key of config.yaml merged in)."""
    sweep = tmp_path / f"one-yaml-{os.getpid()}.yaml"   # a stem no one else's study has
    sweep.write_text("grid: {n: 257}\nhurst: [0.7]\nradius: [0.5]\nh_rms: [9.0e-3]\nseeds: 2\n")
    own = ROOT / "studies" / sweep.stem
    assert not own.exists()
    try:
        from_root = _jobs(["--configfile", str(sweep)], ROOT)
        assert own.is_dir()   # made by the dry run, as --directory makes its directory
    finally:
        shutil.rmtree(own, ignore_errors=True)
        with contextlib.suppress(OSError):
            (ROOT / "studies").rmdir()   # where no other study is
    elsewhere = _jobs(["--configfile", str(sweep), "--directory", str(tmp_path / "study")], tmp_path)
    assert from_root == elsewhere
    assert any(rule.startswith("indent_coarse") for rule in from_root), from_root


def test_a_derived_companion_that_cannot_press_the_sweep_is_left_out():
    """A cutoff of 0.05 L is 2 cells of 65² but 1.6 of the derived 33²: no companion, no error."""
    cfg = resolve_config({**SWEEP, "grid": {"n": 65}, "cutoff": [0.05]})
    assert cfg["grid"]["coarse"] is None


def test_a_named_companion_that_cannot_press_the_sweep_is_refused_in_one_line():
    from roughcontact.errors import ConfigError

    with pytest.raises(ConfigError, match="grid.coarse") as err:
        resolve_config({**SWEEP, "grid": {"n": 65, "coarse": 33}, "cutoff": [0.05]})
    assert "\n" not in str(err.value)
