"""Test helper: compare two merged files (one group per surface kind) number by number."""
from __future__ import annotations

import xarray as xr

from roughcontact.study.files import io as study_io


def assert_same_numbers(path_a, path_b) -> None:
    """Both files have the same groups, and each group the same variables, coordinates and values
    (attributes such as the creation time may differ)."""
    a, b = study_io.read_groups(path_a), study_io.read_groups(path_b)
    assert sorted(a) == sorted(b), f"groups {sorted(a)} != {sorted(b)}"
    for kind in a:
        assert "stiffness" in a[kind], f"{kind} has no stiffness"
        xr.testing.assert_equal(a[kind], b[kind])
