"""The power-mean superposition of eqs. 10 and 12 (models.superposition) against its closed-form limits."""
import numpy as np
import pytest

from roughcontact.models import paper, superposition

SPHERE = dict(radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
FORCES = np.logspace(-7, -2, 11)


def test_power_one_is_eq16():
    k = superposition.stiffness_from_force(FORCES, power=1.0, **SPHERE)
    assert k == pytest.approx(paper.stiffness_from_force(FORCES, **SPHERE), rel=1e-12), "p = 1 against eq. 16"


def test_large_power_is_the_lower_asymptote():
    # p = 200: F exceeds max(F_body, F_rough) by a factor of at most 2^(1/200) (0.35 %); k(F) has a local
    # slope of at most 1/(H+1) = 0.59, so k lies within 0.59 x 0.35 % = 0.21 % of min(k_9, k_11)
    k = superposition.stiffness_from_force(FORCES, power=200.0, **SPHERE)
    lower = np.minimum(paper.hertz_stiffness(FORCES, radius=0.5, e_star=1.0),
                       paper.fractal_stiffness(FORCES, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0))
    assert k == pytest.approx(lower, rel=2.1e-3), "p -> inf against min(k_9, k_11)"


def test_crossover_force_is_two_to_one_over_p_times_either_term():
    # at the stiffness where the terms are equal, F = 2^(1/p) F_body (exact)
    f_tr = paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    k_tr = paper.hertz_stiffness(f_tr, radius=0.5, e_star=1.0)
    force = superposition.force_from_stiffness(k_tr, power=3.0, **SPHERE)
    assert force == pytest.approx(2 ** (1 / 3) * f_tr, rel=1e-12), "F at the crossover stiffness, p = 3"


def test_inversion_round_trip():
    k = superposition.stiffness_from_force(FORCES, power=2.5, **SPHERE)
    back = superposition.force_from_stiffness(k, power=2.5, **SPHERE)
    assert back == pytest.approx(FORCES, rel=1e-12), "F(k(F)) = F"


def test_flat_is_eq11():
    flat = dict(SPHERE, radius=np.inf)
    k = superposition.stiffness_from_force(FORCES, power=2.0, **flat)
    assert k == pytest.approx(paper.fractal_stiffness(FORCES, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0,
                                                      zeta=1.0), rel=1e-12), "R = inf against eq. 11"


def test_power_below_one_rejected():
    with pytest.raises(ValueError, match="power must be >= 1"):
        superposition.force_from_stiffness(1e-2, power=0.5, **SPHERE)
