"""The analytic model (eqs. 7–18) against its own closed-form special cases."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from roughcontact import theory

HURSTS = [0.1, 0.3, 0.7, 1.0, 1.5, 1.9]


def test_kappa_at_one():
    assert theory.kappa(1.0) == pytest.approx(math.pi / 2, rel=1e-14), "κ(1) = π/2"


def test_kappa_at_two():
    assert theory.kappa(2.0) == pytest.approx(2.0, rel=1e-14), "κ(2) = 2"


@pytest.mark.parametrize("hurst", HURSTS)
def test_kappa_equals_its_integral(hurst):
    """Eq. 8: the gamma-function form equals H ∫₀¹ ξ^(H−1)/√(1−ξ²) dξ."""
    integral = quad(lambda xi: xi ** (hurst - 1) / math.sqrt(1 - xi**2), 0, 1, limit=200)[0]
    assert theory.kappa(hurst) == pytest.approx(hurst * integral, rel=1e-8), f"κ({hurst})"


def test_zeta_estimate():
    assert theory.zeta_estimate(0.7) == pytest.approx(1.0, rel=1e-14), "eq. 13 at H = 0.7"


def test_crossover_force_of_figure_3():
    """Eq. 17 with R = 0.5, H = 0.7, h = 9e-3, L = 1, ζ = 1: F_tr/(E*L²) = 8.0e-5 (Fig. 3)."""
    assert theory.crossover_force(0.5, 0.7, 9e-3, 1.0, 1.0, 1.0) == pytest.approx(8.0e-5, rel=1e-2)


@pytest.mark.parametrize("force", [1e-6, 1e-3, 2.0])
def test_eq7_with_parabola_is_hertz(force):
    """Eq. 7 with H = 2 and Q3D = 1/(2R) is eq. 9."""
    radius, e_star = 0.37, 2.5
    assert theory.profile_stiffness(force, 1 / (2 * radius), 2.0, e_star) == \
        pytest.approx(theory.hertz_stiffness(force, radius, e_star), rel=1e-13)


@pytest.mark.parametrize("hurst", HURSTS)
def test_eq7_with_eq14_is_eq11(hurst):
    """Eq. 7 with Q3D from eq. 14 equals eq. 11 for any H."""
    h, length, e_star, zeta = 4e-3, 1.7, 2.0, 1.3
    q3d = theory.profile_prefactor(hurst, h, length, zeta)
    forces = np.geomspace(1e-8, 1e-1, 5)
    assert np.allclose(theory.profile_stiffness(forces, q3d, hurst, e_star),
                       theory.fractal_stiffness(forces, hurst, h, length, e_star, zeta),
                       rtol=1e-12), f"eq. 7 + eq. 14 != eq. 11 at H = {hurst}"


@pytest.mark.parametrize("hurst", HURSTS)
def test_terms_equal_at_crossover(hurst):
    """At F_tr the Hertz term and the roughness term of eq. 16 are equal."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 2.0, 1.1
    f_tr = theory.crossover_force(radius, hurst, h, length, e_star, zeta)
    k_hertz = theory.hertz_stiffness(f_tr, radius, e_star)
    k_fractal = theory.fractal_stiffness(f_tr, hurst, h, length, e_star, zeta)
    assert k_hertz == pytest.approx(k_fractal, rel=1e-10), "asymptotes do not meet at F_tr"


@pytest.mark.parametrize("hurst", HURSTS)
def test_eq16_force_at_crossover_is_twice(hurst):
    """Eq. 16 evaluated at the common stiffness of the asymptotes gives 2 F_tr."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 2.0, 1.1
    f_tr = theory.crossover_force(radius, hurst, h, length, e_star, zeta)
    k = theory.hertz_stiffness(f_tr, radius, e_star)
    assert theory.force_from_stiffness(k, radius, hurst, h, length, e_star, zeta) == \
        pytest.approx(2 * f_tr, rel=1e-10), "eq. 16 at the crossover"


def test_eq18_limit_for_small_hurst():
    """For H → 0, F_tr/(E* h^1.5 R^0.5) → √6/ζ^1.5 with ζ = 1.7: λ ≈ 1.1 (eq. 18)."""
    radius, h, e_star = 0.5, 9e-3, 1.0
    hurst = 1e-9
    f_tr = theory.crossover_force(radius, hurst, h, 1.0, e_star, theory.zeta_estimate(hurst))
    assert f_tr / (e_star * h**1.5 * radius**0.5) == pytest.approx(math.sqrt(6) / 1.7**1.5,
                                                                   rel=1e-6)
    assert math.sqrt(6) / 1.7**1.5 == pytest.approx(1.1, abs=0.01), "λ of eq. 18"


@pytest.mark.parametrize("radius", [0.5, math.inf])
def test_stiffness_from_force_inverts_eq16(radius):
    hurst, h, length, e_star, zeta = 0.7, 9e-3, 1.0, 1.0, 1.0
    k = np.geomspace(1e-3, 1.0, 7)
    forces = theory.force_from_stiffness(k, radius, hurst, h, length, e_star, zeta)
    assert np.allclose(theory.stiffness_from_force(forces, radius, hurst, h, length, e_star, zeta),
                       k, rtol=1e-12), "eq. 16 not inverted"


@pytest.mark.parametrize("hurst", HURSTS)
def test_crossover_slope_is_local_slope_of_eq16(hurst):
    """d ln k/d ln F of eq. 16 where its terms are equal (F = 2 F_tr) is 2/(H+4)
    (central difference, step 1e-5: error O(1e-10))."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 1.0, 1.0
    f_tr = theory.crossover_force(radius, hurst, h, length, e_star, zeta)
    f = 2 * f_tr * np.exp([-1e-5, 1e-5])
    k = theory.stiffness_from_force(f, radius, hurst, h, length, e_star, zeta)
    slope = np.diff(np.log(k))[0] / 2e-5
    assert slope == pytest.approx(theory.crossover_slope(hurst), rel=1e-6), "slope at F_tr"
