"""The method of dimensionality reduction (roughcontact.mdr) against closed forms.

Discretisation bounds used below. The Winkler force ``F = E* Σ f(x_i) Δx`` with
``f = max(d − g, 0)`` is the composite trapezoidal rule for ``∫ f dx`` (``f``
vanishes at the ends), whose error is at most ``(Δx²/8) TV(f')`` (Peano kernel
``x(Δx − x)/2 ≤ Δx²/8`` per cell). For a convex body ``g = κ Q |x|^m`` (m ≥ 1)
in contact over ``|x| < a``, ``TV(f') = 4 g'(a)``, so with ``F = 2E* a d m/(m+1)``
the relative force error is ``ε ≤ (m+1)/4 (Δx/a)²``. The contact length counts
the nodes in ``|x| ≤ a``, ``2a/Δx ± 1``, so ``|k − 2E* a| ≤ E* Δx`` at a given
depth; at a given force ``a`` moves by at most ``ε/(m+1)``, adding ``2E* a ε/(m+1)``.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from scipy import integrate
from scipy.special import zeta

from roughcontact import surfaces
from roughcontact.models import mdr, paper
from roughcontact.surfaces import profiles

E_STAR = 2.0
LENGTH = 1.0
RADIUS = 0.5
NS = [256, 257]  # even and odd


def force_bound(m, dx, a):
    """Relative bound ε on the discretised force at contact radius a (module docstring)."""
    return (m + 1.0) / 4.0 * (dx / a) ** 2


def stiffness_bound(m, dx, a):
    """Absolute bound on |k − k_exact| at a given force (module docstring)."""
    return E_STAR * dx + 2.0 * E_STAR * a * force_bound(m, dx, a) / (m + 1.0) * 1.01


# --- the smooth sphere: Hertz ---------------------------------------------------------------

@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("a_cells", [10.3, 25.0, 40.7, 60.5])
def test_smooth_sphere_force_is_hertz(n, a_cells):
    dx = LENGTH / n
    a = a_cells * dx
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS)
    force = mdr.mdr_force(a**2 / RADIUS, np.zeros(n), dx=dx, e_star=E_STAR, body=body)
    hertz = 4.0 * E_STAR * a**3 / (3.0 * RADIUS)
    assert abs(force / hertz - 1.0) <= force_bound(2, dx, a), \
        f"F = {force} differs from 4E*a³/(3R) = {hertz} beyond the trapezoid bound"


@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("a_cells", [10.3, 25.0, 40.7, 60.5])
def test_smooth_sphere_contact_stiffness_is_2_e_a(n, a_cells):
    dx = LENGTH / n
    a = a_cells * dx
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS)
    k = mdr.mdr_stiffness(a**2 / RADIUS, np.zeros(n), dx=dx, e_star=E_STAR, body=body)
    assert abs(k - 2.0 * E_STAR * a) <= E_STAR * dx * (1 + 1e-9), \
        f"k = {k} differs from 2E*a = {2 * E_STAR * a} by more than one spring"


@pytest.mark.parametrize("n", NS)
def test_smooth_sphere_stiffness_at_force_is_hertz(n):
    dx = LENGTH / n
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS)
    forces = np.geomspace(1e-4, 1e-2, 9)
    result = mdr.mdr_indentation(forces, np.zeros(n), dx=dx, e_star=E_STAR, body=body)
    k_hertz = (6.0 * RADIUS * E_STAR**2 * forces) ** (1.0 / 3.0)
    assert np.allclose(k_hertz, paper.hertz_stiffness(forces, radius=RADIUS, e_star=E_STAR), rtol=1e-14)
    for f, k, kh in zip(forces, result.stiffness, k_hertz):
        a = kh / (2.0 * E_STAR)
        assert abs(k - kh) <= stiffness_bound(2, dx, a), \
            f"k({f}) = {k} against (6RE*²F)^(1/3) = {kh}"
    for f, d, kh in zip(forces, result.depth, k_hertz):
        a = kh / (2.0 * E_STAR)
        eps = force_bound(2, dx, a)
        assert abs(d / (a**2 / RADIUS) - 1.0) <= (2.0 / 3.0) * eps / (1 - eps), \
            f"depth({f}) = {d} against a²/R = {a**2 / RADIUS}"


# --- bodies of revolution f = Q r^m: eq. 7 and the MDR rule --------------------------------

@pytest.mark.parametrize("m", [1.0, 1.5, 2.0, 3.0])
def test_body_profile_is_the_mdr_rule(m):
    """g(x) = |x| ∫_0^|x| f'(r)/√(x² − r²) dr by quadrature (r = |x| sin t), f = Q r^m."""
    q = RADIUS ** (1.0 - m) / m
    for x in [0.01, 0.2, -0.37]:
        def slope(t, x=x):
            return q * m * (abs(x) * math.sin(t)) ** (m - 1.0)
        rule = abs(x) * integrate.quad(slope, 0.0, math.pi / 2, epsabs=0.0, epsrel=1e-13)[0]
        g = mdr.body_profile(x, radius=RADIUS, exponent=m)
        assert g == pytest.approx(rule, rel=1e-10), f"g({x}) = {g} != MDR rule {rule} (m = {m})"


@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("m", [1.0, 1.5, 3.0])
def test_power_law_body_stiffness_is_eq_7(n, m):
    dx = LENGTH / n
    q = RADIUS ** (1.0 - m) / m
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS, exponent=m)
    a = np.array([12.4, 30.0, 55.5]) * dx
    forces = paper.body_indentation(a, radius=RADIUS, e_star=E_STAR, exponent=m).force
    result = mdr.mdr_indentation(forces, np.zeros(n), dx=dx, e_star=E_STAR, body=body)
    for f, k, ai in zip(forces, result.stiffness, a):
        k7 = paper.profile_stiffness(f, q3d=q, hurst=m, e_star=E_STAR)
        assert abs(k - k7) <= stiffness_bound(m, dx, ai), f"m = {m}: k({f}) = {k}, eq. 7: {k7}"


@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("m", [1.0, 1.5, 3.0])
def test_power_law_body_force_at_depth(n, m):
    dx = LENGTH / n
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS, exponent=m)
    for a in np.array([12.4, 30.0, 55.5]) * dx:
        exact = paper.body_indentation(a, radius=RADIUS, e_star=E_STAR, exponent=m)
        f = mdr.mdr_force(exact.depth, np.zeros(n), dx=dx, e_star=E_STAR, body=body)
        assert abs(f / exact.force - 1.0) <= force_bound(m, dx, a), \
            f"m = {m}: F(d) = {f}, closed form {exact.force}"


# --- the 1D profile: spectrum and variance --------------------------------------------------

@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("hurst", [0.3, 0.7, 1.2])
def test_profile_spectrum_slope(n, hurst):
    """Mean periodogram over 8 seeds ∝ q^(−2H−1) (C1D = π q C2D, C2D ∝ q^(−2H−2)).

    The amplitudes are fixed and only the phases are random, so every seed's
    periodogram is the same up to FFT round-off (~1e-15 relative): the fitted
    slope is exact to 1e-9.
    """
    power = np.mean([np.abs(np.fft.rfft(profiles.profile_1d(n, hurst=hurst, h_rms=1e-2,
                                                       length=LENGTH, seed=s)))[1:] ** 2
                     for s in range(8)], axis=0)
    q = 2 * np.pi / LENGTH * np.arange(1, n // 2 + 1)
    slope = np.polyfit(np.log(q), np.log(power), 1)[0]
    assert slope == pytest.approx(-2 * hurst - 1, abs=1e-9), f"slope {slope} != -2H-1"


@pytest.mark.parametrize("n", NS)
def test_profile_spectrum_band(n):
    """Roll-off, cutoff: C1D ∝ q (C2D's plateau) below q_r, q^(−2H−1) up to q_c, 0 above."""
    hurst, rolloff, cutoff = 0.7, LENGTH / 8, LENGTH / 32
    power = np.abs(np.fft.rfft(profiles.profile_1d(n, hurst=hurst, h_rms=1e-2, length=LENGTH,
                                              seed=1, rolloff=rolloff, cutoff=cutoff)))[1:] ** 2
    k = np.arange(1, n // 2 + 1)
    below, band, above = k < 8, (k >= 8) & (k <= 32), k > 32
    slope_below = np.polyfit(np.log(k[below]), np.log(power[below]), 1)[0]
    slope_band = np.polyfit(np.log(k[band]), np.log(power[band]), 1)[0]
    assert slope_below == pytest.approx(1.0, abs=1e-9), "C1D below the roll-off is not ∝ q"
    assert slope_band == pytest.approx(-2 * hurst - 1, abs=1e-9), "band slope != -2H-1"
    assert np.max(power[above]) <= 1e-24 * np.max(power), "modes above the cutoff are not 0"


@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("band", [(None, None), (LENGTH / 4, None), (LENGTH / 4, LENGTH / 40)])
def test_profile_variance_is_rho_h2(n, band):
    """Parseval with fixed amplitudes: var(profile) = ρ h² to round-off."""
    rolloff, cutoff = band
    h = 3e-3
    rho = profiles.profile_variance_ratio(n, hurst=0.7, length=LENGTH, rolloff=rolloff, cutoff=cutoff)
    for seed in [0, 5]:
        p = profiles.profile_1d(n, hurst=0.7, h_rms=h, length=LENGTH, seed=seed,
                           rolloff=rolloff, cutoff=cutoff)
        assert abs(p.mean()) <= 1e-13 * h, "profile mean is not 0"
        assert np.mean(p**2) == pytest.approx(rho * h**2, rel=1e-12), "variance != ρ h²"


@pytest.mark.parametrize("n", [64, 65])
@pytest.mark.parametrize("band", [(None, None), (LENGTH / 4, LENGTH / 20)])
def test_rho_from_the_2d_generator(n, band):
    """ρ from surfaces.self_affine's own modes: σ²(q) = |FFT z|²/n⁴ = C2D Δq², so the 1D
    variance is Σ_k π|q_k| C2D(q_k) Δq = Σ_k π|k| σ²(k, 0); round-off only (no phases)."""
    rolloff, cutoff = band
    h = 2e-3
    z = surfaces.self_affine(n, hurst=0.7, h_rms=h, length=LENGTH, seed=4,
                             rolloff=rolloff, cutoff=cutoff)
    sigma2 = np.abs(np.fft.fft2(z)) ** 2 / n**4
    k = np.fft.fftfreq(n, 1.0 / n)
    assert sigma2.sum() == pytest.approx(h**2, rel=1e-12), "2D modes do not sum to h²"
    expected = float(np.sum(np.pi * np.abs(k) * sigma2[:, 0])) / h**2
    rho = profiles.profile_variance_ratio(n, hurst=0.7, length=LENGTH, rolloff=rolloff, cutoff=cutoff)
    assert rho == pytest.approx(expected, rel=1e-10), "ρ disagrees with the 2D generator's modes"


@pytest.mark.parametrize("hurst", [0.7, 1.2])
def test_rho_lattice_limit(hurst):
    """Paper's spectrum (no roll-off): ρ → π ζ(2H+1)/(2 ζ(H+1) β(H+1)) ≠ 1 as n → ∞.

    The 1D and 2D sums miss tails beyond |k| ≈ n/2 of relative size below
    π (n/2 − 1)^(−2H)/H each (integral bound; both sums are ≥ 1).
    """
    n, s = 513, hurst + 1.0
    beta = 4.0**-s * (zeta(s, 0.25) - zeta(s, 0.75))
    limit = np.pi * zeta(2 * hurst + 1) / (2 * zeta(s) * beta)
    rho = profiles.profile_variance_ratio(n, hurst=hurst, length=LENGTH)
    tail = np.pi * (n / 2 - 1) ** (-2 * hurst) / hurst
    assert abs(rho / limit - 1) <= 2 * tail, f"ρ = {rho} far from the lattice limit {limit}"
    assert rho > 1.15, f"ρ = {rho}: the 1D variance is not h² (it exceeds it by 15-30 %)"


@pytest.mark.parametrize("scale", [8, 16])
def test_rho_tends_to_one_with_rolloff(scale):
    """λ_r ≪ L and cutoff on the Nyquist wavenumber: lattice sums → integrals, ρ → 1.

    Observed |ρ − 1| ≈ 0.27 (λ_r/L)²; the tolerance is (λ_r/L)².
    """
    rho = profiles.profile_variance_ratio(1024, hurst=0.7, length=LENGTH, rolloff=LENGTH / scale,
                                     cutoff=2 * LENGTH / 1024)
    assert abs(rho - 1) <= scale**-2, f"ρ = {rho} at λ_r = L/{scale}"


def test_profiles_are_one_seeded_stream(monkeypatch):
    one = profiles.profile_1d(129, hurst=0.7, h_rms=1e-3, seed=11)
    many = profiles.profile_ensemble(129, 7, hurst=0.7, h_rms=1e-3, seed=11)
    assert np.array_equal(one, many[0]), "profile_1d is not row 0 of profile_ensemble"
    assert np.array_equal(many[:3], profiles.profile_ensemble(129, 3, hurst=0.7, h_rms=1e-3,
                                                         seed=11)), "rows depend on count"
    kwargs = {"radius": RADIUS, "hurst": 0.7, "h_rms": 1e-3, "length": LENGTH, "n": 129,
              "e_star": E_STAR, "realizations": 50, "seed": 3}
    whole = mdr.sphere_stiffness([1e-5, 1e-3], **kwargs)
    monkeypatch.setattr(profiles, "_CHUNK_CELLS", 129 * 7)   # blocks of 7 rows
    chunked = mdr.sphere_stiffness([1e-5, 1e-3], **kwargs)
    # the same profiles in other blocks: equal up to the summation order of the means (1e-13)
    np.testing.assert_allclose(chunked.stiffness, whole.stiffness, rtol=1e-13, err_msg="chunking changes the result")


# --- ensembles ------------------------------------------------------------------------------

@pytest.mark.parametrize("n", [128, 129])
def test_ensemble_equals_single_profiles(n):
    forces = np.geomspace(1e-6, 1e-3, 4)
    result = mdr.sphere_stiffness(forces, radius=RADIUS, hurst=0.7, h_rms=2e-3, length=LENGTH,
                                  n=n, e_star=E_STAR, realizations=3, seed=9)
    body = mdr.body_profile(profiles.coordinates(n, LENGTH), radius=RADIUS)
    rows = profiles.profile_ensemble(n, 3, hurst=0.7, h_rms=2e-3, length=LENGTH, seed=9)
    single = [mdr.mdr_indentation(forces, p, dx=LENGTH / n, e_star=E_STAR, body=body)
              for p in rows]
    assert np.allclose(result.stiffness, np.mean([s.stiffness for s in single], axis=0),
                       rtol=1e-14), "vectorised stiffness != mean of single profiles"
    assert np.allclose(result.depth, np.mean([s.depth for s in single], axis=0),
                       rtol=1e-12), "vectorised depth != mean of single profiles"


def test_ensemble_mean_converges_as_inverse_sqrt_n():
    """16 independent means of N = 100 scatter by their standard error, and N = 1600 has 1/4 of it.

    A sample standard deviation from 16 values is within ±50 % with probability > 0.99;
    from N = 100 and 1600 samples within ±30 % (kurtosis of k allowed for).
    """
    forces = [1e-5, 1e-4]
    kwargs = {"radius": RADIUS, "hurst": 0.7, "h_rms": 5e-3, "length": LENGTH, "n": 129,
              "e_star": E_STAR}
    runs = [mdr.sphere_stiffness(forces, realizations=100, seed=s, **kwargs) for s in range(16)]
    scatter = np.std([r.stiffness for r in runs], axis=0, ddof=1)
    error = np.mean([r.stiffness_error for r in runs], axis=0)
    big = mdr.sphere_stiffness(forces, realizations=1600, seed=99, **kwargs)
    for i in range(len(forces)):
        assert 0.5 <= scatter[i] / error[i] <= 1.5, "scatter of means != standard error"
        assert 0.7 <= 4 * big.stiffness_error[i] / error[i] <= 1.3, "error not ∝ 1/√N"
        assert abs(big.stiffness[i] - np.mean([r.stiffness[i] for r in runs])) \
            <= 4 * math.hypot(big.stiffness_error[i], error[i] / 4), "means disagree"


def test_rough_sphere_tends_to_hertz():
    """At large force the edge of contact moves by ~ h₁/g'(a) (h₁ = √ρ h the profile's rms,
    g' = 2a/R), i.e. |k/k_H − 1| ≲ h₁/(2 d_H) each side plus a spring, Δx/a."""
    n, h = 513, 9e-3
    forces = np.array([1e-4, 1e-3, 1e-2])
    result = mdr.sphere_stiffness(forces, radius=RADIUS, hurst=0.7, h_rms=h, length=LENGTH,
                                  n=n, e_star=E_STAR, realizations=400, seed=1)
    ratio = result.stiffness / paper.hertz_stiffness(forces, radius=RADIUS, e_star=E_STAR)
    deviation = np.abs(ratio - 1)
    assert deviation[0] > deviation[1] > deviation[2], f"k/k_H = {ratio} does not approach 1"
    a = paper.hertz_stiffness(forces[-1], radius=RADIUS, e_star=E_STAR) / (2 * E_STAR)
    h1 = math.sqrt(profiles.profile_variance_ratio(n, hurst=0.7)) * h
    tol = h1 / (a**2 / RADIUS) + LENGTH / n / a
    assert deviation[-1] <= tol, f"k/k_H = {ratio[-1]} at F = {forces[-1]} (tolerance {tol})"


@pytest.mark.parametrize("n", [128, 129])
def test_flat_full_contact_is_e_l(n):
    """Once the whole period touches, k = E* n Δx = E* L exactly (and no scatter)."""
    result = mdr.flat_stiffness([1e3], hurst=0.7, h_rms=1e-3, length=LENGTH, n=n,
                                e_star=E_STAR, realizations=20, seed=2)
    assert result.stiffness[0] == pytest.approx(E_STAR * LENGTH, rel=1e-14), "k != E* L"
    assert result.stiffness_error[0] == 0.0, "full contact has scatter"
    same = mdr.sphere_stiffness([1e3], radius=math.inf, hurst=0.7, h_rms=1e-3, length=LENGTH,
                                n=n, e_star=E_STAR, realizations=20, seed=2)
    assert np.array_equal(same.stiffness, result.stiffness), "flat != sphere with R = inf"


@settings(max_examples=60, deadline=None)
@given(profile=hnp.arrays(np.float64, st.integers(1, 40),
                          elements=st.floats(-1.0, 1.0, allow_subnormal=False)),
       force=st.floats(0.0, 100.0))
def test_inversion_round_trip(profile, force):
    """mdr_indentation inverts mdr_force exactly (piecewise-linear F(d))."""
    res = mdr.mdr_indentation(force, profile, dx=0.1, e_star=E_STAR)
    back = mdr.mdr_force(res.depth, profile, dx=0.1, e_star=E_STAR)
    assert back[0] == pytest.approx(force, rel=1e-9, abs=1e-12), "F(d(F)) != F"
    # k(d) is non-decreasing: the stiffness at F lies between k just below and above d(F).
    below, above = mdr.mdr_stiffness(np.maximum(res.depth + [-1e-9, 1e-9], 0.0), profile,
                                     dx=0.1, e_star=E_STAR)
    assert below <= res.stiffness[0] <= above, "stiffness at F is not dF/dd at d(F)"


# --- bad input ------------------------------------------------------------------------------

GOOD = {"hurst": 0.7, "h_rms": 1e-3, "length": 1.0}


@pytest.mark.parametrize("call, match", [
    (lambda: profiles.profile_1d(7, **GOOD), "n must be"),
    (lambda: profiles.profile_1d(64, hurst=2.0, h_rms=1e-3), "hurst"),
    (lambda: profiles.profile_1d(64, hurst=0.7, h_rms=0.0), "h_rms"),
    (lambda: profiles.profile_1d(64, **GOOD, seed=1.5), "seed"),
    (lambda: profiles.profile_1d(64, **GOOD, rolloff=2.0), "rolloff"),
    (lambda: profiles.profile_1d(64, **GOOD, cutoff=0.01), "cutoff"),
    (lambda: profiles.profile_ensemble(64, 0, **GOOD), "count"),
    (lambda: mdr.mdr_force(-1.0, np.zeros(5), dx=0.1, e_star=1.0), "depth"),
    (lambda: mdr.mdr_force(1.0, np.zeros((2, 5)), dx=0.1, e_star=1.0), "profile"),
    (lambda: mdr.mdr_force(1.0, [0.0, np.nan], dx=0.1, e_star=1.0), "profile"),
    (lambda: mdr.mdr_force(1.0, np.zeros(5), dx=0.0, e_star=1.0), "dx"),
    (lambda: mdr.mdr_force(1.0, np.zeros(5), dx=0.1, e_star=1.0, body=np.zeros(4)), "body"),
    (lambda: mdr.mdr_indentation("x", np.zeros(5), dx=0.1, e_star=1.0), "force"),
    (lambda: mdr.body_profile(0.1, radius=-1.0), "radius"),
    (lambda: mdr.sphere_stiffness(1e-3, radius=0.0, n=64, e_star=1.0, **GOOD), "radius"),
    (lambda: mdr.sphere_stiffness(1e-3, radius=1.0, n=64, e_star=-1.0, **GOOD), "e_star"),
    (lambda: mdr.sphere_stiffness([-1e-3], radius=1.0, n=64, e_star=1.0, **GOOD), "force"),
    (lambda: mdr.sphere_stiffness(1e-3, radius=1.0, n=64, e_star=1.0, realizations=1, **GOOD),
     "realizations"),
])
def test_bad_input_raises_value_error(call, match):
    with pytest.raises(ValueError, match=match):
        call()
