"""The same config run twice gives identical numbers in results/stiffness.nc."""
from __future__ import annotations

import pytest
from merged import assert_same_numbers
from test_slurm import _snakemake, _write_config


@pytest.mark.workflow
def test_same_config_twice_identical_numbers(tmp_path):
    dirs = [tmp_path / "a", tmp_path / "b"]
    for d in dirs:
        d.mkdir()
        _write_config(d)
        _snakemake(d, "--cores", "2")
    assert_same_numbers(dirs[0] / "results/stiffness.nc", dirs[1] / "results/stiffness.nc")
