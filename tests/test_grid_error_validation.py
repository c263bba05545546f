"""The grid error's validation (roughcontact.study.analysis.grid_error_validation) on tables built with a
known estimate and a known actual error: the bounded fraction and the looseness are exact."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from roughcontact.study.analysis.grid_error_validation import compare, summary

FORCE = np.geomspace(1e-5, 1e-3, 4)
AXES = {"hurst": 0.7, "radius": 0.5, "exponent": 2.0, "h_rms": 9e-3, "rolloff": 1.0, "cutoff": 0.0,
        "hardness": np.inf}


def _tables(estimate, actual, grid_resolved=(True, True, True, False)):
    """The study's table (against its companion: g = 0.1 everywhere, the given estimate) and the
    actual one (the study against its reference: the given error), 100 study cells at every load."""
    study = pd.DataFrame({**AXES, "force_normalized": FORCE, "contact_cells_coarse": 25.0, "contact_cells_fine": 100.0,
                          "grid_error": 0.1, "grid_error_ci_low": 0.05, "grid_error_ci_high": 0.15,
                          "grid_ratio": 2.0, "grid_error_estimate": estimate, "band": 0.2,
                          "cell_resolved": True, "grid_resolved": list(grid_resolved)})
    reference = pd.DataFrame({**AXES, "force_normalized": FORCE, "contact_cells_coarse": 100.0,
                              "contact_cells_fine": 400.0, "grid_error": actual, "cell_resolved": True})
    return study, reference


def test_bounded_fraction_counts_the_resolved_loads():
    """Estimates 4 % at every load, actual errors 1, −3, 5, 9 %: of the three resolved loads, two bounded."""
    table = compare(*_tables(np.full(4, 0.04), [0.01, -0.03, 0.05, 0.09]))
    assert summary(table)["bounded_fraction"] == pytest.approx(2 / 3, rel=1e-12), table


def test_median_looseness_is_the_ratio_of_estimate_to_actual():
    """Ratios 4, 4/3 and 0.8 at the resolved loads: median 4/3."""
    table = compare(*_tables(np.full(4, 0.04), [0.01, -0.03, 0.05, 0.09]))
    assert summary(table)["median_looseness"] == pytest.approx(4 / 3, rel=1e-12), table


def test_every_cell_resolved_load_counts_without_the_grid_rule():
    table = compare(*_tables(np.full(4, 0.04), [0.01, -0.03, 0.05, 0.09]))
    assert summary(table)["cell_bounded_fraction"] == pytest.approx(0.5, rel=1e-12), table


def test_observed_order_of_a_power_law():
    """g = 0.1 and an actual error −0.1/2^1.5 (a monotone sequence of order 1.5 on r = 2): order 1.5."""
    table = compare(*_tables(np.full(4, 0.04), np.full(4, -0.1 / 2 ** 1.5)))
    np.testing.assert_allclose(table["order"], 1.5, rtol=1e-12, err_msg="observed order")
