"""The effective modulus of two bodies against its closed form (Johnson 1985, eq. 4.22)."""
from __future__ import annotations

import math

import pytest

from roughcontact.models import effective_modulus


def test_steel_on_steel():
    """E = 210 GPa, ν = 0.3 on both: E* = E/(2(1 − ν²)) = 210/1.82 = 115.3846... GPa."""
    assert effective_modulus(210.0, 0.3, 210.0, 0.3) == pytest.approx(210.0 / 1.82, rel=1e-14), "steel on steel"


def test_rigid_counter_body_is_the_default():
    assert effective_modulus(3.0, 0.5) == pytest.approx(4.0, rel=1e-14), "E/(1 - nu^2) with a rigid counter-body"


def test_symmetric_in_the_bodies():
    a = effective_modulus(70.0, 0.33, 210.0, 0.29)
    assert a == pytest.approx(effective_modulus(210.0, 0.29, 70.0, 0.33), rel=1e-15), "order of the bodies"


def test_rubber_on_glass():
    """Rubber (E = 10 MPa, ν = 0.5) on glass (70 GPa, ν = 0.22): within 1e-3 of the rubber alone."""
    e_star = effective_modulus(10e6, 0.5, 70e9, 0.22)
    assert e_star == pytest.approx(10e6 / 0.75, rel=1e-3), f"E* = {e_star:g} Pa"


def test_two_rigid_bodies():
    assert math.isinf(effective_modulus(math.inf, 0.3, math.inf, 0.3)), "two rigid bodies"


@pytest.mark.parametrize("kwargs, name", [({"e1": 0.0, "nu1": 0.3}, "e1"), ({"e1": 1.0, "nu1": 0.6}, "nu1"),
                                          ({"e1": 1.0, "nu1": -1.0}, "nu1"), ({"e1": 1.0, "nu1": 0.3, "e2": -2.0}, "e2"),
                                          ({"e1": 1.0, "nu1": 0.3, "nu2": float("nan")}, "nu2"),
                                          ({"e1": float("nan"), "nu1": 0.3}, "e1")])
def test_bad_values_name_themselves(kwargs, name):
    with pytest.raises(ValueError, match=name):
        effective_modulus(**kwargs)
