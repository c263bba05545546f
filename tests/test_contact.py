"""The BEM solver against closed forms: Boussinesq/Love, Hertz, flat punch, wavy surface."""

import math

import numpy as np
import pytest

from roughcontact import bem
from roughcontact import errors
from roughcontact import surfaces
from roughcontact.bem import active_sets
from roughcontact.bem import operators

E_STAR = 1.0


# --- influence operators ---------------------------------------------------------------

@pytest.mark.parametrize("n", [64, 65])
def test_free_operator_far_field_is_point_load(n):
    """Far from a loaded cell, u = F/(π E* r) (Boussinesq); the cell's finite size
    adds O((Δ/r)²/24) ≈ 4e-4 at r = 10 cells."""
    length, e_star = 2.0, 3.0
    spacing = length / n
    pressure = np.zeros((n, n))
    pressure[0, 0] = 1.0
    u = operators.FreeSpaceOperator(n, length, e_star)(pressure)
    force = spacing**2
    for i, j in [(10, 0), (0, 25), (20, 20), (n - 1, 3)]:
        r = math.hypot(i, j) * spacing
        assert u[i, j] == pytest.approx(force / (math.pi * e_star * r), rel=1e-3), \
            f"far field at offset ({i}, {j})"


def test_free_operator_self_coefficient():
    """Centre of a uniformly loaded square: u = 4 ln(1+√2) Δ p/(π E*) (Love 1929)."""
    n, length, e_star = 32, 3.0, 2.0
    op = operators.FreeSpaceOperator(n, length, e_star)
    expected = 4 * math.log(1 + math.sqrt(2)) * (length / n) / (math.pi * e_star)
    assert op.self_coefficient == pytest.approx(expected, rel=1e-14), "self-coefficient"


def test_free_operator_window_equals_full_grid():
    """A window convolved on its own padded size gives the full grid's displacement."""
    n = 65
    rng = np.random.default_rng(0)
    pressure = np.zeros((n, n))
    pressure[20:41, 25:37] = rng.uniform(size=(21, 12))
    op = operators.FreeSpaceOperator(n, 1.0, 1.0)
    full = op(pressure)
    window = op(pressure[20:41, 25:37])
    assert np.allclose(window, full[20:41, 25:37], rtol=1e-12, atol=1e-15 * full.max()), \
        "windowed DC-FFT differs from the full grid"


def test_free_operator_window_after_a_smaller_one_of_the_same_fft_size():
    """Windows of 57 and 60 cells share the padded size 120: the spectrum cached for the first
    also serves the second, whose displacement equals the full grid's (a spectrum built with
    the 57-cell window's offsets only was 2.5 % off at the far cells)."""
    n = 100
    rng = np.random.default_rng(1)
    op = operators.FreeSpaceOperator(n, 1.0, 1.0)
    op(rng.uniform(size=(57, 57)))
    pressure = np.zeros((n, n))
    pressure[:60, :60] = rng.uniform(size=(60, 60))
    full = operators.FreeSpaceOperator(n, 1.0, 1.0)(pressure)[:60, :60]
    window = op(pressure[:60, :60])
    assert np.allclose(window, full, rtol=1e-12, atol=1e-15 * full.max()), \
        "a cached spectrum misses offsets of a larger window of the same padded size"


@pytest.mark.parametrize("periodic", [False, True])
@pytest.mark.parametrize("n", [32, 33])
def test_column_sums_equal_the_convolution(n, periodic):
    """The solver's incremental update (influence columns summed directly, on a window
    for the free half-space, a small window first and then a larger one) equals the
    FFT convolution of the same pressures."""
    op = operators.operator_for(n, 1.0, 2.0, periodic)
    for shape in [(n, n)] if periodic else [(9, 7), (n - 5, n - 9)]:
        cells = np.array([0, 7, shape[1] + 3, shape[0] * shape[1] - 1])
        values = np.array([1.0, -0.5, 2.0, 0.25])
        pressure = np.zeros(shape)
        pressure.flat[cells] = values
        field = np.zeros(shape)
        op.add_columns(field, values, cells)
        expected = op(pressure)
        assert np.allclose(field, expected, rtol=0, atol=1e-13 * np.abs(expected).max()), \
            f"column sums differ from the convolution on a {shape} window"


@pytest.mark.parametrize("n", [64, 63])
def test_periodic_operator_cosine(n):
    """p = p0 cos(q x) gives u = 2 p0 cos(q x)/(E* q) on a periodic half-space."""
    length, e_star, p0 = 2.0, 3.0, 0.7
    x = np.arange(n) * length / n
    q = 2 * math.pi * 3 / length
    pressure = np.broadcast_to(p0 * np.cos(q * x)[:, None], (n, n))
    u = operators.PeriodicOperator(n, length, e_star)(pressure)
    expected = 2 * p0 * np.cos(q * x)[:, None] / (e_star * q)
    assert np.allclose(u, expected, atol=1e-12 * abs(expected).max()), "periodic cosine response"


# --- Hertz -----------------------------------------------------------------------------

@pytest.fixture(scope="module")
def hertz():
    """Paraboloid, n = 512, R = 0.5, L = 1, force for a contact radius a = 0.1 (51 cells)."""
    n, radius, length = 512, 0.5, 1.0
    a = 0.1
    force = 4 * E_STAR * a**3 / (3 * radius)
    z = surfaces.paraboloid(n, radius=radius, length=length)
    state = bem.solve(z, force=force, length=length, e_star=E_STAR, tol=1e-8)
    return state, radius, force


def test_hertz_converged(hertz):
    assert hertz[0].converged, "Hertz solve did not converge"


def test_hertz_depth(hertz):
    """d = (9F²/(16 R E*²))^(1/3); the discretization error is O(Δ²/a²) of d ≈ 2e-2."""
    state, radius, force = hertz
    expected = (9 * force**2 / (16 * radius * E_STAR**2)) ** (1 / 3)
    assert state.depth == pytest.approx(expected, abs=1e-4), "Hertz depth"


def test_hertz_contact_radius(hertz):
    """a = (3FR/4E*)^(1/3), measured as √(area/π), within one cell."""
    state, radius, force = hertz
    expected = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    measured = math.sqrt(state.contact_area / math.pi)
    assert measured == pytest.approx(expected, abs=1.0 / 512), "Hertz contact radius"


def test_hertz_peak_pressure(hertz):
    """p0 = 3F/(2πa²) within 1% (the apex cell carries the maximum)."""
    state, radius, force = hertz
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    assert state.pressure.max() == pytest.approx(3 * force / (2 * math.pi * a**2), rel=1e-2), \
        "Hertz peak pressure"


def test_hertz_force_matched(hertz):
    state, _, force = hertz
    assert state.force == pytest.approx(force, rel=1e-12), "force not matched"


def test_hertz_stiffness(hertz):
    """k = 2 E* a within 1%."""
    state, radius, force = hertz
    a = (3 * force * radius / (4 * E_STAR)) ** (1 / 3)
    assert bem.stiffness(state) == pytest.approx(2 * E_STAR * a, rel=1e-2), "Hertz stiffness"


def test_hertz_windowed_equals_full(hertz):
    """The windowed solve and the whole-grid solve agree within the tolerance."""
    state, _, force = hertz
    full = bem.solve(state.heights, force=force, length=1.0, e_star=E_STAR, windowed=False)
    assert state.window != full.window, "the test should compare a window with the full grid"
    assert state.depth == pytest.approx(full.depth, rel=1e-7), "windowed depth differs"
    assert np.array_equal(state.contact, full.contact), "windowed contact set differs"


# --- flat punch ------------------------------------------------------------------------

@pytest.mark.parametrize("n, cells", [(128, 30), (129, 31)])
def test_flat_punch_stiffness(n, cells):
    """Rigid flat circular punch: k = 2 E* a (Boussinesq), a = √(area/π) of the
    discretized disc; the unresolved edge singularity costs ≈ 0.4% at 30 cells."""
    r = surfaces.radial_distance(n, 1.0)
    z = np.where(r <= cells / n, 0.0, 1.0)
    state = bem.solve(z, force=1e-3, length=1.0, e_star=E_STAR)
    a = math.sqrt(state.contact_area / math.pi)
    assert np.count_nonzero(state.contact) == np.count_nonzero(z == 0), "punch not in full contact"
    assert bem.stiffness(state) == pytest.approx(2 * E_STAR * a, rel=2e-2), "punch stiffness"


@pytest.mark.parametrize("n, cells", [(128, 30), (129, 31)])
def test_contact_stiffness_of_a_disc_is_the_flat_punch(n, cells):
    """bem.punch.contact_stiffness of a disc mask off the grid's centre: k = 2 E* a, a = √(area/π),
    within the 2 % of the test above (the same discretised edge)."""
    from roughcontact.bem.punch import contact_stiffness

    r = surfaces.radial_distance(n, 1.0)
    disc = np.roll(r <= cells / n, (n // 5, -n // 7), axis=(0, 1))
    a = math.sqrt(np.count_nonzero(disc) / math.pi) / n
    k = contact_stiffness(disc, length=1.0, e_star=E_STAR, periodic=False, tol=1e-10)
    assert k == pytest.approx(2 * E_STAR * a, rel=2e-2), "punch stiffness of the mask"


# --- periodic wavy surface -------------------------------------------------------------

@pytest.mark.parametrize("n", [256, 255])
@pytest.mark.parametrize("load_ratio", [0.1, 0.5, 0.9])
def test_wavy_contact_half_width(n, load_ratio):
    """Johnson (1985) §13.2: sin²(π a/λ) = p̄/p*, p* = π E* h/λ; 2a within two cells
    (one at each end of the strip)."""
    length, h = 1.0, 1e-2
    x = np.arange(n) * length / n
    z = np.broadcast_to(h * np.cos(2 * math.pi * x / length)[:, None], (n, n)).copy()
    p_star = math.pi * E_STAR * h / length
    force = load_ratio * p_star * length**2
    state = bem.solve(z, force=force, length=length, e_star=E_STAR, periodic=True)
    half_width = math.asin(math.sqrt(load_ratio)) * length / math.pi
    measured = np.count_nonzero(state.contact[:, 0]) * length / n / 2
    assert state.converged, "wavy solve did not converge"
    assert measured == pytest.approx(half_width, abs=length / n), "wavy contact half-width"


def wavy_state(load_ratio, n=64, length=1.0, h=1e-2):
    x = np.arange(n) * length / n
    z = np.broadcast_to(h * np.cos(2 * math.pi * x / length)[:, None], (n, n)).copy()
    force = load_ratio * math.pi * E_STAR * h / length * length**2
    return bem.solve(z, force=force, length=length, e_star=E_STAR, periodic=True)


@pytest.mark.parametrize("load_ratio", [1.0, 1.5])
def test_wavy_gap_closed_at_full_load(load_ratio):
    """At p̄ ≥ p* the gap closes everywhere (at p̄ = p* the crest pressure is 0)."""
    state = wavy_state(load_ratio)
    assert np.abs(state.gap()).max() <= state.tol * state.depth, \
        f"gap not closed everywhere at p/p* = {load_ratio}"


def test_wavy_full_contact_above_critical_load():
    """Above p* the pressure p̄ (1 + (p*/p̄) cos) is positive on every cell."""
    assert wavy_state(1.5).contact.all(), "not in full contact at p/p* = 1.5"


# --- nominally flat rough surface (periodic) -------------------------------------------

@pytest.fixture(scope="module", params=[128, 129])
def flat_path(request):
    """Self-affine surface on the periodic half-space; loads with 1 to a few hundred cells."""
    n = request.param
    z = surfaces.self_affine(n, hurst=0.7, h_rms=9e-3, length=1.0, seed=3)
    forces = np.geomspace(1e-6, 3e-4, 5)
    return z, forces, bem.load_path(z, forces, length=1.0, e_star=E_STAR, periodic=True)


def test_flat_candidates_equal_whole_grid(flat_path):
    """The dense solve on the cells that can touch gives the whole-grid FFT solution."""
    z, forces, states = flat_path
    for force, state in zip(forces, states):
        full = bem.solve(z, force=force, length=1.0, e_star=E_STAR, periodic=True,
                             windowed=False)
        assert state.depth == pytest.approx(full.depth, rel=1e-7), f"depth differs at F = {force:g}"
        assert np.array_equal(state.contact, full.contact), f"contact set differs at F = {force:g}"


def test_flat_candidates_complementarity(flat_path):
    """Complementarity on the whole grid: |g| ≤ tol·d in contact, g ≥ −tol·d outside."""
    _, forces, states = flat_path
    for force, state in zip(forces, states):
        gap = state.gap()
        assert np.abs(gap[state.contact]).max() <= state.tol * state.depth, f"gap open at F = {force:g}"
        assert gap[~state.contact].min() >= -state.tol * state.depth, f"penetration at F = {force:g}"


def test_flat_cold_solve_enlarges_the_candidates(monkeypatch):
    """A cold solve at F/(E*L²) = 3e-4 (60 contact cells, depth 1.7× the first bound: the
    depth of the 64 lowest cells) enlarges the candidates once and still equals the FFT
    solution on the whole grid."""
    z = surfaces.self_affine(129, hurst=0.7, h_rms=9e-3, length=1.0, seed=3)
    used = []
    solve_candidates = active_sets.solve_candidates
    monkeypatch.setattr(active_sets, "solve_candidates",
                        lambda *args: used.append(solve_candidates(*args)) or used[-1])
    state = bem.solve(z, force=3e-4, length=1.0, e_star=E_STAR, periodic=True)
    full = bem.solve(z, force=3e-4, length=1.0, e_star=E_STAR, periodic=True, windowed=False)
    assert used and used[-1] is not None, "the candidate solve was not used"
    assert state.depth > np.quantile(z - z.min(), 64 / z.size), "the first bound was not too small"
    assert state.depth == pytest.approx(full.depth, rel=1e-7), "depth differs from the whole grid"
    assert np.array_equal(state.contact, full.contact), "contact set differs from the whole grid"


@pytest.mark.parametrize("periodic", [True, False])
def test_dense_punch_stiffness_equals_matrix_free(flat_path, rough, monkeypatch, periodic):
    """The punch stiffness with a dense influence matrix equals the FFT-based one."""
    states = flat_path[2] if periodic else [rough[1]]
    dense = [bem.stiffness(s) for s in states]
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 0)
    for state, k in zip(states, dense):
        assert k == pytest.approx(bem.stiffness(state), rel=1e-7), \
            f"dense punch stiffness differs ({int(state.contact.sum())} cells)"


def _replace_single(monkeypatch, state, product):
    """Patch the single-precision product of ``state``'s operator class with
    ``product(exact_single, self, p)``."""
    operator_type = type(operators.operator_for(state.heights.shape[0], state.length,
                                                state.e_star, state.periodic))
    exact_single = operator_type.single
    monkeypatch.setattr(operator_type, "single", lambda self, p: product(exact_single, self, p))


@pytest.mark.parametrize("periodic", [True, False])
def test_punch_refinement_uses_single_precision_products(flat_path, rough, monkeypatch, periodic):
    """A large footprint's punch solve runs on single-precision products (the fast path) and
    still meets tol = 1e-8: the dense solve gives the same stiffness within 1e-7."""
    state = flat_path[2][-1] if periodic else rough[1]
    dense = bem.stiffness(state)
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 0)
    calls = []
    _replace_single(monkeypatch, state, lambda single, self, p: calls.append(1) or single(self, p))
    assert bem.stiffness(state) == pytest.approx(dense, rel=1e-7), "refined punch stiffness differs"
    assert len(calls) > 0, "the single-precision products were not used"


@pytest.mark.parametrize("wrong", ["scaled", "indefinite"])
@pytest.mark.parametrize("periodic", [True, False])
def test_punch_refinement_survives_a_wrong_single_precision_product(flat_path, rough, monkeypatch,
                                                                     periodic, wrong):
    """The single-precision products only steer the refinement. Products off by a factor 2
    (each correction overshoots, the residual does not shrink) or indefinite (K − 2 K_00 I:
    the inner conjugate gradients do not converge) make the solve fall back to double
    precision, with the same stiffness within 1e-7 (tol = 1e-8)."""
    state = flat_path[2][-1] if periodic else rough[1]
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 0)
    refined = bem.stiffness(state)
    if wrong == "scaled":
        _replace_single(monkeypatch, state, lambda single, self, p: 0.5 * single(self, p))
    else:
        _replace_single(monkeypatch, state,
                        lambda single, self, p: single(self, p) - 2.0 * self.self_coefficient * p)
    assert bem.stiffness(state) == pytest.approx(refined, rel=1e-7), \
        f"a {wrong} single-precision product changed the punch stiffness"


# --- rough sphere ----------------------------------------------------------------------

@pytest.fixture(scope="module")
def rough():
    n, length = 257, 1.0
    z = surfaces.rough_sphere(n, radius=0.5, hurst=0.7, h_rms=9e-3, length=length, seed=4)
    state = bem.solve(z, force=1e-3, length=length, e_star=E_STAR, tol=1e-8)
    return z, state


def test_rough_pressure_non_negative(rough):
    assert rough[1].pressure.min() >= 0.0, "negative pressure"


def test_rough_gap_closed_in_contact(rough):
    z, state = rough
    gap = state.gap()
    assert np.abs(gap[state.contact]).max() <= state.tol * state.depth, "gap open in contact"


def test_rough_gap_non_negative_outside(rough):
    z, state = rough
    gap = state.gap()
    assert gap[~state.contact].min() >= -state.tol * state.depth, "interpenetration outside"


def test_rough_force_matched(rough):
    assert rough[1].force == pytest.approx(1e-3, rel=1e-10), "force not matched"


def test_rough_warm_equals_cold(rough):
    z, cold = rough
    lower = bem.solve(z, force=0.7e-3, length=1.0, e_star=E_STAR)
    warm = bem.solve(z, force=1e-3, length=1.0, e_star=E_STAR, initial=lower.pressure)
    assert warm.depth == pytest.approx(cold.depth, rel=1e-7), "warm-start depth differs"
    assert np.array_equal(warm.contact, cold.contact), "warm-start contact set differs"


@pytest.mark.parametrize("periodic", [False, True])
def test_warm_start_in_fortran_order(periodic):
    """A warm start in Fortran order (e.g. a transposed pressure) is an array like any other:
    the same contact set and a depth within the solver's tolerance of the cold start
    (the kernel's flat views of such an array once were copies, and the solve never moved)."""
    z = surfaces.rough_sphere(64, radius=0.5, hurst=0.7, h_rms=2e-3, length=1.0, seed=3)
    if periodic:
        z = surfaces.self_affine(64, hurst=0.7, h_rms=2e-3, length=1.0, seed=3)
    force = 2e-3
    cold = bem.solve(z, force=force, length=1.0, e_star=E_STAR, periodic=periodic)
    lower = bem.solve(z.T, force=0.7 * force, length=1.0, e_star=E_STAR, periodic=periodic)
    warm = bem.solve(z, force=force, length=1.0, e_star=E_STAR, periodic=periodic,
                     initial=lower.pressure.T)
    assert warm.converged, "the Fortran-order warm start did not converge"
    assert warm.depth == pytest.approx(cold.depth, rel=1e-7), "warm-start depth differs"
    assert np.array_equal(warm.contact, cold.contact), "warm-start contact set differs"


def test_rough_windowed_equals_full(rough):
    z, state = rough
    full = bem.solve(z, force=1e-3, length=1.0, e_star=E_STAR, windowed=False)
    assert full.depth == pytest.approx(state.depth, rel=1e-7), "windowed depth differs"
    assert np.array_equal(full.contact, state.contact), "windowed contact set differs"


def test_rough_difference_quotient_equals_punch(rough):
    """The paper's differential quotient approaches the exact tangent stiffness;
    over ±0.1% of load few cells change status, so they agree within 1%."""
    _, state = rough
    exact = bem.stiffness(state)
    assert bem.stiffness(state, method="difference", rel_step=1e-3) == \
        pytest.approx(exact, rel=1e-2), "difference quotient vs punch stiffness"


def test_load_path_matches_independent_solves(rough):
    z, state = rough
    states = bem.load_path(z, [1e-5, 1e-4, 1e-3], length=1.0, e_star=E_STAR)
    assert states[-1].depth == pytest.approx(state.depth, rel=1e-7), "load-path depth differs"
    assert [s.force for s in states] == pytest.approx([1e-5, 1e-4, 1e-3], rel=1e-12), "forces"


@pytest.mark.parametrize("n", [64, 65])
def test_iter_load_path_equals_load_path(n):
    """The generator yields, state by state, exactly what load_path returns (same solves,
    same warm starts: equal to the last bit), and reports progress the same way."""
    z = surfaces.rough_sphere(n, radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, seed=5)
    forces = np.geomspace(1e-5, 1e-3, 4)
    calls = []
    listed = bem.load_path(z, forces, length=1.0, e_star=E_STAR,
                               progress=lambda i, total, s: calls.append((i, total, s.force)))
    generated = bem.iter_load_path(z, forces, length=1.0, e_star=E_STAR)
    count = 0
    for a, b in zip(listed, generated, strict=True):
        count += 1
        assert a.depth == b.depth, f"depth differs at F = {a.force:g}"
        assert a.iterations == b.iterations, f"iterations differ at F = {a.force:g}"
        assert np.array_equal(a.pressure, b.pressure), f"pressure differs at F = {a.force:g}"
    assert count == len(forces), "the generator yielded the wrong number of states"
    assert [c[:2] for c in calls] == [(i + 1, len(forces)) for i in range(len(forces))], \
        "progress calls"


def test_iter_load_path_checks_arguments_eagerly():
    """Bad arguments raise when the generator is made, not at the first next()."""
    z = surfaces.paraboloid(16, radius=0.5)
    with pytest.raises(ValueError, match="forces"):
        bem.iter_load_path(z, [1e-4, -1.0], length=1.0, e_star=E_STAR)


def test_stiffness_increases_along_load_path(rough):
    z, _ = rough
    states = bem.load_path(z, np.geomspace(1e-6, 1e-3, 6), length=1.0, e_star=E_STAR)
    k = [bem.stiffness(s) for s in states]
    assert np.all(np.diff(k) > 0), f"stiffness not increasing: {k}"


# --- scaling ---------------------------------------------------------------------------

def test_exact_scaling_with_length_and_modulus():
    """Same problem with L = 2, E* = 3: F ∝ E*L², k ∝ E*L, d ∝ L, to 1e-10."""
    n, kw = 129, dict(radius=0.5, hurst=0.7, h_rms=9e-3, seed=2)
    base_z = surfaces.rough_sphere(n, length=1.0, **kw)
    base = bem.solve(base_z, force=1e-3, length=1.0, e_star=1.0, tol=1e-12)
    scaled_z = surfaces.rough_sphere(n, length=2.0, **{**kw, "radius": 1.0, "h_rms": 18e-3})
    scaled = bem.solve(scaled_z, force=1e-3 * 3 * 4, length=2.0, e_star=3.0, tol=1e-12)
    assert scaled.force / base.force == pytest.approx(12, rel=1e-10), "force scaling"
    assert scaled.depth / base.depth == pytest.approx(2, rel=1e-10), "depth scaling"
    assert bem.stiffness(scaled, tol=1e-13) / bem.stiffness(base, tol=1e-13) == \
        pytest.approx(6, rel=1e-10), "stiffness scaling"


# --- failure modes ---------------------------------------------------------------------

def test_contact_reaching_edge_raises():
    z = surfaces.paraboloid(32, radius=0.5, length=1.0)
    with pytest.raises(errors.DomainTooSmallError, match="edge"):
        bem.solve(z, force=1.0, length=1.0, e_star=E_STAR)


def test_maxiter_reports_not_converged():
    z = surfaces.rough_sphere(65, radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, seed=0)
    state = bem.solve(z, force=1e-3, length=1.0, e_star=E_STAR, maxiter=2)
    assert not state.converged, "a 2-iteration solve claims convergence"


@pytest.mark.parametrize("kwargs, name", [
    (dict(force=-1.0), "force"),
    (dict(force=float("nan")), "force"),
    (dict(length=0.0), "length"),
    (dict(e_star=-1.0), "e_star"),
    (dict(tol=0.0), "tol"),
    (dict(maxiter=0), "maxiter"),
])
def test_bad_arguments_name_themselves(kwargs, name):
    z = surfaces.paraboloid(16, radius=0.5)
    args = dict(force=1e-4, length=1.0, e_star=1.0) | kwargs
    with pytest.raises(ValueError, match=name):
        bem.solve(z, **args)


def test_non_square_heights_rejected():
    with pytest.raises(ValueError, match="heights"):
        bem.solve(np.zeros((16, 17)), force=1.0, length=1.0, e_star=1.0)


def test_unknown_stiffness_method_rejected(rough):
    with pytest.raises(ValueError, match="method"):
        bem.stiffness(rough[1], method="secant")


def test_edge_contact_allowed_for_a_finite_flat_punch():
    """A nominally flat rough indenter as large as the grid may touch its edge cells."""
    z = surfaces.self_affine(64, hurst=0.7, h_rms=9e-3, length=1.0, seed=0)
    state = bem.solve(z, force=1e-2, length=1.0, e_star=E_STAR, edge_contact=True)
    edge = np.concatenate([state.contact[0], state.contact[-1],
                           state.contact[:, 0], state.contact[:, -1]])
    assert state.converged, "edge-contact solve did not converge"
    assert edge.any(), "the test load should reach the edge"
    gap = state.gap()
    assert np.abs(gap[state.contact]).max() <= state.tol * state.depth, "gap open in contact"
