"""The same config run twice gives identical numbers in results/stiffness.nc."""
from __future__ import annotations

import numpy as np
import xarray as xr

from test_slurm import TINY, _snakemake, _write_config  # noqa: F401  (helpers)


def test_same_config_twice_identical_numbers(tmp_path):
    dirs = [tmp_path / "a", tmp_path / "b"]
    for d in dirs:
        d.mkdir()
        _write_config(d)
        _snakemake(d, "--cores", "2")
    with xr.open_dataset(dirs[0] / "results/stiffness.nc") as a, xr.open_dataset(dirs[1] / "results/stiffness.nc") as b:
        assert set(a.data_vars) == set(b.data_vars) and "stiffness" in a
        for name in a.data_vars:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
        for name in a.coords:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
