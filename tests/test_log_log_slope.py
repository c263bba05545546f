"""The study's one log-log slope (roughcontact.study.analysis.statistics.log_log_slope): exact on
a power law, with and without a covariate, and the same numbers as the four fits it replaced
(the crossover table's slopes, claim (j), the free exponent of the ζ fit, claim (g))."""
from __future__ import annotations

import math

import numpy as np
import pytest

from roughcontact.study.analysis import eq16_fit
from roughcontact.study.analysis.statistics import log_log_slope

X = np.geomspace(1e-6, 1e-2, 9)


@pytest.mark.parametrize("c, a", [(1.0, 1 / 3), (2.5e-3, 1 / 1.7), (7.0, -0.4), (1e5, 2.0)])
def test_slope_of_a_power_law_is_its_exponent(c, a):
    got = log_log_slope(np.log(X), np.log(c * X**a))
    assert got == pytest.approx(a, abs=1e-12), f"slope of {c} x^{a}: {got}"


def test_slope_of_each_curve_of_a_stack():
    exponents = np.array([0.2, 0.5, 1 / 3])
    got = log_log_slope(np.log(X), np.log(3.0 * X[None, :] ** exponents[:, None]))
    np.testing.assert_allclose(got, exponents, rtol=0, atol=1e-12)


def test_partial_slope_with_a_covariate_is_its_exponent():
    """``y = c x^a z^b`` on a 3 × 3 product sweep: the slope in x with ln z as a covariate is a."""
    x, z = (v.ravel() for v in np.meshgrid([0.25, 0.5, 1.0], [4e-3, 9e-3, 2e-2]))
    y = 0.3 * x**1.7 * z**3.4
    got = log_log_slope(np.log(x), np.log(y), covariates=[np.log(z)])
    assert got == pytest.approx(1.7, abs=1e-12), f"partial slope: {got}"


def test_slope_of_a_constant_abscissa_is_nan():
    assert math.isnan(log_log_slope(np.zeros(4), np.arange(4.0))), "no slope without a spread of ln x"


def test_slope_explained_by_a_covariate_is_nan():
    x = np.array([1.0, 2.0, 4.0])
    assert math.isnan(log_log_slope(np.log(x), np.log(x), covariates=[2 * np.log(x)])), "collinear covariate"


def test_the_crossover_table_slope_is_the_one_slope():
    assert eq16_fit._slopes is log_log_slope, "eq16_fit._slopes is a second slope"


@pytest.fixture
def noisy():
    rng = np.random.default_rng(7)
    return np.log(X), np.log(X) / 1.7 + rng.normal(0, 0.05, (200, X.size))


def test_same_numbers_as_the_centred_formula(noisy):
    """The crossover table's and claim (j)'s formula before: ``Σ x̃ ln y / Σ x̃²``, bit for bit."""
    log_x, log_y = noisy
    xm = log_x - log_x.mean()
    assert np.array_equal(log_log_slope(log_x, log_y), (log_y * xm).sum(-1) / (xm @ xm)), "not bit-identical"


def test_same_numbers_as_polyfit(noisy):
    """The ζ fit's free exponent before: ``np.polyfit(x, y, 1)[0]``, to 1e-12."""
    log_x, log_y = noisy
    for y in log_y[:20]:
        assert log_log_slope(log_x, y) == pytest.approx(np.polyfit(log_x, y, 1)[0], rel=1e-12, abs=1e-14)


def test_same_numbers_as_the_least_squares_design(noisy):
    """Claim (g) before: ``lstsq`` of ``[1, ln R, ln h]`` for the value, ``pinv`` for the replicates,
    coefficient of ln R; to 1e-12."""
    rng = np.random.default_rng(3)
    radius, h_rms = (v.ravel() for v in np.meshgrid([0.25, 0.5, 1.0], [4e-3, 9e-3]))
    log_f = np.log(radius) * 0.85 + np.log(h_rms) * 1.6 + rng.normal(0, 0.05, (50, radius.size))
    design = np.column_stack([np.ones(radius.size), np.log(radius), np.log(h_rms)])
    before = np.linalg.pinv(design)[1] @ log_f.T
    got = log_log_slope(np.log(radius), log_f, covariates=[np.log(h_rms)])
    np.testing.assert_allclose(got, before, rtol=1e-12, atol=1e-14)
    point = np.linalg.lstsq(design, log_f[0], rcond=None)[0][1]
    assert got[0] == pytest.approx(point, rel=1e-12, abs=1e-14)
