"""Spectrum representations against Parseval and closed-form integrals of the self-affine band."""

import math

import numpy as np
import pytest

from roughcontact import surfaces
from roughcontact.surfaces import spectra

GRIDS = [15, 16]                      # odd and even n
BANDS = [{}, {"rolloff": 1.0, "cutoff": 0.3}]
LENGTH = 2.0


def band_integral(exponent, lower, upper):
    """∫_lower^upper q^exponent dq."""
    if exponent == -1:
        return math.log(upper / lower)
    return (upper ** (exponent + 1) - lower ** (exponent + 1)) / (exponent + 1)


def closed_form_moment(k, *, hurst, h_rms, length, cutoff, rolloff=None):
    """∫ d²q q^k C(q) = 2π ∫ q^(k+1) C dq of the plateau + power-law band, scaled to h_rms²."""
    q0, q1 = 2 * math.pi / length, 2 * math.pi / cutoff
    q_r = q0 if rolloff is None else 2 * math.pi / rolloff
    exponent = -2 - 2 * hurst

    def raw(k):
        plateau = q_r**exponent * (q_r ** (k + 2) - q0 ** (k + 2)) / (k + 2)
        return plateau + band_integral(exponent + k + 1, q_r, q1)

    return h_rms**2 * raw(k) / raw(0)


@pytest.mark.parametrize("n", GRIDS)
def test_from_heights_variance_is_parseval(n):
    heights = np.random.default_rng(n).normal(3.0, 0.2, size=(n, n))
    spectrum = spectra.from_heights(heights, length=LENGTH)
    variance = np.mean((heights - heights.mean()) ** 2)
    assert spectrum.h_rms**2 == pytest.approx(variance, rel=1e-12), "Σ variance = mean(h²)"


@pytest.mark.parametrize("n", GRIDS)
@pytest.mark.parametrize("band", BANDS)
def test_grid_spectrum_total_is_surface_variance(n, band):
    heights = surfaces.self_affine(n, hurst=0.7, h_rms=0.03, length=LENGTH, seed=5, **band)
    measured = spectra.from_heights(heights, length=LENGTH)
    built = spectra.self_affine_spectrum(hurst=0.7, h_rms=0.03, length=LENGTH, n=n, **band)
    surface_variance = np.mean(heights**2)
    assert measured.h_rms**2 == pytest.approx(surface_variance, rel=1e-12), "from_heights total"
    assert built.h_rms**2 == pytest.approx(surface_variance, rel=1e-12), \
        "self_affine_spectrum total"


@pytest.mark.parametrize("n", GRIDS)
@pytest.mark.parametrize("band", BANDS)
def test_grid_spectrum_equals_measured_shell_by_shell(n, band):
    heights = surfaces.self_affine(n, hurst=1.2, h_rms=0.03, length=LENGTH, seed=11, **band)
    measured = spectra.from_heights(heights, length=LENGTH)
    built = spectra.self_affine_spectrum(hurst=1.2, h_rms=0.03, length=LENGTH, n=n, **band)
    assert np.array_equal(measured.q, built.q), "same shells"
    assert np.max(np.abs(measured.variance - built.variance)) <= 1e-12 * 0.03**2, \
        "only phases are random: shell variances equal up to round-off"


@pytest.mark.parametrize("n", GRIDS)
def test_grid_shells_count_the_modes(n):
    spectrum = spectra.self_affine_spectrum(hurst=0.5, h_rms=1.0, length=LENGTH, n=n)
    modes = spectrum.bin_area / spectrum.q0**2
    assert modes.sum() == pytest.approx(n * n - 1, abs=1e-9), "every mode but q = 0 once"


def test_single_cosine_persson_c():
    """h = a cos(q0 x): variance a²/2 on the q0 shell of 4 modes, C = a²/(8 q0²)."""
    n, amplitude = 16, 0.3
    x = np.arange(n) * LENGTH / n
    heights = np.broadcast_to(amplitude * np.cos(2 * np.pi * x / LENGTH), (n, n))
    spectrum = spectra.from_heights(heights, length=LENGTH)
    q0 = 2 * np.pi / LENGTH
    assert spectrum.variance[0] == pytest.approx(amplitude**2 / 2, rel=1e-12), "shell variance"
    assert spectrum.persson_c()[0] == pytest.approx(amplitude**2 / (8 * q0**2), rel=1e-12), "C(q0)"


@pytest.mark.parametrize("hurst", [0.3, 1.0, 1.6])
@pytest.mark.parametrize("rolloff", [None, 0.4])
def test_analytic_band_height_and_slope(hurst, rolloff):
    kwargs = {"hurst": hurst, "h_rms": 0.01, "length": LENGTH, "cutoff": LENGTH / 500}
    spectrum = spectra.self_affine_spectrum(rolloff=rolloff, **kwargs)
    slope2 = closed_form_moment(2, rolloff=rolloff, **kwargs)
    curvature2 = closed_form_moment(4, rolloff=rolloff, **kwargs)
    assert spectrum.h_rms == pytest.approx(0.01, rel=1e-12), "h_rms² = 2π∫qC dq"
    assert spectrum.rms_slope == pytest.approx(math.sqrt(slope2), rel=1e-10), "h'² = 2π∫q³C dq"
    assert spectrum.moment(4) == pytest.approx(curvature2, rel=1e-3), "2π∫q⁵C dq (bin quadrature)"


def test_analytic_band_persson_c_is_power_law():
    hurst, h_rms, cutoff = 0.8, 0.01, LENGTH / 300
    spectrum = spectra.self_affine_spectrum(hurst=hurst, h_rms=h_rms, length=LENGTH, cutoff=cutoff)
    # C0 from 2π ∫ q C0 q^(−2−2H) dq = h_rms²:
    q0, q1 = 2 * math.pi / LENGTH, 2 * math.pi / cutoff
    c0 = h_rms**2 / (2 * math.pi * band_integral(-1 - 2 * hurst, q0, q1))
    expected = c0 * spectrum.q ** (-2 - 2 * hurst)
    assert np.max(np.abs(spectrum.persson_c() / expected - 1)) < 1e-3, "C = C0 q^(−2−2H)"


def test_from_psd_round_trip_and_conventions():
    q = np.geomspace(np.pi, 3e3, 200)
    c = 1e-9 * q**-2.6
    persson = spectra.from_psd(q, c, length=LENGTH)
    topography = spectra.from_psd(q, (2 * np.pi) ** 2 * c, length=LENGTH,
                                  convention="surfacetopography")
    assert np.allclose(persson.persson_c(), c, rtol=1e-13, atol=0), "persson_c returns the table"
    assert np.allclose(topography.variance, persson.variance, rtol=1e-13, atol=0), \
        "C_iso = (2π)² C_Persson"


def test_from_psd_power_law_variance():
    hurst, q0, q1 = 0.7, np.pi, 3e3
    q = np.geomspace(q0, q1, 3 * 50 + 1)
    spectrum = spectra.from_psd(q, q ** (-2 - 2 * hurst), length=LENGTH)
    exact = 2 * math.pi * band_integral(-1 - 2 * hurst, q0, q1)
    assert spectrum.h_rms**2 == pytest.approx(exact, rel=2e-3), "trapezoid in ln q, 50/decade"


@pytest.mark.parametrize("q, c, message", [
    ([np.pi, 5.0, 5.0], [1.0, 1.0, 1.0], "ascending"),
    ([-1.0, 4.0], [1.0, 1.0], "> 0"),
    ([np.pi, 4.0], [1.0, np.nan], "finite"),
    ([np.pi, np.inf], [1.0, 1.0], "finite"),
    ([4.0, np.pi], [1.0, 1.0], "ascending"),
    ([np.pi, 4.0], [1.0, -1.0], ">= 0"),
    ([1.0, 4.0], [1.0, 1.0], "q0"),
    ([np.pi], [1.0], "length >= 2"),
])
def test_from_psd_rejects_bad_tables(q, c, message):
    with pytest.raises(ValueError, match=message):
        spectra.from_psd(q, c, length=LENGTH)


def test_from_psd_rejects_unknown_convention():
    with pytest.raises(ValueError, match="convention"):
        spectra.from_psd([np.pi, 4.0], [1.0, 1.0], length=LENGTH, convention="iso")


def test_continuous_band_needs_cutoff():
    with pytest.raises(ValueError, match="cutoff is required"):
        spectra.self_affine_spectrum(hurst=0.7, h_rms=1.0, length=LENGTH)


def test_spectrum_is_immutable():
    spectrum = spectra.self_affine_spectrum(hurst=0.7, h_rms=1.0, length=LENGTH, n=8)
    with pytest.raises(ValueError):
        spectrum.variance[0] = 0.0
    with pytest.raises(AttributeError):
        spectrum.length = 1.0


@pytest.mark.parametrize("n", [128, 129])
def test_rebinned_keeps_the_height_and_slope_and_the_lowest_shells(n):
    """Merged shells keep Σ variance and Σ q² variance exactly; the lowest shells, one per
    logarithmic bin, stay as they are."""
    full = spectra.self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=n)
    coarse = full.rebinned(50)
    assert coarse.q.size < full.q.size / 5, f"{coarse.q.size} bins from {full.q.size} shells"
    assert coarse.h_rms == pytest.approx(full.h_rms, rel=1e-13), "h_rms of the rebinned spectrum"
    assert coarse.rms_slope == pytest.approx(full.rms_slope, rel=1e-13), "rms slope of the rebinned spectrum"
    assert np.array_equal(coarse.q[:3], full.q[:3]), "the three lowest shells are merged with others"


def test_rebinning_leaves_persson_sphere_stiffness_unchanged():
    """The sphere's stiffness from 100 bins per decade equals that of all 1620 shells of a 129²
    grid to 1e-5 (measured 2e-7): the integrands vary slowly across a bin of 2.3 % in q."""
    from roughcontact.models import persson

    full = spectra.self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=129)
    force = np.array([1e-5, 1e-3])
    exact = persson.sphere_stiffness(force, full, radius=0.5, e_star=1.0).stiffness
    coarse = persson.sphere_stiffness(force, full.rebinned(100), radius=0.5, e_star=1.0).stiffness
    assert np.allclose(coarse, exact, rtol=1e-5, atol=0), f"{coarse} against {exact}"


def test_structure_function_of_one_mode_is_the_bessel_closed_form():
    # one isotropic shell of wavenumber q and variance v: SF(r) = 2 v (1 - J0(q r)) exactly
    from scipy.special import j0

    one = spectra.Spectrum(q=np.array([20.0]), variance=np.array([4e-6]), length=1.0)
    lag = np.array([0.01, 0.1, 0.3])
    assert one.structure_function(lag) == pytest.approx(2 * 4e-6 * (1 - j0(20.0 * lag)), rel=1e-12)


def test_structure_function_small_lag_is_half_the_slope_squared():
    # 1 - J0(x) = x^2/4 + O(x^4): SF(r) -> rms_slope^2 r^2 / 2 for r much shorter than every wavelength
    spectrum = spectra.self_affine_spectrum(hurst=0.8, h_rms=1e-2, length=1.0, n=65)
    lag = 1e-5
    assert spectrum.structure_function(lag) == pytest.approx(spectrum.rms_slope**2 * lag**2 / 2, rel=1e-4)


def test_structure_function_long_lag_tends_to_twice_the_variance():
    # J0(x) -> 0 (as x^-1/2) for x >> 1: one mode at q = 50, lag 1e4: |J0(5e5)| < 1.2e-3
    one = spectra.Spectrum(q=np.array([50.0]), variance=np.array([1e-4]), length=1.0)
    assert one.structure_function(1e4) == pytest.approx(2e-4, rel=2e-3)
