"""The spectrum fit of a topography (roughcontact.surfaces.spectrum_fit) against closed forms.

:func:`roughcontact.surfaces.self_affine` randomises only the phases: its grid spectrum is
exactly ``A q^(−2H−2)`` on every mode (``self_affine_spectrum(n=...)``), so without a window a
fit has zero scatter and must return H and h_rms to round-off. With the Hann window, the
windowed spectrum of one realisation scatters about its expectation (which the fit models
exactly); the tolerances of those tests are stated where they are used.
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from roughcontact.errors import RoughContactError
from roughcontact.surfaces import self_affine
from roughcontact.surfaces.spectra import self_affine_spectrum
from roughcontact.surfaces.spectrum_fit import SpectrumFitError, fit_spectrum

_DEFAULT = Path(__file__).resolve().parents[1].parent / "shared" / "topographies"
SHARED = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES", _DEFAULT))


def _tiles(h, size):
    n = h.shape[0] // size
    return [h[a * size:(a + 1) * size, b * size:(b + 1) * size] for a in range(n) for b in range(n)]


@pytest.mark.parametrize("n", [128, 129])
@pytest.mark.parametrize("hurst", [0.3, 0.8])
def test_periodic_surface_recovers_hurst_and_h_rms_exactly(n, hurst):
    h_rms, length = 0.01, 2.0
    h = self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=7)
    fit = fit_spectrum(h, length=length, window=None, detrend="mean")
    # zero scatter (phases only): the fit is exact up to the optimiser's tolerance
    assert fit.hurst == pytest.approx(hurst, abs=1e-6)
    assert fit.h_rms_fit == pytest.approx(h_rms, rel=1e-6)
    assert fit.h_rms_for(length, n) == pytest.approx(h_rms, rel=1e-6)
    assert fit.h_rms == pytest.approx(h_rms, rel=1e-12)
    assert (fit.q_min, fit.q_max) == pytest.approx((2 * 2 * np.pi / length, 0.25 * np.pi * n / length))
    assert fit.windows == 1 and fit.n == n and "residual" in fit.interval
    assert hurst in fit.hurst_ci and np.isnan(fit.h_rms_ci.low)
    exact = self_affine_spectrum(hurst=hurst, h_rms=h_rms, length=length, n=n)
    np.testing.assert_allclose(fit.spectrum.variance, exact.variance, rtol=1e-9, atol=1e-12 * h_rms**2)
    assert fit.rms_slope_spectrum == pytest.approx(exact.rms_slope, rel=1e-9)
    np.testing.assert_allclose(fit.fit_model, fit.fit_c, rtol=1e-6)


def test_rms_slope_from_heights_and_spectrum():
    n, length, h_rms = 256, 1.0, 0.002
    delta = length / n
    h = self_affine(n, hurst=0.8, h_rms=h_rms, length=length, seed=3, cutoff=8 * delta)
    fit = fit_spectrum(h, length=length, window=None, detrend="mean", band=(4 * np.pi, 0.2 * np.pi * n))
    sdq = np.sqrt(np.mean(np.diff(h, axis=0) ** 2) + np.mean(np.diff(h, axis=1) ** 2)) / delta
    assert fit.rms_slope == pytest.approx(sdq, rel=1e-12)
    # Difference quotient's symbol (2/Δ) sin(q_x Δ/2) per axis: with every mode at |q| ≤ 2π/(8Δ),
    # sin²x/x² ≥ 1 − x²/3 at x ≤ π/8, so the finite-difference slope lies between
    # √(1 − (π/8)²/3) = 0.974 and 1 times the spectral one (np.diff's missing seam row: < 1 %).
    ratio = fit.rms_slope / fit.rms_slope_spectrum
    assert 0.97 < ratio < 1.005


@pytest.mark.parametrize("n", [512, 513])
@pytest.mark.parametrize("hurst", [0.3, 0.8])
def test_tiles_bootstrap_interval_contains_true_hurst(n, hurst):
    """16 Hann-windowed tiles of 128²: the 95 % percentile interval (half-width ≈ 0.06 here)
    contains H, and the estimate is within 0.06 of it (one half-width)."""
    h = self_affine(n, hurst=hurst, h_rms=0.01, length=1.0, seed=5)
    size = 128
    fit = fit_spectrum(_tiles(h, size), length=size / n, seed=1, resamples=400)
    assert fit.windows == 16 and "bootstrap over the 16 windows" in fit.interval
    assert hurst in fit.hurst_ci
    assert fit.hurst == pytest.approx(hurst, abs=0.06)
    assert fit.h_rms_fit in fit.h_rms_fit_ci
    assert fit.h_rms in fit.h_rms_ci and fit.rms_slope in fit.rms_slope_ci
    assert fit.rms_slope_spectrum in fit.rms_slope_spectrum_ci
    # the fit extrapolated to the whole periodic surface gives its h_rms within the band's scatter
    assert fit.h_rms_for(1.0, n) == pytest.approx(0.01, rel=0.15)


def test_hann_single_window_within_scatter():
    """One 256² window: the Hann-windowed spectrum of one realisation scatters (H over seeds 0–5:
    standard deviation ≈ 0.07), so H is asked within 0.15 (about two standard deviations)."""
    h = self_affine(256, hurst=0.8, h_rms=1.0, length=1.0, seed=2)
    fit = fit_spectrum(h, length=1.0)
    assert fit.hurst == pytest.approx(0.8, abs=0.15)
    assert np.isfinite(fit.hurst_ci.low) and fit.hurst_ci.low < fit.hurst < fit.hurst_ci.high


def test_seeded_bootstrap_is_reproducible():
    h = self_affine(256, hurst=0.5, h_rms=1.0, length=1.0, seed=0)
    a, b = (fit_spectrum(_tiles(h, 64), length=0.25, resamples=50, seed=4) for _ in range(2))
    assert a.hurst_ci == b.hurst_ci and a.h_rms_fit_ci == b.h_rms_fit_ci


def _one_line(call, *args, **kwargs):
    with pytest.raises(SpectrumFitError) as err:
        call(*args, **kwargs)
    assert isinstance(err.value, RoughContactError) and isinstance(err.value, ValueError)
    message = str(err.value)
    assert "\n" not in message
    return message


def test_bad_input_raises_one_line():
    h = self_affine(64, hurst=0.8, h_rms=1.0, length=1.0, seed=0)
    assert "holds 2 logarithmic bins" in _one_line(fit_spectrum, h, length=1.0, band=(13.0, 20.0))
    assert "band must satisfy" in _one_line(fit_spectrum, h, length=1.0, band=(1.0, 20.0))
    assert "band must be" in _one_line(fit_spectrum, h, length=1.0, band="wide")
    white = np.random.default_rng(0).normal(size=(64, 64))
    assert "outside (0, 2)" in _one_line(fit_spectrum, white, length=1.0)
    assert "square 2-D arrays of one shape" in _one_line(fit_spectrum, h[:, :40], length=1.0)
    assert "of one shape" in _one_line(fit_spectrum, [h, h[:32, :32]], length=1.0)
    assert "constant heights" in _one_line(fit_spectrum, np.ones((32, 32)), length=1.0)
    bad = h.copy()
    bad[3, 3] = np.nan
    assert "finite" in _one_line(fit_spectrum, bad, length=1.0)
    assert "length is required" in _one_line(fit_spectrum, h)
    assert "length > 0" in _one_line(fit_spectrum, h, length=-1.0)
    assert "window must be" in _one_line(fit_spectrum, h, length=1.0, window="welch")
    assert "detrend must be" in _one_line(fit_spectrum, h, length=1.0, detrend="quadric")
    assert "empty list" in _one_line(fit_spectrum, [], length=1.0)
    assert "square 2-D arrays" in _one_line(fit_spectrum, 3.0, length=1.0)
    assert "confidence" in _one_line(fit_spectrum, h, length=1.0, confidence=95)


@pytest.mark.skipif(not (SHARED / "di-6.di").is_file(), reason=f"measured scans not found in {SHARED}")
def test_di6_fit():
    pytest.importorskip("SurfaceTopography")
    from roughcontact.surfaces import from_topography, tiles

    surface = from_topography(SHARED / "di-6.di", detrend="height")
    # di-6 rolls off near a wavelength of L/20 = 500 nm: its spectrum is nearly flat (C ~ q^-1)
    # above, so the default band of the whole scan (L/2 to 8 pixels) fits H < 0 and says so.
    assert "outside (0, 2)" in _one_line(fit_spectrum, surface)
    q0 = 2 * np.pi / surface.length
    fit = fit_spectrum(surface, band=(16 * q0, 64 * q0))        # 625 nm to 156 nm
    assert np.isfinite(fit.hurst) and 0.0 < fit.hurst < 1.2
    assert fit.h_rms == pytest.approx(14.3, rel=0.05)           # README: Sq = 14.3 nm
    assert np.isfinite(fit.h_rms_fit) and np.isfinite(fit.rms_slope)
    tiled = fit_spectrum(tiles(surface, 128), resamples=400)
    assert tiled.windows == 16 and 0.0 < tiled.hurst_ci.low <= tiled.hurst <= tiled.hurst_ci.high < 1.2
