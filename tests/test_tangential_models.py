"""The closed forms of :mod:`roughcontact.models.tangential` against each other and the MDR."""
from __future__ import annotations

import math

import numpy as np
import pytest

from roughcontact.models import mdr
from roughcontact.models import tangential as closed


@pytest.mark.parametrize("nu, ratio", [(0.0, 1.0), (0.5, 2 / 3), (0.3, 1.4 / 1.7)])
def test_stiffness_ratio(nu, ratio):
    """2(1 − ν)/(2 − ν) at three values worked by hand."""
    assert closed.stiffness_ratio(nu) == pytest.approx(ratio, rel=1e-15)


def test_mindlin_over_hertz_is_the_ratio():
    """8Ga/(2 − ν) over 2E*a with G = E*(1 − ν)/2 (L = 3, E* = 210)."""
    a, e_star, nu = 0.7, 210.0, 0.27
    assert closed.mindlin_stiffness(a, e_star=e_star, poisson=nu) / (2 * e_star * a) == pytest.approx(
        closed.stiffness_ratio(nu), rel=1e-14)


def test_displacement_integrates_the_tangent_stiffness():
    """dδ_x/dQ = 1/k_t(Q) on Hertz's sphere: the Cattaneo–Mindlin displacement and stiffness are one
    curve (central differences of step 1e-5 in Q/μP: error ~1e-10 relative; bound 1e-7)."""
    e_star, nu, friction, radius, force = 3.0, 0.3, 0.4, 2.0, 0.05
    a = (3 * force * radius / (4 * e_star)) ** (1 / 3)
    f, h = 0.4, 1e-5
    kwargs = dict(normal_force=force, friction=friction, contact_radius=a, e_star=e_star, poisson=nu)
    slope = (closed.cattaneo_displacement(f + h, **kwargs) - closed.cattaneo_displacement(f - h, **kwargs)) \
        / (2 * h * friction * force)
    k = closed.cattaneo_stiffness(f, contact_radius=a, e_star=e_star, poisson=nu)
    assert slope * k == pytest.approx(1.0, rel=1e-7)


def test_gross_slip_displacement():
    """δ_x at Q = μP is 3μP(2 − ν)/(16Ga) (Johnson 1985, §7.2)."""
    e_star, nu = 2.0, 0.25
    g = e_star * (1 - nu) / 2
    value = closed.cattaneo_displacement(1.0, normal_force=1.5, friction=0.3, contact_radius=0.2,
                                         e_star=e_star, poisson=nu)
    assert value == pytest.approx(3 * 0.3 * 1.5 * (2 - nu) / (16 * g * 0.2), rel=1e-14)


def test_stick_radius_endpoints():
    """c = a at Q = 0 and c = 0 at Q = μP."""
    assert closed.stick_radius(2.0, [0.0, 1.0]).tolist() == [2.0, 0.0]


def test_mdr_sphere_is_the_ratio_times_k_n():
    """The MDR rough sphere's k_t is its k_n times the ratio (same seeded profiles)."""
    kwargs = dict(radius=1.0, hurst=0.7, h_rms=1e-2, length=1.0, n=256, e_star=1.0, realizations=4, seed=3)
    normal = mdr.sphere_stiffness([1e-4, 1e-3], **kwargs)
    tangential = closed.mdr_sphere_stiffness([1e-4, 1e-3], poisson=0.3, **kwargs)
    assert tangential.stiffness == pytest.approx(normal.stiffness * closed.stiffness_ratio(0.3), rel=1e-14)


@pytest.mark.parametrize("bad", [-1.0, 0.51, math.nan])
def test_bad_poisson(bad):
    with pytest.raises(ValueError, match="poisson"):
        closed.stiffness_ratio(bad)


@pytest.mark.parametrize("bad", [-0.1, 1.1, math.nan])
def test_bad_load_ratio(bad):
    with pytest.raises(ValueError, match="load_ratio"):
        closed.stick_radius(1.0, np.array([bad]))
