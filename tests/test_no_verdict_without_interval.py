"""No verdict without an interval (issue 48, item 1): every row of the claims table passes
``registry.row``, which makes a consistent/differs verdict on a point or missing interval untested."""
import math

import pytest

from roughcontact.study.analysis import statistics
from roughcontact.study.claims import registry


def _row(verdict, low, high):
    return registry.row("x", "a statement", 0.2837, low, high, 0.3, verdict)


@pytest.mark.parametrize("verdict", ["consistent: inside", "differs: outside"])
def test_a_point_interval_is_untested(verdict):
    """One seed: every bootstrap resample is that seed, the interval [0.2837, 0.2837]."""
    assert _row(verdict, 0.2837, 0.2837)["verdict"] == "untested"


def test_a_point_interval_names_unresolved():
    assert _row("differs: outside", 0.2837, 0.2837)["untested_because"] == statistics.UNRESOLVED


def test_a_point_interval_says_why():
    assert "at least 2 seeds" in _row("differs: outside", 0.2837, 0.2837)["reason"]


def test_a_missing_interval_is_untested():
    assert _row("consistent: inside", math.nan, math.nan)["verdict"] == "untested"


def test_an_interval_keeps_its_verdict():
    assert _row("differs: outside", 0.27, 0.29)["verdict"] == "differs"


def test_an_untested_row_keeps_its_reason():
    text = statistics.untested(statistics.NOT_SWEPT, "one radius")
    assert _row(text, 0.2837, 0.2837)["reason"] == "one radius"


def test_a_one_seed_bootstrap_is_a_point():
    """What the rule guards against: the percentile interval of a bootstrap over one seed."""
    samples = 0.2837 * (1 + 0 * statistics.bootstrap_indices(1, 200)[:, 0])
    low, high = statistics.interval(samples, 0.95)
    assert low == high
