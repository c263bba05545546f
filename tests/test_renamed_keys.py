"""The study-wide analysis settings' renamed keys (roughcontact.study.config.renamed): an old key
in a configuration is refused in one line naming the new one; a configuration recorded in a file
before the rename is still read, with its own values."""
from __future__ import annotations

import copy
import json
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
import yaml

from roughcontact import errors
from roughcontact.study.analysis.grid_error import run_grid_error
from roughcontact.study.config import resolve_config
from roughcontact.study.config.renamed import RENAMED, current_layout
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.files.io import read_csv, write_groups
from roughcontact.study.files.provenance import canonical_json

ROOT = Path(__file__).resolve().parents[1]
TINY = yaml.safe_load((ROOT / "presets/tiny.yaml").read_text())
#: a value of each renamed key that is not its default (20 cells, 1000 resamples, 0.95)
OFF_DEFAULT = {("fit", "resolved_cells"): 5, ("fit", "bootstrap"): 37, ("fit", "confidence"): 0.8}


def _old_layout(cfg: dict) -> dict:
    """*cfg* (a resolved configuration) as a version before the rename recorded it."""
    old = copy.deepcopy(cfg)
    for before, after in RENAMED.items():
        value = old["fit"].pop(after[-1])
        old["fit"].setdefault("zeta", {})[before[-1]] = value
    return old


@pytest.mark.parametrize("old", list(RENAMED), ids=[".".join(p) for p in RENAMED])
def test_an_old_key_is_refused_in_one_line_naming_the_new_one(old):
    cfg = copy.deepcopy(TINY)
    cfg["fit"].setdefault("zeta", {})[old[-1]] = OFF_DEFAULT[RENAMED[old]]
    with pytest.raises(errors.ConfigError) as err:
        resolve_config(cfg)
    message = str(err.value)
    assert "\n" not in message, "one line"
    assert f"'{'.'.join(RENAMED[old])}'" in message, "names the new key"
    assert err.value.key == ".".join(old), "the key at fault is the old one"


def test_the_new_keys_are_read():
    cfg = copy.deepcopy(TINY)
    for (_, name), value in OFF_DEFAULT.items():
        cfg["fit"][name] = value
    fit = StudySettings.of(resolve_config(cfg)).fit
    assert (fit.resolved_cells, fit.bootstrap, fit.confidence) == (5, 37, 0.8)


def test_a_configuration_recorded_before_the_rename_reads_as_the_new_one():
    """A file's ``config`` attribute (JSON) in the old layout gives the same typed settings."""
    cfg = copy.deepcopy(TINY)
    for (_, name), value in OFF_DEFAULT.items():
        cfg["fit"][name] = value
    resolved = resolve_config(cfg)
    recorded = json.loads(canonical_json(_old_layout(resolved)))
    assert StudySettings.of(recorded).fit == StudySettings.of(resolved).fit


def test_the_stickiness_interval_of_an_old_recorded_configuration_is_read():
    resolved = resolve_config(yaml.safe_load((ROOT / "presets/adhesion.yaml").read_text()))
    recorded = json.loads(canonical_json(_old_layout(resolved)))
    assert StudySettings.of(recorded).stickiness == StudySettings.of(resolved).stickiness


def test_current_layout_leaves_a_current_configuration_as_it_is():
    resolved = resolve_config(copy.deepcopy(TINY))
    assert current_layout(resolved) is resolved


FORCE = np.geomspace(1e-6, 1e-3, 4)
#: mean contact cells of the four loads: the first is resolved at 5 cells, not at the default 20
CELLS = np.array([6, 30, 300, 3000])


def _merged(path: Path, k: np.ndarray, *, config: dict, n: int) -> None:
    """A merged ``stiffness.nc`` of one sphere combination with stiffness k[seed, force]."""
    axes = {"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3]}
    dims = (*axes, "seed", "force")
    shape = (1,) * len(axes) + k.shape
    sphere = xr.Dataset({"stiffness": (dims, k.reshape(shape)),
                         "contact_cells": (dims, np.broadcast_to(CELLS, k.shape).reshape(shape))},
                        coords={**axes, "seed": np.arange(k.shape[0]), "force": FORCE,
                                "force_normalized": ("force", FORCE)})
    path.mkdir(parents=True)
    write_groups(path / "stiffness.nc", {"sphere": sphere}, {"config": canonical_json(config), "grid_n": n})


def test_the_grid_error_reads_the_fit_settings_of_a_merged_file_written_before_the_rename(tmp_path):
    """``run_grid_error`` types the finer study's recorded configuration: in the old layout with
    ``fit.zeta.min_cells = 5``, the first load (6 mean contact cells) is cell-resolved; at the
    default 20 it would not be."""
    cfg = copy.deepcopy(TINY)
    cfg["fit"]["resolved_cells"] = 5
    old = _old_layout(resolve_config(cfg))
    k = 1 + 0.1 * np.random.default_rng(0).random((4, FORCE.size))
    _merged(tmp_path / "coarse", k * 1.05, config=old, n=64)
    _merged(tmp_path / "fine", k, config=old, n=128)
    run_grid_error(tmp_path / "coarse", tmp_path / "fine", tmp_path / "grid_error.csv")
    table = read_csv(tmp_path / "grid_error.csv")
    assert table["cell_resolved"].tolist() == [True, True, True, True]
