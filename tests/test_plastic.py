"""Penetration-hardness plasticity against the fully plastic limit, the elastic solver
and ContactMechanics' PlasticNonSmoothContactSystem."""

import itertools
import math

import numpy as np
import pytest

from roughcontact import bem
from roughcontact import surfaces
from roughcontact.bem import bounded

E_STAR = 1.0
LENGTH = 1.0
RADIUS = 0.5
#: Contact radius a₀ of the fully plastic sphere tests: F = H π a₀² (≈ 25 cells).
PLASTIC_RADIUS = 0.2
HARDNESSES = (1e-2, 3e-3, 1e-3)          # H/E*
#: Cells of equal height form rings of 4 to 16 cells around the apex; a force-controlled
#: fully plastic contact sits at the level of one ring while it fills, so the discrete
#: plastic area differs from the continuous 2πRd by up to about this many cells.
RING_CELLS = 16


# --- smooth sphere: the fully plastic limit --------------------------------------------

@pytest.fixture(scope="module", params=[128, 129])
def plastic_spheres(request):
    """Paraboloid pressed with F = H π a₀² at each hardness of HARDNESSES."""
    n = request.param
    z = surfaces.paraboloid(n, radius=RADIUS, length=LENGTH)
    states = {hardness: bem.solve(z, force=hardness * math.pi * PLASTIC_RADIUS**2,
                                      length=LENGTH, e_star=E_STAR, hardness=hardness)
              for hardness in HARDNESSES}
    return n, states


def plastic_limit_deviation(state):
    """F/(2πR H d) − 1: the deviation from the fully plastic limit F = 2πR H d."""
    return state.force / (2 * math.pi * RADIUS * state.hardness * state.depth) - 1


def sink_in_depth(force, hardness):
    """Depth of the fully plastic sphere with the elastic sink-in of its contact edge.

    The uniform pressure H on a disc of radius a = √(F/(πH)) displaces its edge by
    4Ha/(πE*) (Johnson, Contact Mechanics, 1985, ch. 3), and the edge is where the sphere meets the
    deformed surface: a²/(2R) = d − 4Ha/(πE*), i.e. d = F/(2πRH) + 4Ha/(πE*).
    """
    a = math.sqrt(force / (math.pi * hardness))
    return force / (2 * math.pi * RADIUS * hardness) + 4 * hardness * a / (math.pi * E_STAR)


def test_fully_plastic_limit_converges(plastic_spheres):
    """|F/(2πRHd) − 1| decreases as H/E* goes 1e-2 → 3e-3 → 1e-3 (the elastic sink-in,
    ≈ (8R/(πa))·H/E*, vanishes)."""
    _, states = plastic_spheres
    deviations = [abs(plastic_limit_deviation(states[h])) for h in HARDNESSES]
    assert all(a > b for a, b in itertools.pairwise(deviations)), \
        f"no convergence to the fully plastic limit: |F/(2πRHd) − 1| = {deviations}"


def test_fully_plastic_limit_at_smallest_hardness(plastic_spheres):
    """At H/E* = 1e-3, F = 2πR H d within the sink-in (8R/(πa))·H/E* ≈ 0.6 % plus
    RING_CELLS of the ≈ 2060 contact cells (0.8 %, the grid's resolution of the circle)."""
    _, states = plastic_spheres
    hardness = min(HARDNESSES)
    state = states[hardness]
    cells = state.force / (hardness * state.cell_area)
    bound = 8 * RADIUS / (math.pi * PLASTIC_RADIUS) * hardness / E_STAR + RING_CELLS / cells
    deviation = plastic_limit_deviation(state)
    assert abs(deviation) <= bound, f"F/(2πRHd) − 1 = {deviation:.2e} > {bound:.2e}"


@pytest.mark.parametrize("hardness", HARDNESSES)
def test_fully_plastic_depth_with_sink_in(plastic_spheres, hardness):
    """d = F/(2πRH) + 4Ha/(πE*) (sink_in_depth), up to RING_CELLS cells of the contact
    and the neglected second order of the sink-in, ((8R/(πa))·H/E*)²."""
    _, states = plastic_spheres
    state = states[hardness]
    cells = state.force / (hardness * state.cell_area)
    bound = RING_CELLS / cells + (8 * RADIUS / (math.pi * PLASTIC_RADIUS) * hardness / E_STAR) ** 2
    expected = sink_in_depth(state.force, hardness)
    assert state.depth == pytest.approx(expected, rel=bound), \
        f"H/E* = {hardness:g}: depth {state.depth:.6g} vs {expected:.6g} (rel. bound {bound:.2e})"


def test_fully_plastic_loading_stiffness(plastic_spheres):
    """The loading secant over F → 1.5 F follows sink_in_depth, k = ΔF/Δd ≈ 2πRH; the ring
    lattice enters at both ends: 2·RING_CELLS of the ≈ 1030 cells added."""
    _, states = plastic_spheres
    hardness = min(HARDNESSES)
    state = states[hardness]
    step = 0.5
    measured = bem.stiffness(state, method="loading", rel_step=step)
    expected = step * state.force / (sink_in_depth(state.force * (1 + step), hardness)
                                     - sink_in_depth(state.force, hardness))
    added = step * state.force / (hardness * state.cell_area)
    assert measured == pytest.approx(expected, rel=2 * RING_CELLS / added), \
        f"loading stiffness {measured:.4g} vs fully plastic {expected:.4g}"


def test_fully_plastic_unloading_stiffness(plastic_spheres):
    """Unloading is elastic on the flattened footprint: a flat punch, k = 2E*a with
    a = √(area/π); the unresolved edge singularity costs ≈ 0.4 % at 25 cells."""
    _, states = plastic_spheres
    state = states[min(HARDNESSES)]
    a = math.sqrt(state.contact_area / math.pi)
    assert bem.stiffness(state) == pytest.approx(2 * E_STAR * a, rel=1e-2), \
        "unloading stiffness of the fully plastic sphere"


# --- rough sphere ----------------------------------------------------------------------

@pytest.fixture(scope="module", params=[128, 129])
def rough(request):
    """Rough sphere with its elastic solution at F/(E*L²) = 1e-3 (peak pressure ≈ 0.5 E*)."""
    n = request.param
    z = surfaces.rough_sphere(n, radius=RADIUS, hurst=0.7, h_rms=9e-3, length=LENGTH, seed=0)
    return z, bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR)


@pytest.fixture(scope="module")
def capped_path(rough):
    """Load path at H = 0.05 E* (a tenth of the elastic peak): most contact cells flow."""
    z, _ = rough
    return bem.load_path(z, [3e-4, 6e-4, 1e-3], length=LENGTH, e_star=E_STAR, hardness=0.05)


def test_hardness_above_peak_keeps_depth(rough):
    """H = 2 max p of the elastic solution: the same solution, to round-off."""
    z, elastic = rough
    capped = bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR,
                           hardness=2 * elastic.pressure.max())
    assert capped.depth == pytest.approx(elastic.depth, rel=1e-14, abs=0), "depth changed"


def test_hardness_above_peak_keeps_force(rough):
    z, elastic = rough
    capped = bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR,
                           hardness=2 * elastic.pressure.max())
    assert capped.force == pytest.approx(elastic.force, rel=1e-14, abs=0), "force changed"


def test_hardness_above_peak_keeps_pressure(rough):
    z, elastic = rough
    capped = bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR,
                           hardness=2 * elastic.pressure.max())
    difference = np.abs(capped.pressure - elastic.pressure).max()
    assert difference <= 1e-14 * elastic.pressure.max(), f"pressure changed by {difference:.2e}"


def test_hardness_above_peak_along_a_path(rough):
    """A load path that never reaches the cap gives the elastic load path's depths."""
    z, elastic = rough
    forces = [3e-4, 1e-3]
    hardness = 2 * elastic.pressure.max()
    capped = bem.load_path(z, forces, length=LENGTH, e_star=E_STAR, hardness=hardness)
    free = bem.load_path(z, forces, length=LENGTH, e_star=E_STAR)
    assert [s.depth for s in capped] == pytest.approx([s.depth for s in free], rel=1e-14), \
        "depths of the capped path differ from the elastic path"


def test_loading_equals_unloading_when_elastic(rough):
    """Without flow loading and unloading tangents coincide; the forward quotient's bias
    is ≈ rel_step/6 = 1.7e-4 (Hertz-like F ∝ d^(3/2))."""
    z, elastic = rough
    capped = bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR,
                           hardness=2 * elastic.pressure.max())
    assert bem.stiffness(capped, method="loading") == \
        pytest.approx(bem.stiffness(capped), rel=1e-3), "loading vs unloading stiffness"


def test_pressure_capped(capped_path):
    for state in capped_path:
        assert state.pressure.max() <= state.hardness, f"p > H at F = {state.force:g}"


def test_flow_happened(capped_path):
    assert capped_path[-1].plastic.sum() > 100, "the test load should make cells flow"


def test_plastic_displacement_non_negative(capped_path):
    for state in capped_path:
        assert state.plastic_displacement.min() >= 0.0, f"δ < 0 at F = {state.force:g}"


def test_plastic_displacement_only_on_plastic_cells(rough):
    """A single solve from the virgin surface: δ > 0 exactly on the cells that flowed."""
    z, _ = rough
    state = bem.solve(z, force=1e-3, length=LENGTH, e_star=E_STAR, hardness=0.05)
    assert np.array_equal(state.plastic_displacement > 0, state.plastic), \
        "plastic displacement off the plastic cells"


def test_plastic_displacement_on_cells_that_flowed_along_the_path(capped_path):
    """Along a path δ > 0 exactly on the cells that flowed at some state so far."""
    flowed = np.zeros_like(capped_path[0].plastic)
    for state in capped_path:
        flowed |= state.plastic
        assert np.array_equal(state.plastic_displacement > 0, flowed), \
            f"δ > 0 off the cells that flowed, at F = {state.force:g}"


def test_plastic_complementarity(capped_path):
    """Whole-grid gap after the flow: |g| ≤ tol·d on all contact cells (the plastic ones
    conform), g ≥ −tol·d elsewhere."""
    state = capped_path[-1]
    gap = state.gap()
    worst = max(np.abs(gap[state.contact]).max(), -gap[~state.contact].min())
    assert worst <= state.tol * state.depth, f"complementarity violated by {worst:.2e}"


def test_plastic_windowed_equals_full(rough, capped_path):
    z, _ = rough
    state = capped_path[-1]
    full = bem.solve(z, force=state.force, length=LENGTH, e_star=E_STAR, hardness=0.05,
                         windowed=False, plastic_displacement=capped_path[-2].plastic_displacement)
    assert state.window != full.window, "the test should compare a window with the full grid"
    assert full.depth == pytest.approx(state.depth, rel=1e-7), "windowed plastic depth differs"


def test_unloading_is_elastic(rough, capped_path):
    """A lower force after plastic loading: no new flow, δ unchanged, and the quotient
    (F − F₋)/(d − d₋) over 0.1 % of unloading equals the punch stiffness within 1e-3
    (no contact cell is lost over so small a step)."""
    z, _ = rough
    state = capped_path[-1]
    lower = bem.solve(z, force=state.force * (1 - 1e-3), length=LENGTH, e_star=E_STAR,
                          hardness=0.05, initial=state.pressure,
                          plastic_displacement=state.plastic_displacement)
    assert not lower.plastic.any(), "cells flowed on unloading"
    quotient = (state.force - lower.force) / (state.depth - lower.depth)
    assert quotient == pytest.approx(bem.stiffness(state), rel=1e-3), \
        "unloading quotient vs punch stiffness"


@pytest.mark.parametrize("n", [128, 129])
def test_periodic_capped_candidates_equal_whole_grid(n):
    """Periodic rough surface, H = 0.3 × the elastic peak: the candidate-cell solve equals the
    FFT solve on the whole grid (depths within the tolerance 1e-8)."""
    z = surfaces.self_affine(n, hurst=0.7, h_rms=9e-3, length=LENGTH, seed=3)
    elastic = bem.solve(z, force=3e-4, length=LENGTH, e_star=E_STAR, periodic=True)
    kwargs = {"force": 3e-4, "length": LENGTH, "e_star": E_STAR, "periodic": True,
              "hardness": 0.3 * elastic.pressure.max()}
    fast = bem.solve(z, **kwargs)
    full = bem.solve(z, windowed=False, **kwargs)
    assert fast.plastic.any(), "the test load should make cells flow"
    assert fast.depth == pytest.approx(full.depth, rel=1e-7), "candidate depth differs"


# --- against ContactMechanics ------------------------------------------------------------

#: Depths (length unit) at which ContactMechanics is run, in order (plastic flow carried).
CM_DEPTHS = (0.010, 0.015, 0.020)
CM_HARDNESS = 0.05
CM_TOL = 1e-10


@pytest.fixture(scope="module")
def contact_mechanics(rough):
    """ContactMechanics' plastic system, displacement-controlled at CM_DEPTHS, and our load
    path at its forces. Conventions as in benchmarks/peers.py: h = −(z − min z), offset = d,
    pixel forces f = p Δ²; its plastic displacement is −δ."""
    pytest.importorskip("ContactMechanics")
    from ContactMechanics import FreeFFTElasticHalfSpace
    from ContactMechanics.Factory import make_plastic_system
    from SurfaceTopography import PlasticTopography, Topography

    z, _ = rough
    n = z.shape[0]
    topography = PlasticTopography(Topography(-(z - z.min()), (LENGTH, LENGTH)), CM_HARDNESS)
    system = make_plastic_system(
        substrate=FreeFFTElasticHalfSpace((n, n), E_STAR, (LENGTH, LENGTH)), surface=topography)
    peer = []
    for depth in CM_DEPTHS:
        result = system.minimize_proxy(offset=depth, pentol=CM_TOL * depth, forcetol=1e-12,
                                       thermotol=CM_TOL, maxiter=100_000)
        assert result.success, f"ContactMechanics did not converge at d = {depth}"
        peer.append({"force": float(np.sum(result.jac)), "depth": depth,
                     "pressure": np.asarray(result.jac) / (LENGTH / n) ** 2,
                     "plastic_displacement": -topography.plastic_displ.copy()})
    ours = bem.load_path(z, [p["force"] for p in peer], length=LENGTH, e_star=E_STAR,
                             hardness=CM_HARDNESS, tol=CM_TOL)
    return list(zip(peer, ours))


def test_depth_matches_contact_mechanics(contact_mechanics):
    """At ContactMechanics' force our depth is its offset: both stop at 1e-10·d."""
    for peer, state in contact_mechanics:
        relative = state.depth / peer["depth"] - 1
        assert abs(relative) <= 1e-8, f"d = {peer['depth']}: depth differs by {relative:.2e}"


def test_force_matches_contact_mechanics(contact_mechanics):
    """Force at the same depth: our force at CM's depth differs from CM's by k·Δd with
    k ≤ the unloading stiffness (the loading one is smaller); relative bound 1e-7."""
    for peer, state in contact_mechanics:
        implied = bem.stiffness(state) * abs(state.depth - peer["depth"]) / peer["force"]
        assert implied <= 1e-7, f"d = {peer['depth']}: force differs by {implied:.2e}"


def test_plastic_cells_match_contact_mechanics(contact_mechanics):
    """ContactMechanics marks every cell with a negative gap as plastic, including elastic
    contact cells at round-off; the cells it moved by more than the tolerance tol·d are
    exactly ours."""
    previous = np.zeros_like(contact_mechanics[0][1].pressure)
    for peer, state in contact_mechanics:
        flowed = peer["plastic_displacement"] - previous > CM_TOL * peer["depth"]
        previous = peer["plastic_displacement"]
        differing = int(np.count_nonzero(flowed != state.plastic))
        assert differing == 0, (f"d = {peer['depth']}: {differing} of {int(flowed.sum())} "
                                f"plastic cells differ from ContactMechanics")


def test_plastic_displacement_matches_contact_mechanics(contact_mechanics):
    """Cumulative plastic displacement within 10·tol·d (both gaps are resolved to tol·d)."""
    for peer, state in contact_mechanics:
        difference = np.abs(state.plastic_displacement - peer["plastic_displacement"]).max()
        assert difference <= 10 * CM_TOL * peer["depth"], \
            f"d = {peer['depth']}: plastic displacement differs by {difference:.2e}"


def test_pressure_matches_contact_mechanics(contact_mechanics):
    """A gap error tol·d moves a cell's pressure by about E*·tol·d/(1.12 Δ) (the cell's
    self-compliance 4 ln(1+√2) Δ/(π E*)); bound: 10 times that."""
    for peer, state in contact_mechanics:
        n = state.pressure.shape[0]
        bound = 10 * E_STAR * CM_TOL * peer["depth"] / (1.12 * LENGTH / n)
        difference = np.abs(state.pressure - peer["pressure"]).max()
        assert difference <= bound, f"d = {peer['depth']}: pressure differs by {difference:.2e}"


# --- arguments -------------------------------------------------------------------------

@pytest.mark.parametrize("hardness", [0.0, -1.0, float("inf")])
def test_bad_hardness_rejected(hardness):
    z = surfaces.paraboloid(16, radius=0.5)
    with pytest.raises(ValueError, match="hardness"):
        bem.solve(z, force=1e-4, length=1.0, e_star=1.0, hardness=hardness)


def test_negative_plastic_displacement_rejected():
    z = surfaces.paraboloid(16, radius=0.5)
    with pytest.raises(ValueError, match="plastic_displacement"):
        bem.solve(z, force=1e-4, length=1.0, e_star=1.0, hardness=0.1,
                      plastic_displacement=-np.ones((16, 16)))


def test_central_difference_rejected_for_capped_state(capped_path):
    with pytest.raises(ValueError, match="elastic state"):
        bem.stiffness(capped_path[-1], method="difference")


def test_projected_gradient_steps_alone(rough, capped_path, monkeypatch):
    """With every step a projected-gradient step (bounded.GRADIENT_EVERY = 0: the steps the
    termination argument rests on, no conjugate-gradient step) the kernel reaches the same
    state: both meet the stopping test at tol = 1e-8, so their depths agree within ~tol."""
    z, _ = rough
    state = capped_path[0]
    monkeypatch.setattr(bounded, "GRADIENT_EVERY", 0)
    slow = bem.solve(z, force=state.force, length=LENGTH, e_star=E_STAR, hardness=0.05)
    assert slow.converged, f"projected gradients did not converge: {slow.diagnosis}"
    assert slow.depth == pytest.approx(state.depth, rel=1e-7), "projected-gradient depth differs"
