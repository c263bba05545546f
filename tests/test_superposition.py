"""The power-mean superposition of eqs. 10 and 12 (models.superposition) against its closed-form limits."""
import numpy as np
import pytest

from roughcontact.models import paper, superposition
from roughcontact.surfaces.spectra import self_affine_spectrum

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


def test_power_half_is_the_squared_sum_of_roots():
    """p = 1/2 (broader than eq. 16): F = (√F_body + √F_rough)² at every stiffness."""
    k = np.logspace(-3, -1, 7)
    body = k**3 / (6 * SPHERE["radius"])                                           # eq. 10, E* = 1
    rough = SPHERE["h_rms"] * (k / SPHERE["zeta"]) ** (SPHERE["hurst"] + 1)        # eq. 12, E* = L = 1
    assert superposition.force_from_stiffness(k, power=0.5, **SPHERE) == pytest.approx(
        (np.sqrt(body) + np.sqrt(rough)) ** 2, rel=1e-12), "p = 1/2 against its closed form"


def test_power_half_inverts():
    k = superposition.stiffness_from_force(FORCES, power=0.5, **SPHERE)
    assert superposition.force_from_stiffness(k, power=0.5, **SPHERE) == pytest.approx(FORCES, rel=1e-9), \
        "F(k(F)) = F at p = 1/2"


def test_hurst_constants_are_linear():
    constants = {"zeta_factor": (0.8, 0.1), "power": (1.0, 0.5)}
    assert superposition.hurst_constants(0.6, constants) == pytest.approx((0.86, 1.3), rel=1e-12), \
        "c = 0.8 + 0.1 H, p = 1 + 0.5 H at H = 0.6"


def test_power_not_positive_rejected():
    with pytest.raises(ValueError, match="power must be > 0"):
        superposition.force_from_stiffness(1e-2, power=0.0, **SPHERE)


def test_rough_force_with_its_own_reference_is_eq12():
    # h_a = h sqrt(SF/SF_ref) = h when the spectrum is the reference: eq. 12 to round-off
    reference = self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=129).rebinned(100)
    k = np.logspace(-3, 0, 7)
    scaled = superposition.rough_force(k, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0,
                                       spectrum=reference, reference=reference)
    plain = superposition.rough_force(k, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    assert scaled == pytest.approx(plain, rel=1e-12), "spectrum = reference against eq. 12"


def test_rolloff_raises_the_small_scale_roughness():
    # at equal h_rms a roll-off at L/4 puts more variance into the power law: SF(0.01)/SF_ref(0.01) > 1,
    # so the roughness carries more force at a small contact (a = 0.005) than eq. 12 says
    reference = self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=257).rebinned(100)
    rolled = self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=257, rolloff=0.25).rebinned(100)
    kwargs = dict(hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    ratio = superposition.rough_force(0.01, spectrum=rolled, reference=reference, **kwargs) / \
        superposition.rough_force(0.01, **kwargs)
    assert ratio > 1.5, f"F_rough with roll-off / eq. 12 at a = 0.005: {ratio}"


def test_spectrum_without_reference_rejected():
    reference = self_affine_spectrum(hurst=0.7, h_rms=9e-3, length=1.0, n=33)
    with pytest.raises(ValueError, match="both spectrum and reference"):
        superposition.rough_force(0.1, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0, spectrum=reference)


def test_contact_scale_h_is_eq16_where_its_power_is_one():
    """At H₁ = (1 − p₀)/p₁ the order of contact_scale_h's p-norm is 1: the model is eq. 16 with
    ζ = c(H₁)·ζ_law(H₁)."""
    from roughcontact.models.zeta_law import zeta_law

    (c0, c1), (p0, p1) = superposition.CALIBRATED_HURST["zeta_factor"], superposition.CALIBRATED_HURST["power"]
    hurst = (1.0 - p0) / p1
    sphere = dict(radius=0.5, hurst=hurst, h_rms=9e-3, length=1.0, e_star=1.0)
    k = superposition.hurst_calibrated_stiffness(FORCES, **sphere)
    eq16 = paper.stiffness_from_force(FORCES, zeta=(c0 + c1 * hurst) * float(zeta_law(hurst)), **sphere)
    assert k == pytest.approx(eq16, rel=1e-10), f"contact_scale_h at H = {hurst:.4f} against eq. 16"


#: the join with a tail: β and an order p above the tail's s = 2/(2 − 0.7) = 1.54
TAIL = dict(SPHERE, power=2.5, tail=2.0)


def test_tail_join_at_the_crossover_stiffness():
    """Where F_body = F_rough (x = 1): F = F_body (2 + β)^(1/p), exactly."""
    f_tr = paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    k_tr = paper.hertz_stiffness(f_tr, radius=0.5, e_star=1.0)
    force = superposition.force_from_stiffness(k_tr, **TAIL)
    assert force == pytest.approx(f_tr * 4.0 ** (1 / 2.5), rel=1e-12), "F at x = 1 against F_body (2 + β)^(1/p)"


def _tail_at(force):
    """1 − k/k_Hertz of the tail join and its first-order closed form β x^s/(p (m + 1)), x = F_rough/F_body
    at k_Hertz (module docstring of models.superposition)."""
    k = superposition.stiffness_from_force(force, **TAIL)
    k_hertz = paper.hertz_stiffness(force, radius=0.5, e_star=1.0)
    x = superposition.rough_force(k_hertz, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0) / force
    return 1 - k / k_hertz, 2.0 * x ** superposition.tail_exponent(0.7) / (2.5 * 3)


def test_tail_join_approaches_hertz_as_its_closed_form():
    """At 10⁶ F_tr, x = 2.5·10⁻³: the next orders are x^(p − s) = 3·10⁻³ and 1 − k/k_Hertz itself
    (10⁻⁴) relative to the first, so 1 % holds them."""
    f_tr = paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    deficit, first_order = _tail_at(np.array([1e6 * f_tr]))
    assert deficit == pytest.approx(first_order, rel=1e-2), "1 − k/k_Hertz against β x^s/(p (m + 1))"


def test_tail_join_falls_as_f_to_minus_two_thirds():
    """The interfacial compliance's law: 1 − k/k_Hertz ∝ F^(−m/(m + 1)) = F^(−2/3) for the paraboloid,
    whatever H and p (the slope between 10⁶ and 10⁷ F_tr, where the first order holds to 1 %)."""
    f_tr = paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    deficit, _ = _tail_at(np.array([1e6, 1e7]) * f_tr)
    slope = np.log(deficit[1] / deficit[0]) / np.log(10.0)
    assert slope == pytest.approx(-2 / 3, abs=5e-3), "log-slope of 1 − k/k_Hertz"


def test_tail_join_keeps_the_fractal_branch():
    """At 10⁻⁶ F_tr (x ≈ 4·10⁴) the join is eq. 11 to β x^(s − p)/(p (H + 1)) ≈ 2·10⁻⁵."""
    f_tr = paper.crossover_force(0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    force = np.array([1e-6 * f_tr])
    k = superposition.stiffness_from_force(force, **TAIL)
    fractal = paper.fractal_stiffness(force, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0, zeta=1.0)
    assert k == pytest.approx(fractal, rel=1e-4), "the tail join far below F_tr against eq. 11"


def test_zero_tail_is_the_p_norm():
    k = superposition.stiffness_from_force(FORCES, power=1.0, tail=0.0, **SPHERE)
    assert k == pytest.approx(paper.stiffness_from_force(FORCES, **SPHERE), rel=1e-12), "β = 0, p = 1 against eq. 16"


def test_negative_tail_rejected():
    with pytest.raises(ValueError, match="tail must be >= 0"):
        superposition.force_from_stiffness(0.1, power=2.0, tail=-1.0, **SPHERE)


def test_tail_join_without_roughness_force_is_the_body():
    """x = 0 (F_rough = 0, as below a cutoff): F = F_body exactly, ln x = −inf handled without a warning."""
    import warnings

    k = np.array([0.05, 0.1])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        force = superposition.force_from_stiffness(k, **dict(TAIL, h_rms=0.0))
    assert force == pytest.approx(k ** 3 / 3.0, rel=1e-12), "F_body = k³/(6R) E*⁻² with R = 0.5"
