"""The scorecard's models from a spectrum fit (roughcontact.study.analysis.measured_models).

A fit of :func:`roughcontact.surfaces.self_affine` without a window has H and h_rms exact to
~1e-9 and the measured grid spectrum equal to ``self_affine_spectrum(n=...)`` to ~1e-9 (see
``test_spectrum_fit.py``): every model must then agree with the scorecard's, called with the
generating parameters, to 1e-6 (eq. 16's and MDR's k depend smoothly on H and h_rms with
O(1) log-derivatives; MDR's piecewise-constant k does not jump for a 1e-9 shift at these loads).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from roughcontact.models import scorecard as registry
from roughcontact.study.analysis import scorecard
from roughcontact.study.analysis.measured_models import crossover_force, predict
from roughcontact.models import paper
from roughcontact.surfaces import self_affine
from roughcontact.surfaces.spectrum_fit import fit_spectrum

FORCES = np.geomspace(1e-6, 1e-2, 4)


def _fit(hurst, h_rms=0.009, n=129, length=1.0, scale=1.0):
    h = self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=1) * scale
    return fit_spectrum(h, length=length * scale, window=None, detrend="mean", resamples=20)


@pytest.mark.parametrize("hurst", [0.3, 0.8])
def test_predict_agrees_with_scorecard(hurst):
    n, length, radius, e_star, zeta = 129, 1.0, 0.5, 1.0, 1.1
    fit = _fit(hurst, n=n, length=length)
    combo = scorecard.Combination(radius=radius, hurst=hurst, h_rms=0.009, length=length, e_star=e_star,
                                  exponent=2.0, n=n, rolloff=length, cutoff=0.0, hardness=math.inf,
                                  zeta_fit=zeta)
    out = predict(FORCES, fit, radius=radius, e_star=e_star, length=length, n=n, zeta=zeta)
    assert list(out) == list(registry.models()) + ["crossover_force"]
    for name, model in registry.models().items():
        expected = model.predict(FORCES, combo.surface())
        finite = np.isfinite(expected)
        assert finite.any()
        np.testing.assert_allclose(out[name][finite], expected[finite], rtol=1e-6, err_msg=name)
        assert np.array_equal(np.isfinite(out[name]), finite)
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=0.009, length=length, e_star=e_star, zeta=zeta)
    assert float(out["crossover_force"]) == pytest.approx(f_tr, rel=1e-6)


def test_units_scale_force_and_stiffness():
    """Lengths × s, E* × p: forces × p s², stiffnesses × p s; exact for eq. 16 (a closed form
    inverted by bisection to machine precision), to the solvers' tolerances for the others."""
    s, p = 1e3, 1e-2
    n, radius = 129, 0.5
    base = predict(FORCES, _fit(0.8, n=n), radius=radius, e_star=1.0, length=1.0, n=n, zeta=1.0)
    scaled = predict(FORCES * p * s**2, _fit(0.8, n=n, scale=s), radius=radius * s, e_star=p, length=s,
                     n=n, zeta=1.0)
    for name in ("eq16_paper", "eq16_fitted"):
        np.testing.assert_allclose(scaled[name], base[name] * p * s, rtol=1e-10, err_msg=name)
    assert float(scaled["crossover_force"]) == pytest.approx(float(base["crossover_force"]) * p * s**2, rel=1e-10)
    for name in ("greenwood_tripp", "mdr", "persson"):
        finite = np.isfinite(base[name])
        np.testing.assert_allclose(scaled[name][finite], base[name][finite] * p * s, rtol=1e-5, err_msg=name)


def test_flat_surface():
    n = 129
    fit = _fit(0.8, n=n)
    out = predict(FORCES, fit, radius=math.inf, e_star=1.0, length=1.0, n=n)
    assert set(out) == {"eq16_paper", "eq16_law", "contact_scale", "contact_scale_h", "contact_scale_tail", "mdr", "persson",
                        "crossover_force"}
    zeta = float(paper.zeta_estimate(fit.hurst))
    np.testing.assert_allclose(out["eq16_paper"], paper.fractal_stiffness(
        FORCES, hurst=fit.hurst, h_rms=fit.h_rms_for(1.0, n), length=1.0, e_star=1.0, zeta=zeta), rtol=1e-12)
    assert math.isnan(float(out["crossover_force"]))
    assert math.isnan(crossover_force(fit, radius=math.inf, e_star=1.0, length=1.0, n=n))
    assert np.all(out["persson"] > 0) and np.all(np.diff(out["persson"]) > 0)


def test_h_rms_override():
    n, fit = 64, _fit(0.8, n=64)
    out = predict(FORCES, fit, radius=0.5, e_star=1.0, length=1.0, n=n, h_rms=fit.h_rms)
    expected = paper.stiffness_from_force(FORCES, radius=0.5, hurst=fit.hurst, h_rms=fit.h_rms, length=1.0,
                                          e_star=1.0, zeta=float(paper.zeta_estimate(fit.hurst)))
    np.testing.assert_allclose(out["eq16_paper"], expected, rtol=1e-12)
    assert float(out["crossover_force"]) == pytest.approx(crossover_force(
        fit, radius=0.5, e_star=1.0, length=1.0, n=n, h_rms=fit.h_rms), rel=1e-12)


def test_bad_input():
    fit = _fit(0.8, n=64)
    with pytest.raises(ValueError, match="force must be"):
        predict([0.0, 1e-3], fit, radius=1.0, e_star=1.0, length=1.0, n=64)
    with pytest.raises(ValueError, match="radius must be"):
        predict(FORCES, fit, radius=-1.0, e_star=1.0, length=1.0, n=64)
    with pytest.raises(ValueError, match="h_rms must be"):
        predict(FORCES, fit, radius=1.0, e_star=1.0, length=1.0, n=64, h_rms=0.0)
    with pytest.raises(TypeError, match="SpectrumFit"):
        predict(FORCES, {"hurst": 0.8}, radius=1.0, e_star=1.0, length=1.0, n=64)
