"""The analytic model (eqs. 7–18) against its own closed-form special cases."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from roughcontact.models import paper

HURSTS = [0.1, 0.3, 0.7, 1.0, 1.5, 1.9]


def test_kappa_at_one():
    assert paper.kappa(1.0) == pytest.approx(math.pi / 2, rel=1e-14), "κ(1) = π/2"


def test_kappa_at_two():
    assert paper.kappa(2.0) == pytest.approx(2.0, rel=1e-14), "κ(2) = 2"


@pytest.mark.parametrize("hurst", HURSTS)
def test_kappa_equals_its_integral(hurst):
    """Eq. 8: the gamma-function form equals H ∫₀¹ ξ^(H−1)/√(1−ξ²) dξ."""
    integral = quad(lambda xi: xi ** (hurst - 1) / math.sqrt(1 - xi**2), 0, 1, limit=200)[0]
    assert paper.kappa(hurst) == pytest.approx(hurst * integral, rel=1e-8), f"κ({hurst})"


def test_zeta_estimate():
    assert paper.zeta_estimate(0.7) == pytest.approx(1.0, rel=1e-14), "eq. 13 at H = 0.7"


def test_crossover_force_of_figure_3():
    """Eq. 17 with R = 0.5, H = 0.7, h = 9e-3, L = 1, ζ = 1: F_tr/(E*L²) = 8.0e-5 (Fig. 3)."""
    assert paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0) == pytest.approx(8.0e-5, rel=1e-2)


@pytest.mark.parametrize("force", [1e-6, 1e-3, 2.0])
def test_eq7_with_parabola_is_hertz(force):
    """Eq. 7 with H = 2 and Q3D = 1/(2R) is eq. 9."""
    radius, e_star = 0.37, 2.5
    assert paper.profile_stiffness(force, q3d=1 / (2 * radius), hurst=2.0, e_star=e_star) == \
        pytest.approx(paper.hertz_stiffness(force, radius=radius, e_star=e_star), rel=1e-13)


@pytest.mark.parametrize("hurst", HURSTS)
def test_eq7_with_eq14_is_eq11(hurst):
    """Eq. 7 with Q3D from eq. 14 equals eq. 11 for any H."""
    h, length, e_star, zeta = 4e-3, 1.7, 2.0, 1.3
    q3d = paper.profile_prefactor(hurst, h_rms=h, length=length, zeta=zeta)
    forces = np.geomspace(1e-8, 1e-1, 5)
    assert np.allclose(paper.profile_stiffness(forces, q3d=q3d, hurst=hurst, e_star=e_star),
                       paper.fractal_stiffness(forces, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta),
                       rtol=1e-12), f"eq. 7 + eq. 14 != eq. 11 at H = {hurst}"


@pytest.mark.parametrize("hurst", HURSTS)
def test_terms_equal_at_crossover(hurst):
    """At F_tr the Hertz term and the roughness term of eq. 16 are equal."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 2.0, 1.1
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    k_hertz = paper.hertz_stiffness(f_tr, radius=radius, e_star=e_star)
    k_fractal = paper.fractal_stiffness(f_tr, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    assert k_hertz == pytest.approx(k_fractal, rel=1e-10), "asymptotes do not meet at F_tr"


@pytest.mark.parametrize("hurst", HURSTS)
def test_eq16_force_at_crossover_is_twice(hurst):
    """Eq. 16 evaluated at the common stiffness of the asymptotes gives 2 F_tr."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 2.0, 1.1
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    k = paper.hertz_stiffness(f_tr, radius=radius, e_star=e_star)
    assert paper.force_from_stiffness(k, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta) == \
        pytest.approx(2 * f_tr, rel=1e-10), "eq. 16 at the crossover"


def test_eq18_limit_for_small_hurst():
    """For H → 0, F_tr/(E* h^1.5 R^0.5) → √6/ζ^1.5 with ζ = 1.7: λ ≈ 1.1 (eq. 18)."""
    radius, h, e_star = 0.5, 9e-3, 1.0
    hurst = 1e-9
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=1.0, e_star=e_star, zeta=paper.zeta_estimate(hurst))
    assert f_tr / (e_star * h**1.5 * radius**0.5) == pytest.approx(math.sqrt(6) / 1.7**1.5,
                                                                   rel=1e-6)
    assert math.sqrt(6) / 1.7**1.5 == pytest.approx(1.1, abs=0.01), "λ of eq. 18"


@pytest.mark.parametrize("radius", [0.5, math.inf])
def test_stiffness_from_force_inverts_eq16(radius):
    hurst, h, length, e_star, zeta = 0.7, 9e-3, 1.0, 1.0, 1.0
    k = np.geomspace(1e-3, 1.0, 7)
    forces = paper.force_from_stiffness(k, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    assert np.allclose(paper.stiffness_from_force(forces, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta),
                       k, rtol=1e-12), "eq. 16 not inverted"


@pytest.mark.parametrize("hurst", HURSTS)
def test_crossover_slope_is_local_slope_of_eq16(hurst):
    """d ln k/d ln F of eq. 16 where its terms are equal (F = 2 F_tr) is 2/(H+4)
    (central difference, step 1e-5: error O(1e-10))."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 1.0, 1.0
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    f = 2 * f_tr * np.exp([-1e-5, 1e-5])
    k = paper.stiffness_from_force(f, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    slope = np.diff(np.log(k))[0] / 2e-5
    assert slope == pytest.approx(paper.crossover_slope(hurst), rel=1e-6), "slope at F_tr"


# --- smooth bodies of revolution z = (R/m)(r/R)^m --------------------------------------------

EXPONENTS = [0.5, 1.0, 2.0, 3.0, 4.0]


def test_body_prefactor():
    assert paper.body_prefactor(0.37, exponent=2.0) == pytest.approx(1 / (2 * 0.37), rel=1e-15), \
        "Q(m=2) = 1/(2R)"
    assert paper.body_prefactor(0.37, exponent=1.0) == 1.0, "Q(m=1) = 1"


@pytest.mark.parametrize("force", [1e-6, 1e-3, 2.0])
def test_body_stiffness_at_two_is_eq9(force):
    """m = 2: k = E* (6 R F/E*)^(1/3) (eq. 9), to round-off."""
    radius, e_star = 0.37, 2.5
    assert paper.body_stiffness(force, radius=radius, e_star=e_star, exponent=2.0) == \
        pytest.approx(e_star * (6 * radius * force / e_star) ** (1 / 3), rel=1e-14), "eq. 9"
    assert paper.body_stiffness(force, radius=radius, e_star=e_star) == \
        paper.hertz_stiffness(force, radius=radius, e_star=e_star), "body_stiffness(m=2) != hertz_stiffness"


@pytest.mark.parametrize("exponent", EXPONENTS)
def test_body_stiffness_is_eq7(exponent):
    """k = 2 E* ((m+1) F/(2 Q E* m κ(m)))^(1/(m+1)) with Q = R^(1−m)/m (eq. 7, H → m)."""
    radius, e_star = 0.37, 2.5
    forces = np.geomspace(1e-8, 1.0, 5)
    q = radius ** (1 - exponent) / exponent
    assert np.allclose(paper.body_stiffness(forces, radius=radius, e_star=e_star, exponent=exponent),
                       paper.profile_stiffness(forces, q3d=q, hurst=exponent, e_star=e_star), rtol=1e-12), \
        f"body stiffness != eq. 7 at m = {exponent}"


def test_cone_closed_forms():
    """Cone z = r (m = 1, κ(1) = π/2, Q = 1): d = π a/2, F = π E* a²/2, k = 2 E* a."""
    a, e_star = 0.12, 2.5
    cone = paper.body_indentation(a, radius=0.8, e_star=e_star, exponent=1.0)
    assert cone.depth == pytest.approx(math.pi * a / 2, rel=1e-14), "cone depth"
    assert cone.force == pytest.approx(math.pi * e_star * a**2 / 2, rel=1e-14), "cone force"
    assert cone.stiffness == pytest.approx(2 * e_star * a, rel=1e-15), "cone stiffness"


def test_hertz_closed_forms():
    """m = 2 (κ(2) = 2, Q = 1/(2R)): d = a²/R, F = 4 E* a³/(3R)."""
    a, radius, e_star = 0.12, 0.5, 2.5
    sphere = paper.body_indentation(a, radius=radius, e_star=e_star)
    assert sphere.depth == pytest.approx(a**2 / radius, rel=1e-14), "Hertz depth"
    assert sphere.force == pytest.approx(4 * e_star * a**3 / (3 * radius), rel=1e-14), \
        "Hertz force"


def test_quartic_closed_forms():
    """m = 4 (κ(4) = 8/3, Q = 1/(4R³)): d = 2a⁴/(3R³), F = 16 E* a⁵/(15 R³)."""
    a, radius, e_star = 0.12, 0.5, 2.5
    body = paper.body_indentation(a, radius=radius, e_star=e_star, exponent=4.0)
    assert body.depth == pytest.approx(2 * a**4 / (3 * radius**3), rel=1e-14), "m = 4 depth"
    assert body.force == pytest.approx(16 * e_star * a**5 / (15 * radius**3), rel=1e-14), \
        "m = 4 force"


@pytest.mark.parametrize("hurst", HURSTS + [4.0])
def test_profile_indentation_is_eq7_and_dF_dd_is_k(hurst):
    """Eliminating a gives eq. 7, and dF/dd = k = 2 E* a (central differences in a,
    step 1e-5 relative: error O(1e-10))."""
    q3d, e_star = 0.8, 1.7
    a = np.array([0.05, 0.2]) * np.exp([[-1e-5], [0.0], [1e-5]])
    ind = paper.profile_indentation(a, q3d=q3d, hurst=hurst, e_star=e_star)
    assert np.allclose(paper.profile_stiffness(ind.force[1], q3d=q3d, hurst=hurst, e_star=e_star),
                       ind.stiffness[1], rtol=1e-12), "k(F) is not eq. 7"
    slope = (ind.force[2] - ind.force[0]) / (ind.depth[2] - ind.depth[0])
    assert np.allclose(slope, ind.stiffness[1], rtol=1e-8), "dF/dd != 2 E* a"


@pytest.mark.parametrize("exponent", EXPONENTS)
def test_eq16_body_term_is_body_force(exponent):
    """F(k) − F_rough(k) of the generalised eq. 16 is the body's force at a = k/(2E*)."""
    radius, hurst, h, length, e_star, zeta = 0.5, 0.7, 9e-3, 1.0, 2.0, 1.1
    k = np.geomspace(1e-3, 1.0, 5)
    total = paper.force_from_stiffness(k, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta,
                                        exponent=exponent)
    rough = paper.force_from_stiffness(k, radius=math.inf, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    body = paper.body_indentation(k / (2 * e_star), radius=radius, e_star=e_star, exponent=exponent).force
    assert np.allclose(total - rough, body, rtol=1e-10), f"body term at m = {exponent}"


def test_eq16_default_is_paper():
    """Eq. 16 with the defaults: E* [(k/E*)³/(6R) + L h (k/(ζ E* L))^(H+1)]."""
    radius, hurst, h, length, e_star, zeta = 0.5, 0.7, 9e-3, 1.3, 2.0, 1.1
    k = np.geomspace(1e-3, 1.0, 5)
    expected = e_star * ((k / e_star) ** 3 / (6 * radius)
                         + length * h * (k / (zeta * e_star * length)) ** (hurst + 1))
    assert np.allclose(paper.force_from_stiffness(k, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta),
                       expected, rtol=1e-14), "eq. 16"


@pytest.mark.parametrize("exponent", EXPONENTS)
def test_stiffness_from_force_inverts_generalised_eq16(exponent):
    radius, hurst, h, length, e_star, zeta = 0.5, 0.7, 9e-3, 1.0, 1.0, 1.0
    k = np.geomspace(1e-3, 1.0, 7)
    forces = paper.force_from_stiffness(k, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta,
                                         exponent=exponent)
    assert np.allclose(paper.stiffness_from_force(forces, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star,
                                                   zeta=zeta, exponent=exponent),
                       k, rtol=1e-12), f"generalised eq. 16 not inverted at m = {exponent}"


@pytest.mark.parametrize("hurst", HURSTS)
def test_crossover_force_at_two_is_eq17(hurst):
    """F_tr/E* = [ζ^(3H+3) h^(−3) L^(3H) (6R)^(−H−1)]^(1/(H−2)) (eq. 17), to round-off."""
    radius, h, length, e_star, zeta = 0.37, 9e-3, 1.3, 2.0, 1.1
    expected = e_star * (zeta ** (3 * hurst + 3) * h**-3 * length ** (3 * hurst)
                         * (6 * radius) ** (-hurst - 1)) ** (1 / (hurst - 2))
    assert paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta, exponent=2.0) == \
        pytest.approx(expected, rel=1e-12), "eq. 17"


@pytest.mark.parametrize("exponent, hurst",
                         [(m, hurst) for m in (1.0, 3.0, 4.0) for hurst in HURSTS if hurst != m])
def test_generalised_crossover(exponent, hurst):
    """At F_tr the body's and the roughness asymptotes give the same k, and the
    generalised eq. 16 there gives 2 F_tr."""
    radius, h, length, e_star, zeta = 0.5, 9e-3, 1.0, 2.0, 1.1
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta, exponent=exponent)
    k_body = paper.body_stiffness(f_tr, radius=radius, e_star=e_star, exponent=exponent)
    k_rough = paper.fractal_stiffness(f_tr, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta)
    assert k_body == pytest.approx(k_rough, rel=1e-10), "asymptotes do not meet at F_tr"
    assert paper.force_from_stiffness(k_body, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta,
                                       exponent=exponent) == pytest.approx(2 * f_tr, rel=1e-10), \
        "generalised eq. 16 at the crossover"


def test_crossover_needs_distinct_exponents():
    with pytest.raises(ValueError, match="exponent must differ from hurst"):
        paper.crossover_force(0.5, hurst=1.0, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0, exponent=1.0)


@pytest.mark.parametrize("exponent", [1.0, 4.0])
def test_generalised_crossover_slope(exponent):
    """d ln k/d ln F of the generalised eq. 16 at F = 2 F_tr is 2/(H+m+2)
    (central difference, step 1e-5: error O(1e-10))."""
    radius, hurst, h, length, e_star, zeta = 0.5, 0.7, 9e-3, 1.0, 1.0, 1.0
    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta, exponent=exponent)
    f = 2 * f_tr * np.exp([-1e-5, 1e-5])
    k = paper.stiffness_from_force(f, radius=radius, hurst=hurst, h_rms=h, length=length, e_star=e_star, zeta=zeta, exponent=exponent)
    slope = np.diff(np.log(k))[0] / 2e-5
    assert slope == pytest.approx(2 / (hurst + exponent + 2), rel=1e-6), "slope at 2 F_tr"
    assert paper.crossover_slope(hurst, exponent=exponent) == \
        pytest.approx(2 / (hurst + exponent + 2), rel=1e-15), "crossover_slope"
