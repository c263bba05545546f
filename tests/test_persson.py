"""Persson's theory on a Spectrum against its closed-form limits; the rough sphere's limits."""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import erf

from roughcontact import surfaces
from roughcontact.models import persson
from roughcontact.surfaces import spectra

E_STAR = 2.0
GAMMA = 0.42
LENGTH = 1.0
RADIUS = 10.0


def grid_spectrum(n):
    heights = surfaces.self_affine(n, hurst=0.8, h_rms=1e-3, length=LENGTH, seed=n)
    return spectra.from_heights(heights, length=LENGTH)


SPECTRA = {
    "grid-15": lambda: grid_spectrum(15),
    "grid-16": lambda: grid_spectrum(16),
    "band": lambda: spectra.self_affine_spectrum(hurst=0.8, h_rms=1e-3, length=LENGTH,
                                                 cutoff=LENGTH / 100, points_per_decade=50),
}


@pytest.fixture(params=sorted(SPECTRA))
def spectrum(request):
    return SPECTRA[request.param]()


def top_w(spectrum):
    return float(persson.w(spectrum.q[-1], spectrum))


def test_w_at_the_top_is_from_rms_slope(spectrum):
    assert top_w(spectrum) == pytest.approx(math.sqrt(2) / spectrum.rms_slope, rel=1e-12), \
        "w(q1) = [½ Σ q² variance]^(−1/2)"
    assert np.isinf(persson.w(0.5 * spectrum.q[0], spectrum)), "no roughness below q[0]"


def test_separation_scale_against_quadrature():
    """u0 = γ√π ∫ q² C w dq for C = C0 q^(−2−2H) on q0..q1, by adaptive quadrature."""
    hurst, h_rms, cutoff = 0.7, 1e-2, LENGTH / 100
    q0, q1 = 2 * math.pi / LENGTH, 2 * math.pi / cutoff
    c0 = h_rms**2 / (2 * math.pi * (q0 ** (-2 * hurst) - q1 ** (-2 * hurst)) / (2 * hurst))

    def w_of_q(q):
        integral = (q ** (2 - 2 * hurst) - q0 ** (2 - 2 * hurst)) / (2 - 2 * hurst)
        return (math.pi * c0 * integral) ** -0.5

    exact = GAMMA * math.sqrt(math.pi) * quad(
        lambda q: c0 * q ** (-2 * hurst) * w_of_q(q), q0, q1, limit=400, points=[1.001 * q0])[0]
    band = spectra.self_affine_spectrum(hurst=hurst, h_rms=h_rms, length=LENGTH, cutoff=cutoff,
                                        points_per_decade=100)
    assert persson.separation_scale(band, gamma=GAMMA) == pytest.approx(exact, rel=2e-3), \
        "bin sum of q² C w̄ (100 bins/decade)"


def test_stiffness_is_pressure_over_u0_at_small_pressure(spectrum):
    u0 = persson.separation_scale(spectrum, gamma=GAMMA)
    pressure = 1e-6 * E_STAR / float(persson.w(spectrum.q[0], spectrum))
    stiffness = persson.interfacial_stiffness(pressure, spectrum, e_star=E_STAR, gamma=GAMMA)
    assert stiffness * u0 / pressure == pytest.approx(1.0, rel=1e-6), "K → p/u0"


def test_stiffness_is_minus_dp_du(spectrum):
    pressure = 0.3 * E_STAR / top_w(spectrum)
    step = 1e-5
    pair = pressure * np.array([1 - step, 1 + step])
    separation = persson.mean_separation(pair, spectrum, e_star=E_STAR, gamma=GAMMA)
    finite_difference = -(pair[1] - pair[0]) / (separation[1] - separation[0])
    stiffness = persson.interfacial_stiffness(pressure, spectrum, e_star=E_STAR, gamma=GAMMA)
    assert stiffness == pytest.approx(finite_difference, rel=1e-6), "K = −dp/dū"


def test_separation_vanishes_at_full_contact(spectrum):
    pressure = np.array([3.0, 10.0]) * E_STAR / top_w(spectrum)
    separation = persson.mean_separation(pressure, spectrum, e_star=E_STAR, gamma=GAMMA)
    assert separation[0] < 1e-4 * spectrum.h_rms, "ū small at w(q1) p/E* = 3"
    assert separation[1] < 1e-30 * spectrum.h_rms, "ū → 0 at w(q1) p/E* = 10"


def test_separation_decreases_with_pressure(spectrum):
    pressure = np.geomspace(1e-8, 10.0, 40) * E_STAR / top_w(spectrum)
    separation = persson.mean_separation(pressure, spectrum, e_star=E_STAR, gamma=GAMMA)
    assert np.all(np.diff(separation) < 0), "ū decreasing in p"


@pytest.mark.parametrize("scaled_pressure", [1e-9, 0.3, 2.0])
def test_single_shell_separation_against_quadrature(scaled_pressure):
    """One shell (q, h²): w = √2/(q h), ū = (h/√(2π)) G(s) for w uniform over the shell
    (w̄ = 2w), with G(s) = ∫_s^∞ (dt/t)[γ + 3(1−γ)erf²t] e^{−t²}."""
    q, h_rms = 2 * math.pi / LENGTH, 1e-2
    shell = spectra.Spectrum(q=[q], variance=[h_rms**2], length=LENGTH)
    w_bar = 2 * math.sqrt(2) / (q * h_rms)
    pressure = scaled_pressure * E_STAR / w_bar

    def integrand(t):
        return (GAMMA + 3 * (1 - GAMMA) * erf(t) ** 2) * math.exp(-t * t) / t

    lower = scaled_pressure
    g_value = sum(quad(integrand, a, b, limit=200)[0]
                  for a, b in [(lower, max(lower, 1.0)), (max(lower, 1.0), 12.0)])
    expected = q * w_bar * h_rms**2 / (2 * math.sqrt(math.pi)) * g_value
    separation = persson.mean_separation(pressure, shell, e_star=E_STAR, gamma=GAMMA)
    assert separation == pytest.approx(expected, rel=1e-7), f"ū at s = {scaled_pressure}"


def test_area_fraction_small_pressure_limit(spectrum):
    pressure = 1e-5 * E_STAR / top_w(spectrum)
    area = persson.contact_area_fraction(pressure, spectrum, e_star=E_STAR)
    assert area == pytest.approx(2 / math.sqrt(math.pi) * top_w(spectrum) * pressure / E_STAR,
                                 rel=1e-9), "A/A0 ≈ (2/√π) w(q1) p/E*"


def test_area_fraction_full_contact(spectrum):
    area = persson.contact_area_fraction(6.0 * E_STAR / top_w(spectrum), spectrum, e_star=E_STAR)
    assert area == pytest.approx(1.0, abs=1e-15), "A/A0 → 1"


def test_bad_pressure_is_rejected(spectrum):
    with pytest.raises(ValueError, match="pressure"):
        persson.mean_separation([1.0, -1.0], spectrum, e_star=E_STAR)


# ---- the rough sphere ----------------------------------------------------------------------

@pytest.fixture(scope="module")
def sphere_spectrum():
    return spectra.self_affine_spectrum(hurst=0.8, h_rms=1e-3, length=LENGTH, n=16)


def crossover_force(u0):
    """F* = √(6R) E* (u0/3)^(3/2), where 3F/u0 = k_H."""
    return math.sqrt(6 * RADIUS) * E_STAR * (u0 / 3) ** 1.5


def test_apex_method_small_force_is_linear(sphere_spectrum):
    u0 = persson.separation_scale(sphere_spectrum, gamma=GAMMA)
    force = 1e-9 * crossover_force(u0)
    result = persson.sphere_stiffness(force, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                      gamma=GAMMA, method="apex")
    assert result.stiffness * u0 / (3 * force) == pytest.approx(1.0, rel=1e-5), "k → 3F/u0"


@pytest.mark.parametrize("method", ["apex", "axisymmetric"])
def test_smooth_limit_is_hertz(method):
    smooth = spectra.self_affine_spectrum(hurst=0.8, h_rms=1e-9, length=LENGTH, n=16)
    force = 1e-3 * E_STAR * RADIUS**2
    result = persson.sphere_stiffness(force, smooth, radius=RADIUS, e_star=E_STAR, gamma=GAMMA,
                                      method=method, n_rings=160)
    hertz = (6 * RADIUS * E_STAR**2 * force) ** (1 / 3)
    tolerance = 1e-6 if method == "apex" else 5e-3      # 160 rings: discretisation
    assert result.stiffness == pytest.approx(hertz, rel=tolerance), f"{method}: k_H"


def test_axisymmetric_small_force_is_force_over_u0(sphere_spectrum):
    """Elastic deflection ≪ u0 and p in the log range: p ∝ e^{(d − r²/2R)/u0}, k = F/u0."""
    u0 = persson.separation_scale(sphere_spectrum, gamma=GAMMA)
    force = 1e-5 * crossover_force(u0)
    result = persson.sphere_stiffness(force, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                      gamma=GAMMA, n_rings=120)
    assert result.stiffness * u0 / force == pytest.approx(1.0, rel=1e-4), "k → F/u0"


def test_axisymmetric_large_force_is_hertz(sphere_spectrum):
    u0 = persson.separation_scale(sphere_spectrum, gamma=GAMMA)
    force = 1e5 * crossover_force(u0)
    result = persson.sphere_stiffness(force, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                      gamma=GAMMA, n_rings=160)
    assert result.stiffness / result.hertz_stiffness == pytest.approx(1.0, rel=5e-3), \
        "k → k_H at F ≫ F*"


def test_axisymmetric_stiffness_is_derivative_of_load_path(sphere_spectrum):
    u0 = persson.separation_scale(sphere_spectrum, gamma=GAMMA)
    force = crossover_force(u0) * np.array([1 - 1e-4, 1.0, 1 + 1e-4])
    result = persson.sphere_stiffness(force, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                      gamma=GAMMA, n_rings=120)
    secant = (force[2] - force[0]) / (result.approach[2] - result.approach[0])
    assert result.stiffness[1] == pytest.approx(secant, rel=1e-5), "k = dF/dd"


def test_axisymmetric_lies_between_linear_and_hertz(sphere_spectrum):
    u0 = persson.separation_scale(sphere_spectrum, gamma=GAMMA)
    force = crossover_force(u0) * np.array([1e-2, 1.0, 1e2])
    result = persson.sphere_stiffness(force, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                      gamma=GAMMA, n_rings=120)
    assert np.all(result.stiffness < result.hertz_stiffness), "softer than the smooth sphere"
    assert np.all(np.diff(result.stiffness) > 0), "stiffens with force"


def test_unknown_method_is_rejected(sphere_spectrum):
    with pytest.raises(ValueError, match="method"):
        persson.sphere_stiffness(1.0, sphere_spectrum, radius=RADIUS, e_star=E_STAR,
                                 method="hertz")
