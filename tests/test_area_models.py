"""The closed forms of the real contact area (roughcontact.models.area) against their limits and
an independent quadrature, and the rms slope of the grid's spectrum against the generated surface."""
import math

import numpy as np
import pytest
from scipy import integrate
from scipy.special import erf

from roughcontact import surfaces
from roughcontact.models import area
from roughcontact.models.area import laws
from roughcontact.models.scorecard import Surface

R, E_STAR = 0.5, 2.0


@pytest.mark.parametrize("beta", [0.05, 0.3, 0.499, 0.5, 0.501, 1.0, 2.0, 7.0])
def test_persson_fraction_equals_quadrature(beta):
    """∫₀¹ erf(β√u) du by adaptive quadrature (tolerance 1e-12) against the series / closed form;
    both sides of the switch at β = 0.5 included: agreement to 1e-10 relative."""
    expected, _ = integrate.quad(lambda u: erf(beta * math.sqrt(u)), 0.0, 1.0, epsabs=0, epsrel=1e-12)
    assert laws.persson_area_fraction(np.array([beta]))[0] == pytest.approx(expected, rel=1e-10)


def test_persson_small_force_is_linear_with_persson_kappa():
    """At β = √2 p0/(E* h') ~ 1e-4 Persson's area is κ F/(E* h') with κ = √(8/π) ≈ 1.5958 (the
    next term is O(β²) ~ 1e-8 relative): to 1e-6."""
    slope = 0.3
    force = 1e-12
    kappa = laws.persson_area(force, radius=R, e_star=E_STAR, rms_slope=slope) * E_STAR * slope / force
    assert kappa == pytest.approx(math.sqrt(8 / math.pi), rel=1e-6)


def test_persson_large_force_is_hertz():
    """At β ≫ 1 the fraction of Hertz's area is 1 − 1/(2β²) + O(e^(−β²)): at F = 1e3 E* R² with
    h' = 0.1, β ≈ 40, so A/(π a²) = 1 within 1e-3."""
    force = 1e3 * E_STAR * R**2
    ratio = laws.persson_area(force, radius=R, e_star=E_STAR, rms_slope=0.1) / laws.hertz_area(
        force, radius=R, e_star=E_STAR)
    assert ratio == pytest.approx(1.0, abs=1e-3)


def test_hertz_area_closed_form():
    """π a², a = (3FR/(4E*))^(1/3): F = 4/3 E* R² gives a = R, A = π R² (to round-off)."""
    assert laws.hertz_area(4 / 3 * E_STAR * R**2, radius=R, e_star=E_STAR) == pytest.approx(math.pi * R**2,
                                                                                         rel=1e-14)


def test_crossover_force_joins_the_two_laws():
    """At F_A = (π/κ)³ (3R/4)² E* h'³ the linear law equals Hertz's area (to round-off)."""
    f_a = laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2)
    assert laws.linear_area(f_a, e_star=E_STAR, rms_slope=0.2) == pytest.approx(
        laws.hertz_area(f_a, radius=R, e_star=E_STAR), rel=1e-12)


def test_joined_law_is_linear_below_the_crossover():
    """Below F_A the joined law is κ F/(E* h') with κ = 2, exactly."""
    f_a = laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2)
    force = 1e-3 * f_a
    assert laws.joined_area(force, radius=R, e_star=E_STAR, rms_slope=0.2) == pytest.approx(
        2.0 * force / (E_STAR * 0.2), rel=1e-14)


def test_joined_law_is_hertz_at_large_force():
    """Above F_A the joined law is Hertz's π a², exactly (the smaller of the two)."""
    f_a = laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2)
    force = 1e3 * f_a
    assert laws.joined_area(force, radius=R, e_star=E_STAR, rms_slope=0.2) == pytest.approx(
        laws.hertz_area(force, radius=R, e_star=E_STAR), rel=1e-14)


@pytest.mark.parametrize("n", [64, 65])
def test_rms_slope_is_that_of_the_generated_surface(n):
    """h'_rms of the grid's spectrum (the models' rms_slope) equals √⟨|∇h|²⟩ of the generated
    surface by spectral differentiation (Parseval; the generator draws phases only): odd and even
    grids, to 1e-10 relative."""
    hurst, h_rms, length = 0.7, 9e-3, 1.0
    heights = surfaces.self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=3)
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=length / n)
    spectrum = np.fft.fft2(heights) / n**2
    mean_square_gradient = np.sum(np.abs(spectrum) ** 2 * (q1[:, None] ** 2 + q1[None, :] ** 2))
    s = Surface(hurst=hurst, h_rms=h_rms, radius=R, length=length, n=n, e_star=E_STAR)
    assert area.rms_slope(s) == pytest.approx(math.sqrt(mean_square_gradient), rel=1e-10)


def test_area_models_registered_for_the_paraboloid_only():
    """The area models predict on a paraboloid and decline (None) on a cone and a flat surface."""
    force = np.geomspace(1e-6, 1e-2, 5)
    sphere = Surface(hurst=0.7, h_rms=9e-3, radius=R, length=1.0, n=65, e_star=E_STAR)
    cone = Surface(hurst=0.7, h_rms=9e-3, radius=R, length=1.0, n=65, e_star=E_STAR, exponent=1.0)
    assert sorted(area.predict(force, sphere)) == ["linear_hertz", "persson_area", "three_regime"]
    assert area.predict(force, cone) == {}


@pytest.mark.parametrize("ratio, expected", [(1.0, 0.654), (10.0, 0.904)])
def test_persson_fraction_at_multiples_of_the_crossover(ratio, expected):
    """Persson's A/(π a²) at F = ratio · F_A equals persson_area/hertz_area there (to 1e-12, any
    h'), and the values the claims quote: 0.654 at F_A, 0.904 at 10 F_A (to the 3 digits stated)."""
    force = ratio * laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.17)
    direct = laws.persson_area(force, radius=R, e_star=E_STAR, rms_slope=0.17) / laws.hertz_area(
        force, radius=R, e_star=E_STAR)
    assert float(laws.persson_fraction_at(ratio)) == pytest.approx(direct, rel=1e-12)
    assert float(laws.persson_fraction_at(ratio)) == pytest.approx(expected, abs=5e-4)


# three_regime (roughcontact.models.area.three_regime): its limits in closed form

def _three(force, *, slope=0.2, curvature=math.inf, **kw):
    from roughcontact.models.area.three_regime import three_regime_area

    return three_regime_area(np.atleast_1d(float(force)), radius=R, e_star=E_STAR, rms_slope=slope,
                             rms_curvature=curvature, **kw)[0]


def test_three_regime_small_force_is_the_linear_law_with_its_kappa():
    """Without the one-asperity term (h″ = inf) and at F = 1e-6 F_A (Φ(y) = y (1 − O(y²)), y ~ 1e-2)
    the area is κ F/(E* h′) with κ = 2.34: to 1e-3 relative."""
    from roughcontact.models.area.three_regime import KAPPA

    force = 1e-6 * laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2, kappa=KAPPA)
    assert _three(force) * E_STAR * 0.2 / force == pytest.approx(KAPPA, rel=1e-3)


def test_three_regime_smallest_force_is_one_summit():
    """With the one-asperity term the area at F → 0 is Hertz's on a summit of radius R_s = c_s/h″,
    π (3 F R_s/(4E*))^(2/3) (the linear term is smaller by F^(1/3)): at F = 1e-16 E* R², h″ = 50/R, to
    1e-3 relative."""
    from roughcontact.models.area.three_regime import SUMMIT

    force, curvature = 1e-16 * E_STAR * R**2, 50 / R
    expected = math.pi * (3 * force * SUMMIT / curvature / (4 * E_STAR)) ** (2 / 3)
    assert _three(force, curvature=curvature) == pytest.approx(expected, rel=1e-3)


@pytest.mark.parametrize("curvature", [math.inf, 50 / R])
def test_three_regime_large_force_is_hertz(curvature):
    """At F = 1e6 F_A (Φ = 1 − 1/(2β²), β ~ 200) the area is Hertz's π a² = π (3FR/(4E*))^(2/3), with
    or without the one-asperity term: to 1e-4 relative."""
    force = 1e6 * laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2)
    expected = math.pi * (3 * force * R / (4 * E_STAR)) ** (2 / 3)
    assert _three(force, curvature=curvature) == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize("ratio", [0.01, 1.0, 30.0])
def test_three_regime_reduces_to_persson(ratio):
    """With κ = √(8/π) and no one-asperity term the model is Persson's area under Hertz's pressure
    (laws.persson_area), at any load: to 1e-12 relative."""
    force = ratio * laws.area_crossover_force(radius=R, e_star=E_STAR, rms_slope=0.2)
    expected = laws.persson_area(np.array([force]), radius=R, e_star=E_STAR, rms_slope=0.2)[0]
    assert _three(force, kappa=laws.PERSSON_KAPPA) == pytest.approx(expected, rel=1e-12)


def test_three_regime_zero_force_is_zero_area():
    """F = 0: A = 0 (no division by Hertz's zero area)."""
    assert _three(0.0, curvature=50 / R) == 0.0


def test_rms_curvature_is_that_of_the_generated_surface():
    """h″_rms of the grid's spectrum equals √⟨(∇²h)²⟩ of the generated surface by spectral
    differentiation (Parseval), to 1e-3 relative: the grid spectrum keeps one wavenumber per shell,
    exact for q² (the rms slope agrees to 1e-10) but not for q⁴ (8e-5 apart at n = 65)."""
    from roughcontact.models.area.three_regime import rms_curvature

    n, hurst, h_rms, length = 65, 0.7, 9e-3, 1.0
    heights = surfaces.self_affine(n, hurst=hurst, h_rms=h_rms, length=length, seed=3)
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=length / n)
    spectrum = np.fft.fft2(heights) / n**2
    mean_square_laplacian = np.sum(np.abs(spectrum) ** 2 * (q1[:, None] ** 2 + q1[None, :] ** 2) ** 2)
    s = Surface(hurst=hurst, h_rms=h_rms, radius=R, length=length, n=n, e_star=E_STAR)
    assert rms_curvature(s) == pytest.approx(math.sqrt(mean_square_laplacian), rel=1e-3)
