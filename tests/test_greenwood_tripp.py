"""Greenwood & Tripp (1967) against its limits, ContactMechanics' reference solution and the
spectral moments of the generated surfaces."""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from roughcontact import surfaces
from roughcontact.models import asperities, greenwood_tripp
from roughcontact.models import paper


MU = 4.0


# --- F_n -------------------------------------------------------------------------------

@pytest.mark.parametrize("n", [0.5, 1.5, 2.5])
@pytest.mark.parametrize("h", [-25.0, -3.0, 0.0, 1.7, 6.0])
def test_gt_function_is_the_integral(n, h):
    """F_n(h) = ∫_h^∞ (x − h)^n φ(x) dx by adaptive quadrature (accuracy ~1e-12)."""
    expected, _ = quad(lambda x: (x - h) ** n * math.exp(-x * x / 2) / math.sqrt(2 * math.pi),
                       h, max(h, 0.0) + 40.0, limit=200, epsabs=0.0, epsrel=1e-13)
    assert float(greenwood_tripp.gt_function(h, n)) == pytest.approx(expected, rel=1e-10), \
        f"F_{n}({h}) differs from the integral"


@pytest.mark.parametrize("h", [-2.0, 0.5, 3.0])
def test_gt_function_antiderivative(h):
    """∫_h^∞ F_{3/2}(s) ds = F_{5/2}(h)/(5/2), the identity behind the light-load limit."""
    integral, _ = quad(lambda s: float(greenwood_tripp.gt_function(s, 1.5)), h, h + 40.0, limit=200,
                       epsabs=0.0, epsrel=1e-12)
    assert integral == pytest.approx(float(greenwood_tripp.gt_function(h, 2.5)) / 2.5, rel=1e-9), \
        "antiderivative identity"


# --- the elastic half-space ------------------------------------------------------------

@pytest.fixture(scope="module")
def hertz_displacement():
    """The influence matrix applied to Hertz's pressure (8/π)√(ρ_a² − ρ²), ρ_a = 3, ρ ≤ 5."""
    rho = np.linspace(0.0, 5.0, 100)
    radius = 3.0
    pressure = 8 / math.pi * np.sqrt(np.clip(radius**2 - rho**2, 0.0, None))
    return rho, radius, greenwood_tripp.influence_matrix(5.0, 100) @ pressure


def test_hertz_displacement_inside(hertz_displacement):
    """Inside the contact w(0) − w(ρ) = ρ² (it cancels the sphere). The square-root edge
    limits piecewise-linear pressure to O(h^(3/2)); for ρ ≤ 0.8 ρ_a the error is 1.7e-4 ρ_a²
    at 100 nodes (6e-5 at 200): bound 5e-4 ρ_a²."""
    rho, radius, w = hertz_displacement
    inside = rho <= 0.8 * radius
    error = np.abs(w[0] - w[inside] - rho[inside] ** 2).max()
    assert error <= 5e-4 * radius**2, f"Hertz displacement inside off by {error:.2e}"


def test_hertz_displacement_outside(hertz_displacement):
    """Outside, Johnson's (1985, ch. 3) displacement around a Hertzian pressure, in GT units:
    w = (2/π)[(2ρ_a² − ρ²) asin(ρ_a/ρ) + ρ_a √(ρ² − ρ_a²)]; measured error 1.9e-3 ρ_a²
    next to the edge at 100 nodes (7e-4 at 200): bound 4e-3 ρ_a²."""
    rho, radius, w = hertz_displacement
    outside = rho > radius
    expected = 2 / math.pi * ((2 * radius**2 - rho[outside] ** 2) * np.arcsin(radius / rho[outside])
                              + radius * np.sqrt(rho[outside] ** 2 - radius**2))
    error = np.abs(w[outside] - expected).max()
    assert error <= 4e-3 * radius**2, f"Hertz displacement outside off by {error:.2e}"


# --- against ContactMechanics ----------------------------------------------------------

@pytest.fixture(scope="module")
def versus_contact_mechanics():
    """ContactMechanics' fixed-point GT (100 points on ρ ≤ 5) and ours at d* = 0.5, μ = 4.

    Both discretizations are second order: the difference of the forces is 4.1e-3,
    1.0e-3 and 2.6e-4 at 50, 100 and 200 points, ContactMechanics' error at 100 points
    being ≈ 6e-4 and ours ≈ 4e-4 (against our 400-point value). Its fixed-point damping
    ``mix = 0.5`` (default 0.1) reaches the same solution within its ``tol = 1e-6`` on the
    pressure (forces equal to 1e-6), five times faster.
    """
    reference = pytest.importorskip("ContactMechanics.ReferenceSolutions.GreenwoodTripp")
    displacement, pressure, rho = reference.GreenwoodTripp(0.5, MU, mix=0.5)
    return greenwood_tripp.greenwood_tripp(0.5, MU), displacement, pressure, rho


def test_nodes_match_contact_mechanics(versus_contact_mechanics):
    ours, _, _, rho = versus_contact_mechanics
    assert np.allclose(ours.rho, rho, rtol=0, atol=1e-14), "different radial nodes"


def test_pressure_matches_contact_mechanics(versus_contact_mechanics):
    """Pressure profile within 5e-4 of its peak (measured 1.4e-4)."""
    ours, _, pressure, _ = versus_contact_mechanics
    difference = np.abs(ours.pressure - pressure).max() / pressure.max()
    assert difference <= 5e-4, f"pressure differs by {difference:.2e} of its peak"


def test_displacement_matches_contact_mechanics(versus_contact_mechanics):
    """w(ρ) − w(0) (ContactMechanics' output) within 1e-3 of its largest value (measured 4.4e-4)."""
    ours, displacement, _, _ = versus_contact_mechanics
    relative = ours.displacement - ours.displacement[0]
    difference = np.abs(relative - displacement).max() / np.abs(displacement).max()
    assert difference <= 1e-3, f"displacement differs by {difference:.2e}"


def test_force_matches_contact_mechanics(versus_contact_mechanics):
    """2π ∫ρ p dρ (trapezoidal for ContactMechanics' nodes) within 2e-3 (measured 1.0e-3)."""
    ours, _, pressure, rho = versus_contact_mechanics
    force = 2 * math.pi * np.trapezoid(rho * pressure, rho)
    assert ours.force_star == pytest.approx(force, rel=2e-3), "total force"


# --- limits ----------------------------------------------------------------------------

def light_load_force(depth_star, mu):
    """Rigid sphere on the summits: (2π/5) μ F_{5/2}(d*)."""
    return 2 * math.pi / 5 * mu * float(greenwood_tripp.gt_function(depth_star, 2.5))


#: Discretization error of the force at 100 points for d* = 1…2 (against 400 points: ≤ 1.2e-3).
LIGHT_LOAD_RTOL = 2e-3


@pytest.mark.parametrize("depth_star", [1.0, 2.0])
@pytest.mark.parametrize("mu", [1.0, MU])
def test_light_load_lower_bound(depth_star, mu):
    """The displacement is largest at the centre (w ≤ w(0)), so every separation is at most
    the rigid one and F ≥ (2π/5) μ F_{5/2}(d*)."""
    solution = greenwood_tripp.greenwood_tripp(depth_star, mu)
    assert solution.force_star >= light_load_force(depth_star, mu) * (1 - LIGHT_LOAD_RTOL), \
        "force below the rigid-sphere force"


@pytest.mark.parametrize("depth_star", [1.0, 2.0])
@pytest.mark.parametrize("mu", [1.0, MU])
def test_light_load_upper_bound(depth_star, mu):
    """Separations shrink by at most w(0): F ≤ (2π/5) μ F_{5/2}(d* − w(0))."""
    solution = greenwood_tripp.greenwood_tripp(depth_star, mu)
    upper = light_load_force(depth_star - solution.displacement[0], mu)
    assert solution.force_star <= upper * (1 + LIGHT_LOAD_RTOL), "force above the upper bound"


def test_light_load_limit():
    """F/((2π/5) μ F_{5/2}(d*)) − 1 decreases towards 0 as d* = 1, 2, 3 (3.3e-2, 4.4e-3,
    1.8e-3 for μ = 1)."""
    excess = [greenwood_tripp.greenwood_tripp(d, 1.0).force_star / light_load_force(d, 1.0) - 1
              for d in (1.0, 2.0, 3.0)]
    assert excess[0] > excess[1] > excess[2] > 0, f"no light-load convergence: {excess}"


@pytest.fixture(scope="module")
def heavy():
    """μ = 4 at d* = 0, −1, −2 (Hertz radius ρ_a = 1.0, 2.4, 5.1) on ρ ≤ 8."""
    return [greenwood_tripp.greenwood_tripp(d, MU, rho_max=8.0, points=160) for d in (0.0, -1.0, -2.0)]


def hertz_deviation(solution):
    """k/k_Hertz − 1 at the same force: k_Hertz = 4 ρ_a, F = (16/3) ρ_a³ in GT units."""
    radius = (3 * solution.force_star / 16) ** (1 / 3)
    return solution.stiffness_star / (4 * radius) - 1, radius


def test_hertz_limit_bound(heavy):
    """The summit layer, O(σ) thick, perturbs an approach of 2ρ_a² σ: |k/k_H − 1| ≤ 1/(2ρ_a²)
    at every load (measured 0.16, 0.035, 0.011 against 0.47, 0.083, 0.020)."""
    for solution in heavy:
        deviation, radius = hertz_deviation(solution)
        assert abs(deviation) <= 1 / (2 * radius**2), \
            f"d* = {solution.depth_star}: k/k_Hertz − 1 = {deviation:.3e}"


def test_hertz_limit_approached(heavy):
    deviations = [abs(hertz_deviation(s)[0]) for s in heavy]
    assert deviations[0] > deviations[1] > deviations[2], f"no approach to Hertz: {deviations}"


def test_load_vanishes_far_from_the_apex():
    """With p(ρ = 5) ≈ 1e-124 of the peak, extending the grid to ρ = 6 (same spacing)
    changes nothing but round-off."""
    near = greenwood_tripp.greenwood_tripp(0.0, MU, rho_max=5.0, points=101)
    far = greenwood_tripp.greenwood_tripp(0.0, MU, rho_max=6.0, points=121)
    assert near.force_star == pytest.approx(far.force_star, rel=1e-12), "truncation at ρ = 5"


def test_truncated_load_rejected():
    with pytest.raises(ValueError, match="rho_max"):
        greenwood_tripp.greenwood_tripp(-2.0, MU, rho_max=4.0)


@pytest.mark.parametrize("depth_star", [1.0, -1.0])
def test_stiffness_is_the_derivative(depth_star):
    """stiffness_star against (F₊ − F₋)/(α₊ − α₋) at d* ± 1e-4: O(1e-8) curvature and
    Newton residual (measured ≤ 8e-9); F is continuous and differentiable in d*."""
    step = 1e-4
    centre = greenwood_tripp.greenwood_tripp(depth_star, MU)
    plus = greenwood_tripp.greenwood_tripp(depth_star + step, MU)
    minus = greenwood_tripp.greenwood_tripp(depth_star - step, MU)
    quotient = (plus.force_star - minus.force_star) / (plus.approach_star - minus.approach_star)
    assert centre.stiffness_star == pytest.approx(quotient, rel=1e-6), "stiffness vs quotient"


def test_force_continuous_in_mu():
    """μ(1 ± 1e-6) moves F by ±(dlnF/dlnμ)·1e-6, with dlnF/dlnμ between 1 (light load)
    and 2.5 here (elastic flattening adds load): |ΔF/F| ≤ 1e-5."""
    centre = greenwood_tripp.greenwood_tripp(-1.0, MU).force_star
    for sign in (1, -1):
        moved = greenwood_tripp.greenwood_tripp(-1.0, MU * (1 + sign * 1e-6)).force_star
        assert 0 < sign * (moved / centre - 1) <= 1e-5, f"F not continuous in μ ({sign:+d})"


def test_theory_reexports_greenwood_tripp():
    assert greenwood_tripp.greenwood_tripp is greenwood_tripp.greenwood_tripp, "greenwood_tripp.greenwood_tripp"


# --- spectral moments and summits -----------------------------------------------------

@pytest.mark.parametrize("n", [64, 65])
@pytest.mark.parametrize("hurst", [0.3, 0.7, 1.2])
def test_array_moments_equal_the_discrete_spectrum(n, hurst):
    """The FFT of the generated surface has exactly the spectrum self_affine_moments sums
    (deterministic amplitudes, random phases): equal to round-off, any seed."""
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=2.0, seed=11)
    measured = surfaces.spectral_moments(z, length=2.0)
    expected = surfaces.self_affine_moments(hurst, h_rms=3e-3, n=n, length=2.0)
    for name in ("m0", "m2", "m4"):
        assert getattr(measured, name) == pytest.approx(getattr(expected, name), rel=1e-10), \
            f"{name} of the array differs from the discrete spectrum"


@pytest.mark.parametrize("n", [64, 65])
def test_moments_of_two_cosines(n):
    """z = A (cos qx + cos qy): m0 = A², m2 = ⟨|∇z|²⟩/2 = A²q²/2, m4 = (3/8)⟨(∇²z)²⟩ = 3A²q⁴/8."""
    length, amplitude = 3.0, 0.2
    q = 2 * math.pi * 4 / length
    x = np.arange(n) * length / n
    z = amplitude * (np.cos(q * x)[:, None] + np.cos(q * x)[None, :])
    moments = surfaces.spectral_moments(z, length=length)
    assert moments.m0 == pytest.approx(amplitude**2, rel=1e-12), "m0"
    assert moments.m2 == pytest.approx(amplitude**2 * q**2 / 2, rel=1e-12), "m2"
    assert moments.m4 == pytest.approx(3 * amplitude**2 * q**4 / 8, rel=1e-12), "m4"


def test_asperities_scale_with_the_heights():
    """Heights scaled by c: α and η unchanged, β ∝ 1/c, σ_s ∝ c (Nayak's formulas)."""
    base = asperities.asperity_parameters(surfaces.self_affine_moments(0.7, h_rms=1e-3, n=65, length=1.0))
    scaled = asperities.asperity_parameters(surfaces.self_affine_moments(0.7, h_rms=3e-3, n=65, length=1.0))
    assert scaled.bandwidth == pytest.approx(base.bandwidth, rel=1e-12), "bandwidth"
    assert scaled.density == pytest.approx(base.density, rel=1e-12), "density"
    assert scaled.summit_radius == pytest.approx(base.summit_radius / 3, rel=1e-12), "radius"
    assert scaled.summit_sigma == pytest.approx(base.summit_sigma * 3, rel=1e-12), "sigma"


def test_isotropic_bandwidth_minimum_rejected():
    """α = m0 m4/m2² ≥ 1.5 for an isotropic surface (Nayak 1971): smaller is rejected."""
    with pytest.raises(ValueError, match="bandwidth"):
        asperities.asperity_parameters(surfaces.SpectralMoments(m0=1.0, m2=1.0, m4=1.0))


# --- physical units --------------------------------------------------------------------

def curve(scale, e_star):
    """GT curve of the paper's rough sphere on 128² (μ ≈ 4.0), lengths scaled by ``scale``."""
    summits = asperities.asperity_parameters(surfaces.self_affine_moments(0.7, h_rms=9e-3 * scale, n=128, length=scale))
    return greenwood_tripp.greenwood_tripp_curve([-1.0, -2.0], radius=0.5 * scale, e_star=e_star,
                                                 asperities=summits, rho_max=8.0, points=160)


@pytest.fixture(scope="module")
def curves():
    return curve(1.0, 1.0), curve(2.0, 3.0)


def test_curve_scaling(curves):
    """Lengths × 2 and E* × 3 leave μ unchanged and give F × 12, k × 6, approach × 2."""
    base, scaled = curves
    assert scaled.mu == pytest.approx(base.mu, rel=1e-12), "μ"
    assert np.allclose(scaled.force, 12 * base.force, rtol=1e-10, atol=0), "force scaling"
    assert np.allclose(scaled.stiffness, 6 * base.stiffness, rtol=1e-10, atol=0), "stiffness"
    assert np.allclose(scaled.approach, 2 * base.approach, rtol=1e-10, atol=0), "approach"


def test_curve_tends_to_hertz(curves):
    """At the heaviest load k → eq. 9, k = E*(6RF/E*)^(1/3), within σ/approach (the summit
    layer against the approach)."""
    base, _ = curves
    hertz = paper.hertz_stiffness(base.force[-1], radius=0.5, e_star=1.0)
    bound = base.sigma / base.approach[-1]
    assert base.stiffness[-1] == pytest.approx(hertz, rel=bound), "GT vs Hertz stiffness"
