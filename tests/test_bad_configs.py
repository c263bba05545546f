"""Table of bad configs: each is rejected before any job runs, with one line naming the key."""
from __future__ import annotations

import copy
import math
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from roughcontact import errors
from roughcontact.study.config import resolve as config

REPO = Path(__file__).resolve().parents[1]

GOOD = {
    "grid": {"n": 65, "length": 1.0},
    "e_star": 1.0,
    "hurst": [0.5, 0.8],
    "radius": [0.5, math.inf],
    "h_rms": [9e-3],
    "seeds": 2,
    "forces": {"sphere": {"from": 1e-6, "to": 1e-2, "count": 6},
               "flat": {"from": 1e-5, "to": 1e-4, "count": 4}},
    "solver": {"tol": 1e-8, "stiffness": "punch"},
    "fit": {"resolved_cells": 5, "zeta": {"max_area_fraction": 0.1},
            "slopes": {"low_max_ratio": 0.3, "high_min_ratio": 5.0}},
}


def _set(cfg, path, value):
    keys = path.split(".")
    node = cfg
    for k in keys[:-1]:
        node = node[k]
    if value is DELETE:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value
    return cfg


DELETE = object()

# (id, dotted key to change, new value, text the one-line message must name)
BAD = [
    ("unknown-top-key", "colour", "red", "colour"),
    ("unknown-nested-key", "grid.cells", 65, "cells"),
    ("unknown-solver-key", "solver.tolerance", 1e-8, "tolerance"),
    ("missing-radius", "radius", DELETE, "radius"),
    ("n-string", "grid.n", "big", "grid.n"),
    ("n-float", "grid.n", 64.5, "grid.n"),
    ("n-too-small", "grid.n", 8, "grid.n"),
    ("length-zero", "grid.length", 0.0, "grid.length"),
    ("e-star-negative", "e_star", -1.0, "e_star"),
    ("hurst-zero", "hurst", [0.0, 0.5], "hurst"),
    ("hurst-two", "hurst", [2.0], "hurst"),
    ("hurst-negative", "hurst", [-0.3], "hurst"),
    ("hurst-not-list", "hurst", {"a": 1}, "hurst"),
    ("hurst-empty", "hurst", [], "hurst"),
    ("radius-zero", "radius", [0.0], "radius"),
    ("radius-negative", "radius", [-0.5, math.inf], "radius"),
    ("radius-empty", "radius", [], "radius"),
    ("h-rms-zero", "h_rms", [0.0], "h_rms"),
    ("h-rms-negative", "h_rms", [-9e-3], "h_rms"),
    ("seeds-zero", "seeds", 0, "seeds"),
    ("seeds-empty", "seeds", [], "seeds"),
    ("seeds-duplicate", "seeds", [1, 1, 2], "seeds"),
    ("seeds-negative", "seeds", [-1, 2], "seeds"),
    ("force-reversed", "forces.sphere", {"from": 1e-2, "to": 1e-6, "count": 6}, "forces.sphere"),
    ("force-equal", "forces.sphere", {"from": 1e-4, "to": 1e-4, "count": 6}, "forces.sphere"),
    ("force-zero", "forces.sphere.from", 0.0, "forces.sphere.from"),
    ("force-negative", "forces.flat.to", -1e-4, "forces.flat.to"),
    ("force-count-one", "forces.sphere.count", 1, "forces.sphere.count"),
    ("h-rms-missing", "h_rms", DELETE, "h_rms"),
    ("flat-full-contact", "forces.flat.to", 0.5, "forces.flat.to"),
    ("sphere-reaches-edge", "forces.sphere.to", 0.5, "forces.sphere.to"),
    ("tol-zero", "solver.tol", 0.0, "solver.tol"),
    ("stiffness-unknown", "solver.stiffness", "secant", "solver.stiffness"),
    ("maxiter-zero", "solver.maxiter", 0, "solver.maxiter"),
    ("resolved-cells-zero", "fit.resolved_cells", 0, "fit.resolved_cells"),
    ("area-fraction-above-one", "fit.zeta.max_area_fraction", 1.5, "fit.zeta.max_area_fraction"),
]


def test_table_is_large_enough():
    assert len(BAD) >= 20


def test_good_config_passes():
    config.resolve_config(copy.deepcopy(GOOD))


@pytest.mark.parametrize("key,value,named", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_config_rejected_with_one_line(key, value, named):
    cfg = _set(copy.deepcopy(GOOD), key, value)
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(cfg)
    msg = str(err.value)
    assert "\n" not in msg, msg
    assert named in msg, msg
    assert "allowed" in msg, msg


def test_difference_stiffness_with_hardness_rejected_with_one_line():
    cfg = _set(_set(copy.deepcopy(GOOD), "hardness", [0.5]), "solver.stiffness", "difference")
    with pytest.raises(errors.ConfigError, match=r"^config key 'solver.stiffness' = 'difference' is not allowed with "
                                                 r"'hardness\[0\]'.*allowed: punch[^\n]*$"):
        config.resolve_config(cfg)


# A few through the real `snakemake -n`: the run stops before any job, one line names the key.
@pytest.mark.parametrize("case", ["unknown-top-key", "radius-negative", "hurst-zero",
                                  "seeds-empty", "force-reversed"])
def test_bad_config_stops_snakemake_before_any_job(tmp_path, case):
    _, key, value, named = next(b for b in BAD if b[0] == case)
    cfg = _set(copy.deepcopy(GOOD), key, value)
    cfg_text = yaml.safe_dump(cfg).replace("inf", ".inf").replace("..inf", ".inf")
    (tmp_path / "bad.yaml").write_text(cfg_text)
    (tmp_path / "config.yaml").write_text(yaml.safe_dump(GOOD).replace("inf", ".inf").replace("..inf", ".inf"))
    r = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(tmp_path),
                        "--configfile", str(tmp_path / "bad.yaml"), "--cores", "1"],
                       capture_output=True, text=True, timeout=120)
    out = r.stdout + r.stderr
    assert r.returncode != 0, out
    lines = [l for l in out.splitlines() if "Invalid configuration" in l]
    assert len(lines) == 1 and named in lines[0], out
    assert not (tmp_path / "results").exists()


# A config file that is no config: one line naming the file (and, for YAML, the line and column),
# from the package's loader and from `snakemake` reading the checkout's config.yaml.
NOT_A_CONFIG = [
    ("empty", "", "is empty; allowed: a YAML mapping of config keys (hurst, radius, h_rms, seeds, ...)"),
    ("comments-only", "# hurst: [0.5]\n\n", "is empty; allowed: a YAML mapping of config keys "
                                            "(hurst, radius, h_rms, seeds, ...)"),
    ("syntax-error", "hurst: [0.5\nradius: [0.5]\n", "is not valid YAML (line 2, column 7): "
                                                     "expected ',' or ']', but got ':'"),
    ("a-list", "- hurst\n- radius\n", "holds a list; allowed: a YAML mapping of config keys "
                                      "(key: value lines: hurst, radius, h_rms, seeds, ...)"),
]


@pytest.mark.parametrize("text,said", [c[1:] for c in NOT_A_CONFIG], ids=[c[0] for c in NOT_A_CONFIG])
def test_a_file_that_is_no_config_is_named_by_the_loader(tmp_path, text, said):
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(errors.ConfigError) as err:
        config.load_config(path)
    assert str(err.value) == f"config file {path} {said}"


def _snakemake_in(directory: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(directory),
                           "--cores", "1", *args], capture_output=True, text=True, timeout=120)


def _messages(done: subprocess.CompletedProcess) -> list:
    """What Snakemake printed, without its note on the workflow's profile."""
    return [line for line in (done.stdout + done.stderr).splitlines() if line and not line.startswith("Using ")]


@pytest.mark.parametrize("text,said", [c[1:] for c in NOT_A_CONFIG if c[0] in ("empty", "syntax-error")],
                         ids=["empty", "syntax-error"])
def test_a_config_yaml_that_is_no_config_stops_snakemake_in_one_line(tmp_path, text, said):
    (tmp_path / "config.yaml").write_text(text)
    done = _snakemake_in(tmp_path, "-n")
    assert _messages(done) == [f"Invalid configuration: config file {tmp_path / 'config.yaml'} {said}"]


def test_a_config_yaml_that_is_no_config_runs_no_job(tmp_path):
    (tmp_path / "config.yaml").write_text("")
    _snakemake_in(tmp_path)
    assert not (tmp_path / "results").exists()


@pytest.fixture(scope="module")
def empty_configfile(tmp_path_factory):
    """`snakemake --configfile empty.yaml` run in a directory of its own: the directory and the run.

    Not fixable in the workflow: Snakemake (9.x) reads a --configfile while it parses its command
    line (snakemake.settings.types.ConfigSettings), before the Snakefile runs, and stops with its
    own two lines naming neither the file nor the line; `roughcontact check-config FILE` names them.
    What the workflow can still promise: a non-zero exit and no job."""
    where = tmp_path_factory.mktemp("empty_configfile")
    (where / "empty.yaml").write_text("")
    return where, _snakemake_in(where, "--configfile", str(where / "empty.yaml"))


def test_an_empty_configfile_stops_snakemake(empty_configfile):
    where, done = empty_configfile
    assert done.returncode != 0, _messages(done)


def test_an_empty_configfile_runs_no_job(empty_configfile):
    where, done = empty_configfile
    assert not (where / "results").exists(), _messages(done)


# A value given as one value of another type than the list its key also takes is shown as given.
def test_seeds_given_as_a_word_is_shown_as_given():
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(_set(copy.deepcopy(GOOD), "seeds", "six"))
    assert str(err.value).startswith("config key 'seeds' = 'six' is not allowed; allowed: ")


def test_seeds_given_as_a_word_says_a_positive_integer_is_allowed():
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(_set(copy.deepcopy(GOOD), "seeds", "six"))
    assert str(err.value).split("; allowed: ", 1)[1].startswith(
        "a positive integer <= 100000 or a non-empty list of distinct non-negative integers < 2^63 (")


def test_seeds_given_as_a_word_is_named_in_check_config(tmp_path):
    path = tmp_path / "six.yaml"
    path.write_text(yaml.safe_dump(_set(copy.deepcopy(GOOD), "seeds", "six")).replace("inf", ".inf")
                    .replace("..inf", ".inf"))
    done = subprocess.run([sys.executable, "-m", "roughcontact.cli", "check-config", str(path)],
                          capture_output=True, text=True, timeout=120)
    assert done.stderr.startswith("Invalid configuration: config key 'seeds' = 'six' is not allowed; "), done.stderr


def test_a_list_only_key_given_as_a_word_names_its_item():
    """hurst takes only a list (one value is a list of one): its item's error says what an H may be."""
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(_set(copy.deepcopy(GOOD), "hurst", "abc"))
    assert str(err.value).startswith("config key 'hurst[0]' = 'abc' is not allowed; allowed: a number > 0 and < 2")
