"""Closed forms of the adhesive sphere (roughcontact.models.adhesion) against their defining
properties: JKR's pull-offs at dF/da = 0 and dd/da = 0, Hertz as w -> 0, Maugis-Dugdale between
DMT (lambda -> 0) and JKR (lambda -> infinity), and the units' scaling. Rough surfaces
(roughcontact.models.rough_adhesion): Fuller & Tabor's pull-off from JKR's (theta -> 0) falling
with theta, its integral by another quadrature, Johnson's parameter, Pastewka & Robbins' criterion
by hand."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import trapezoid
from scipy.optimize import minimize_scalar

from roughcontact.models import adhesion, rough_adhesion

#: a non-unit setting: R = 2.5, E* = 3.0, w = 0.04 (consistent units)
R, E, W = 2.5, 3.0, 0.04


def _jkr(a, **kw):
    return adhesion.jkr(a, **{"radius": R, "e_star": E, "work_of_adhesion": W, **kw})


def test_jkr_load_controlled_pull_off_is_the_least_force():
    """min_a F(a) by bounded minimisation (xatol 1e-12 in ln a) equals -3/2 pi w R."""
    least = minimize_scalar(lambda t: float(_jkr(math.exp(t)).force), bounds=(-10, 2), method="bounded",
                            options={"xatol": 1e-12}).fun
    assert least == pytest.approx(-1.5 * math.pi * W * R, rel=1e-10), f"least JKR force {least}"


def test_jkr_pull_off_radius_is_where_the_force_is_least():
    force, a = adhesion.jkr_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    assert float(_jkr(a).force) == pytest.approx(force, rel=1e-13), "F at the pull-off radius"


def test_jkr_fixed_grips_instability():
    """Where dd/da = 0 the force is -5/6 pi w R (Maugis 1992); the stiffness passes a pole there and
    is negative above it (the branch stable under displacement control only)."""
    force, a, _ = adhesion.jkr_fixed_grips_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    assert force == pytest.approx(-5 / 6 * math.pi * W * R, rel=1e-12), f"fixed-grips pull-off {force}"
    above = _jkr(a * (1 + 1e-6)).stiffness
    assert above < 0, f"stiffness {above} just above the instability"


def test_jkr_stiffness_is_the_derivative_along_the_branch():
    """k = dF/dd against central differences in a (step 1e-6 a: error ~1e-11 relative)."""
    a = np.array([0.05, 0.1, 0.3])
    h = 1e-6 * a
    hi, lo = _jkr(a + h), _jkr(a - h)
    numeric = (hi.force - lo.force) / (hi.depth - lo.depth)
    np.testing.assert_allclose(_jkr(a).stiffness, numeric, rtol=1e-8, err_msg="dF/dd")


def test_jkr_without_adhesion_is_hertz():
    """w = 1e-20: F = 4E*a^3/(3R) and k = 2E*a to 1e-5 (the adhesive terms scale as sqrt(w): 5e-8 here)."""
    a = np.array([0.05, 0.2])
    state = adhesion.jkr(a, radius=R, e_star=E, work_of_adhesion=1e-20)
    np.testing.assert_allclose(state.force, 4 * E * a**3 / (3 * R), rtol=1e-5, err_msg="Hertz force")
    np.testing.assert_allclose(state.stiffness, 2 * E * a, rtol=1e-5, err_msg="Hertz stiffness")


def test_jkr_in_maugis_units():
    """F/(pi w R) = a_bar^3 - sqrt(6 a_bar^3) with a_bar = a (K/(pi w R^2))^(1/3), K = 4E*/3."""
    a_bar = np.array([0.5, 1.0, 2.0])
    a = a_bar * (math.pi * W * R**2 / (4 * E / 3)) ** (1 / 3)
    np.testing.assert_allclose(_jkr(a).force / (math.pi * W * R), a_bar**3 - np.sqrt(6 * a_bar**3), rtol=1e-12,
                               err_msg="JKR in Maugis' units")


@pytest.mark.parametrize("a_bar", [0.5, 1.0, 1.5, 2.0])
def test_maugis_dugdale_tends_to_jkr(a_bar):
    """lambda = 100: the cohesive zone is a hundredth of a: P and delta within 1e-3 of JKR."""
    state = adhesion.maugis_dugdale(a_bar, 100.0)
    jkr_force = a_bar**3 - math.sqrt(6 * a_bar**3)
    assert state.force == pytest.approx(jkr_force, abs=1e-3), f"P at a = {a_bar}"


@pytest.mark.parametrize("lam, expected, tol", [(1e-3, -2.0, 1e-4), (100.0, -1.5, 1e-4)])
def test_maugis_dugdale_pull_off_limits(lam, expected, tol):
    """DMT's -2 as lambda -> 0, JKR's -3/2 as lambda -> infinity (both O(lambda) / O(1/lambda))."""
    assert adhesion.maugis_dugdale_pull_off(lam).force == pytest.approx(expected, abs=tol), f"lambda = {lam}"


def test_maugis_dugdale_pull_off_falls_from_dmt_to_jkr():
    forces = [adhesion.maugis_dugdale_pull_off(lam).force for lam in (0.05, 0.2, 0.5, 1.0, 2.0, 5.0)]
    assert all(np.diff(forces) > 0), f"pull-off against lambda: {forces}"


def test_maugis_dugdale_cohesive_zone_starts_at_the_contact_edge():
    state = adhesion.maugis_dugdale(1.0, 1.0)
    assert state.m > 1.0, f"m = {state.m}"


def test_dmt_pull_off_and_zero_load_radius():
    assert adhesion.dmt_pull_off(radius=R, work_of_adhesion=W) == pytest.approx(-2 * math.pi * W * R, rel=1e-15)
    a0 = float(adhesion.dmt_contact_radius(0.0, radius=R, e_star=E, work_of_adhesion=W))
    assert a0 == pytest.approx((3 * R * 2 * math.pi * W * R / (4 * E)) ** (1 / 3), rel=1e-14), "DMT a(0)"


def test_maugis_parameter():
    sigma = 0.7
    expected = sigma * (9 * R / (2 * math.pi * W * E**2)) ** (1 / 3)
    got = adhesion.maugis_parameter(sigma, radius=R, e_star=E, work_of_adhesion=W)
    assert got == pytest.approx(expected, rel=1e-14), f"lambda = {got}"


def test_pull_off_scales_with_w_and_r():
    """F_c = -(3/2) pi w R whatever E*: doubling w and R quadruples it."""
    one, _ = adhesion.jkr_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    two, _ = adhesion.jkr_pull_off(radius=2 * R, e_star=7 * E, work_of_adhesion=2 * W)
    assert two == pytest.approx(4 * one, rel=1e-14), "pull-off scaling"


@pytest.mark.parametrize("kwargs, name", [({"radius": -1.0}, "radius"), ({"e_star": 0.0}, "e_star"),
                                          ({"work_of_adhesion": float("nan")}, "work_of_adhesion")])
def test_bad_arguments_name_themselves(kwargs, name):
    with pytest.raises(ValueError, match=name):
        adhesion.jkr(0.1, **{"radius": R, "e_star": E, "work_of_adhesion": W, **kwargs})


def test_maugis_cohesive_stress_inverts_the_parameter():
    """sigma_0(lambda) and lambda(sigma_0) are inverses (to rounding, 1e-14)."""
    sigma = adhesion.maugis_cohesive_stress(0.8, radius=R, e_star=E, work_of_adhesion=W)
    lam = adhesion.maugis_parameter(sigma, radius=R, e_star=E, work_of_adhesion=W)
    assert lam == pytest.approx(0.8, rel=1e-14), f"lambda(sigma_0(0.8)) = {lam}"


# --- rough surfaces (roughcontact.models.rough_adhesion) --------------------------------------------

def _delta_c(radius=R):
    return rough_adhesion.jkr_critical_approach(radius=radius, e_star=E, work_of_adhesion=W)


def test_jkr_critical_approach_is_the_fixed_grips_jump_off():
    """delta_c = (3/4)(pi^2 w^2 R/E*^2)^(1/3) is minus JKR's approach where dd/da = 0 (to rounding)."""
    _, _, depth = adhesion.jkr_fixed_grips_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    assert _delta_c() == pytest.approx(-depth, rel=1e-12), f"delta_c {_delta_c()} vs {-depth}"


def test_johnson_rough_sphere_parameter():
    """h_rms/delta_c by hand: delta_c = 0.75 (pi^2 0.04^2 2.5/9)^(1/3) = 0.1569656... for R = 2.5,
    E* = 3, w = 0.04; h_rms = 0.1 gives 0.637082... (to rounding)."""
    expected = 0.1 / (0.75 * (math.pi**2 * 0.04**2 * 2.5 / 9) ** (1 / 3))
    got = rough_adhesion.johnson_rough_sphere_parameter(0.1, radius=R, e_star=E, work_of_adhesion=W)
    assert got == pytest.approx(expected, rel=1e-14), f"h_rms/delta_c = {got}"


def test_fuller_tabor_height_ratio_is_johnsons_parameter_of_one_asperity():
    """sigma/delta_c = (4/3) pi^(-2/3) theta^(2/3) equals h_rms/delta_c with the asperity's radius."""
    sigma, beta = 0.02, 0.3
    theta = rough_adhesion.fuller_tabor_parameter(sigma=sigma, asperity_radius=beta, e_star=E, work_of_adhesion=W)
    johnson = rough_adhesion.johnson_rough_sphere_parameter(sigma, radius=beta, e_star=E, work_of_adhesion=W)
    assert rough_adhesion.fuller_tabor_pull_off(theta).height_ratio == pytest.approx(johnson, rel=1e-12), \
        f"theta = {theta}"


def test_fuller_tabor_theta_zero_comes_off_where_jkr_does():
    """theta = 0: F = -N (3/2) pi w beta at d = -(JKR's approach at a_c), 3^(-2/3) delta_c (to rounding)."""
    _, a_c = adhesion.jkr_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    depth = float(_jkr(a_c).depth)
    assert rough_adhesion.fuller_tabor_pull_off(0.0).separation * _delta_c() == pytest.approx(-depth, rel=1e-12)


def test_fuller_tabor_small_theta_is_one_jkr_asperity():
    """theta = 1e-6 (sigma = 6e-5 delta_c): the force at d = -delta(a = 1.3 a_c) is JKR's force there in
    units of (3/2) pi w R, within 1e-6 (the height spread's effect is ~ (sigma/delta_c)^2 ~ 4e-9)."""
    _, a_c = adhesion.jkr_pull_off(radius=R, e_star=E, work_of_adhesion=W)
    state = _jkr(1.3 * a_c)
    expected = float(state.force) / (1.5 * math.pi * W * R)
    got = float(rough_adhesion.fuller_tabor_force(-float(state.depth) / _delta_c(), 1e-6))
    assert got == pytest.approx(expected, abs=1e-6), f"F/(N P_c) = {got}, JKR {expected}"


def test_fuller_tabor_smooth_limit():
    """theta = 1e-3 (sigma/delta_c = 0.0062): the pull-off is JKR's, -1, within 1e-4 (the spread
    lowers it by ~ (sigma/delta_c)^2 |P''|/2 ~ 2e-5)."""
    force = rough_adhesion.fuller_tabor_pull_off(1e-3).force
    assert force == pytest.approx(-1.0, abs=1e-4), f"F/(N P_c) = {force}"


def test_fuller_tabor_integral_by_another_quadrature():
    """theta = 1, d = 0.2 delta_c (near the pull-off): the integral against the trapezoidal rule over
    20001 contact radii of models.adhesion.jkr (beta = 2, E* = 3, w = 0.05; second order: ~1e-8),
    within 1e-6."""
    beta, e_star, w, theta = 2.0, 3.0, 0.05, 1.0
    sigma = (theta * math.sqrt(beta) * w / e_star) ** (2 / 3)
    delta_c = rough_adhesion.jkr_critical_approach(radius=beta, e_star=e_star, work_of_adhesion=w)
    d = 0.2 * delta_c
    a_end = (math.pi * w * beta**2 / (8 * e_star)) ** (1 / 3)
    a = np.linspace(a_end, 3.0 * math.sqrt(beta * (d + 12 * sigma)) + a_end, 20001)
    state = adhesion.jkr(a, radius=beta, e_star=e_star, work_of_adhesion=w)
    z = d + state.depth
    density = np.exp(-0.5 * (z / sigma) ** 2) / (sigma * math.sqrt(2 * math.pi))
    expected = trapezoid(state.force * density, state.depth) / (1.5 * math.pi * w * beta)
    got = float(rough_adhesion.fuller_tabor_force(0.2, theta))
    assert got == pytest.approx(expected, abs=1e-6), f"F/(N P_c) = {got}, trapezoid {expected}"


def test_fuller_tabor_pull_off_falls_with_theta():
    """The pull-off weakens monotonically: theta = 0.1 ... 10 (computed -0.989, -0.733, -0.512,
    -0.362, -0.185, -0.036 at 0.1, 1, 2, 3, 5, 10)."""
    forces = [rough_adhesion.fuller_tabor_pull_off(theta).force for theta in (0.1, 1.0, 2.0, 3.0, 5.0, 10.0)]
    assert all(np.diff(forces) > 0), f"pull-off against theta: {forces}"


def test_fuller_tabor_pull_off_is_gone_by_theta_10():
    """Fuller & Tabor (Fig. 3): hardly any pull-off left by theta ~ 5-10. At theta = 10 less than 5 %
    of the smooth value (computed 3.6 %; 18.5 % at theta = 5)."""
    force = rough_adhesion.fuller_tabor_pull_off(10.0).force
    assert abs(force) < 0.05, f"F/(N P_c) = {force} at theta = 10"


def test_fuller_tabor_bad_theta_is_named():
    with pytest.raises(ValueError, match="theta"):
        rough_adhesion.fuller_tabor_pull_off(-1.0)


def test_maugis_work_of_adhesion_gives_its_length_unit():
    """l = (pi w R^2/K)^(1/3), K = 4E*/3: w = K l^3/(pi R^2) = (4 * 3/3) 0.008/(pi 0.25) = 0.04074 for
    l = 0.2, R = 0.5, E* = 3, and back to l."""
    w = adhesion.maugis_work_of_adhesion(0.2, radius=0.5, e_star=3.0)
    assert (math.pi * w * 0.5**2 / (4 * 3.0 / 3)) ** (1 / 3) == pytest.approx(0.2, rel=1e-14), f"w = {w}"


#: h' = 0.2, h'' = 0.5, dr = 0.01: h'^2/(h'' dr) = 8, whose 2/3 power is 4; g0 = (16/3) 0.08 = 0.42667
STICKY = {"rms_slope": 0.2, "rms_curvature": 0.5, "interaction_range": 0.01, "e_star": 1000.0}


@pytest.mark.parametrize("w, number", [(8.0, 0.5), (2.0, 2.0)])
def test_pastewka_robbins_number(w, number):
    """(h' E* dr/(2w)) 4 = (0.2 1000 0.01/(2w)) 4 = 4/w by hand: 0.5 for w = 8, 2 for w = 2 (to rounding)."""
    got = rough_adhesion.pastewka_robbins_stickiness(**STICKY, work_of_adhesion=w).number
    assert got == pytest.approx(number, rel=1e-13), f"number {got}"


@pytest.mark.parametrize("w, sticky", [(8.0, True), (2.0, False)])
def test_pastewka_robbins_sticky_below_one(w, sticky):
    assert rough_adhesion.pastewka_robbins_stickiness(**STICKY, work_of_adhesion=w).sticky is sticky, f"w = {w}"


def test_pastewka_robbins_range_ratio():
    """dr/g0 = 0.01/(16/3 * 0.04/0.5) = 0.0234375 exactly by hand: valid (< 0.1)."""
    got = rough_adhesion.pastewka_robbins_stickiness(**STICKY, work_of_adhesion=8.0)
    assert got.range_ratio == pytest.approx(0.0234375, rel=1e-14), f"dr/g0 = {got.range_ratio}"


@pytest.mark.parametrize("number, w", [(0.5, 8.0), (2.0, 2.0)])
def test_pastewka_robbins_work_of_adhesion_inverts_the_number(number, w):
    """w = 4/N by hand (the number is 4/w for STICKY): 8 at N = 0.5, 2 at N = 2."""
    got = rough_adhesion.pastewka_robbins_work_of_adhesion(number, **STICKY)
    assert got == pytest.approx(w, rel=1e-13), f"w {got}"


def test_pastewka_robbins_gap():
    """g0 = (16/3) 0.04/0.5 = 0.42667 by hand."""
    got = rough_adhesion.pastewka_robbins_gap(rms_slope=0.2, rms_curvature=0.5)
    assert got == pytest.approx(16 / 3 * 0.08, rel=1e-14), f"g0 = {got}"


def test_pastewka_robbins_bad_number_is_named():
    with pytest.raises(ValueError, match="number"):
        rough_adhesion.pastewka_robbins_work_of_adhesion(-1.0, **STICKY)


def test_pastewka_robbins_long_range_is_outside_validity():
    """dr = 0.05: dr/g0 = 0.1171875 > 0.1, outside the criterion's range of validity."""
    got = rough_adhesion.pastewka_robbins_stickiness(**{**STICKY, "interaction_range": 0.05}, work_of_adhesion=8.0)
    assert got.valid is False, f"dr/g0 = {got.range_ratio}"
