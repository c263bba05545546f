"""Calibration of the scorecard's own model (study.analysis.calibration) recovers the constants it was made with."""
import math

import numpy as np
import pytest
import xarray as xr

from roughcontact.models import superposition
from roughcontact.study.analysis import calibration
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.files.io import write_groups
from roughcontact.study.files.provenance import canonical_json

FORCES = np.logspace(-6, -2, 13)
HURST = [0.5, 0.8]


def _eq13(hurst):
    return 1.7 / (np.asarray(hurst) + 1)


def _made_up(tmp_path, hurst, constants, scatter=(0.9, 1.0, 1.1)):
    """A study whose ensemble means are the model with (c_zeta, p) = constants(H) exactly (three seeds
    scattered by the factors *scatter*, of mean 1, around it)."""
    k = np.array([[superposition.stiffness_from_force(FORCES, radius=0.5, hurst=h, h_rms=1e-2, length=1.0,
                                                      e_star=1.0, zeta=constants(h)[0] * _eq13(h),
                                                      power=constants(h)[1], tail=(*constants(h), 0.0)[2])]
                  for h in hurst])
    k = k[:, :, None, None, :] * np.array(scatter)[None, None, None, :, None]   # (hurst, radius, h, seed, F)
    hurst = list(hurst)
    dims = ("hurst", "radius", "h_rms", "seed", "force")
    ds = xr.Dataset({"stiffness": (dims, k), "contact_cells": (dims, np.full(k.shape, 100))},
                    coords={"hurst": hurst, "radius": [0.5], "h_rms": [1e-2], "seed": [0, 1, 2], "force": FORCES})
    cfg = resolve_config({"grid": {"n": 129}, "hurst": hurst, "radius": [0.5], "h_rms": [1e-2], "seeds": 3,
                          "forces": {"sphere": {"from": float(FORCES[0]), "to": float(FORCES[-1]),
                                                "count": len(FORCES)}}, "fit": {"resolved_cells": 20}})
    (tmp_path / "results").mkdir()
    write_groups(tmp_path / "results" / "stiffness.nc", {"sphere": ds}, {"config": canonical_json(cfg)})
    return tmp_path


@pytest.fixture
def study(tmp_path, monkeypatch):
    """The model with c_zeta = 0.9 and p = 1.4 at H 0.5 and 0.8."""
    monkeypatch.setattr(superposition, "zeta_law", _eq13)
    return _made_up(tmp_path, HURST, lambda h: (0.9, 1.4))


#: the form ``hurst``'s made-up coefficients: c = 0.8 + 0.15 H, p = 0.9 + 0.8 H
LINEAR = {"zeta_factor": (0.8, 0.15), "power": (0.9, 0.8)}


@pytest.fixture
def hurst_study(tmp_path, monkeypatch):
    """The model with c_zeta and p linear in H (:data:`LINEAR`) at H 0.4, 0.6, 0.8."""
    monkeypatch.setattr(superposition, "zeta_law", _eq13)
    return _made_up(tmp_path, [0.4, 0.6, 0.8], lambda h: superposition.hurst_constants(h, LINEAR))


#: the form ``tail``'s made-up constants: c and p linear in H as :data:`LINEAR` but sharper, and β
TAIL = {"zeta_factor": (0.95, 0.05), "power": (1.8, 0.5), "tail": 2.0}


@pytest.fixture
def tail_study(tmp_path, monkeypatch):
    """The model with the tail join (:data:`TAIL`) at H 0.4, 0.6, 0.8."""
    monkeypatch.setattr(superposition, "zeta_law", _eq13)
    return _made_up(tmp_path, [0.4, 0.6, 0.8], lambda h: (*superposition.hurst_constants(h, TAIL), TAIL["tail"]))


def test_tail_form_recovers_the_tail(tail_study):
    assert calibration.calibrate([tail_study], "tail").tail == pytest.approx(TAIL["tail"], rel=1e-3), \
        "beta of the made-up study"


def test_tail_form_recovers_the_power(tail_study):
    assert calibration.calibrate([tail_study], "tail").power == pytest.approx(TAIL["power"], abs=1e-3), \
        "(p0, p1) of the made-up study"


def test_recovers_the_zeta_factor(study):
    assert calibration.calibrate([study]).zeta_factor == pytest.approx(0.9, rel=1e-4), "c_zeta of the made-up study"


def test_recovers_the_power(study):
    assert calibration.calibrate([study]).power == pytest.approx(1.4, rel=1e-4), "p of the made-up study"


def test_deviation_of_the_exact_model_is_zero(study):
    worst = max(calibration.calibrate([study]).max_rel_dev.values())
    assert worst == pytest.approx(0.0, abs=1e-6), "the model the study was made with"


def test_hurst_form_recovers_the_zeta_factor(hurst_study):
    assert calibration.calibrate([hurst_study], "hurst").zeta_factor == pytest.approx(LINEAR["zeta_factor"], abs=1e-4), \
        "(c0, c1) of the made-up study"


def test_hurst_form_recovers_the_power(hurst_study):
    assert calibration.calibrate([hurst_study], "hurst").power == pytest.approx(LINEAR["power"], abs=1e-3), \
        "(p0, p1) of the made-up study"


def test_unknown_form_rejected(study):
    with pytest.raises(ValueError, match="form must be one of"):
        calibration.calibrate([study], "quadratic")


def test_no_sphere_runs_rejected(tmp_path):
    (tmp_path / "results").mkdir()
    write_groups(tmp_path / "results" / "stiffness.nc", {"flat": xr.Dataset({"x": ("a", [1.0])})},
                 {"config": canonical_json(resolve_config({"grid": {"n": 33}, "hurst": [0.7], "radius": [math.inf],
                                                           "h_rms": [1e-2], "seeds": 2}))})
    with pytest.raises(ValueError, match="no resolved sphere loads"):
        calibration.calibrate([tmp_path])


def test_bootstrap_interval_collapses_without_scatter(tmp_path, monkeypatch):
    """Seeds that are all the exact model: every resample is the same ensemble, so the interval of
    c_zeta is the point 0.9 (to the optimiser's 1e-6)."""
    monkeypatch.setattr(superposition, "zeta_law", _eq13)
    study = _made_up(tmp_path, HURST, lambda h: (0.9, 1.4), scatter=(1.0, 1.0, 1.0))
    low, high = calibration.calibrate([study], resamples=20).zeta_factor_ci
    assert high - low == pytest.approx(0.0, abs=1e-6), "width of the interval of c_zeta without scatter"


def test_bootstrap_interval_brackets_the_estimate(study):
    result = calibration.calibrate([study], resamples=40)
    low, high = result.zeta_factor_ci
    assert low <= result.zeta_factor <= high, "the interval of c_zeta holds its estimate"


def test_bootstrap_interval_is_wider_than_zero_with_scatter(study):
    """Three seeds scattered by ±10 % at every load: a resample's mean moves by up to 10 %, and
    c_zeta with it, so the interval is at least 1 % wide."""
    low, high = calibration.calibrate([study], resamples=40).zeta_factor_ci
    assert high - low > 0.01, "width of the interval of c_zeta with ±10 % scatter"


def test_hurst_form_has_an_interval_per_coefficient(hurst_study):
    result = calibration.calibrate([hurst_study], "hurst", resamples=10)
    assert len(result.power_ci) == 2, "an interval for p0 and one for p1"


def test_negative_resamples_rejected(study):
    with pytest.raises(ValueError, match="resamples must be >= 0"):
        calibration.calibrate([study], resamples=-1)
