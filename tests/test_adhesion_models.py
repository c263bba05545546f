"""Closed forms of the adhesive sphere (roughcontact.models.adhesion) against their defining
properties: JKR's pull-offs at dF/da = 0 and dd/da = 0, Hertz as w -> 0, Maugis-Dugdale between
DMT (lambda -> 0) and JKR (lambda -> infinity), and the units' scaling."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from roughcontact.models import adhesion

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
