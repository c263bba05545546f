"""Tangential contact of a smooth sphere on the BEM against Mindlin and Cattaneo–Mindlin
(Johnson 1985, §7.2), on odd and even grids and with non-unit L, E*, R."""
from __future__ import annotations

import numpy as np
import pytest

from roughcontact import bem, surfaces
from roughcontact.models import tangential as closed


def _sphere(n, cells, *, length=1.0, e_star=1.0, radius=1.0, periodic=False):
    """A paraboloid pressed to Hertz's contact radius of ``cells`` cells; (state, a, P)."""
    a = cells * length / n
    force = 4 * e_star * a**3 / (3 * radius)
    heights = surfaces.paraboloid(n, radius=radius, length=length)
    return bem.solve(heights, force=force, length=length, e_star=e_star, periodic=periodic), a, force


def _ratio_error(n, cells, nu):
    state, _, _ = _sphere(n, cells)
    ratio = bem.tangential_stiffness(state, poisson=nu) / bem.stiffness(state)
    return abs(ratio / closed.stiffness_ratio(nu) - 1)


@pytest.mark.parametrize("n_of", [lambda c: 4 * c + 1, lambda c: 4 * c], ids=["odd", "even"])
@pytest.mark.parametrize("nu", [0.3, 0.5])
def test_full_stick_ratio_converges(nu, n_of):
    """k_t/k_n → 2(1 − ν)/(2 − ν) as the contact radius grows from 8 to 32 cells. Both stiffnesses
    are exact solves on the same footprint, so the footprint's staircase error cancels to first
    order; what is left is O(Δ/a) (measured 2026-11-27: 1.5e-4, 7.2e-5, 3.5e-5 at ν = 0.3 and
    5.4e-4, 2.6e-4, 1.3e-4 at ν = 0.5 for a = 8, 16, 32 cells). Bound: 0.02 Δ/a at each size,
    and the error falls by at least a third per doubling of a."""
    errors = [_ratio_error(n_of(c), c, nu) for c in (8, 16, 32)]
    for cells, error in zip((8, 16, 32), errors):
        assert error <= 0.02 / cells, (cells, errors)
    assert errors[1] <= (2 / 3) * errors[0], errors
    assert errors[2] <= (2 / 3) * errors[1], errors


@pytest.mark.parametrize("n", [33, 32])
def test_full_stick_ratio_is_one_at_zero_poisson(n):
    """At ν = 0 the tangential kernel is the normal one: k_t = k_n to the solves' tolerance
    (1e-8 relative residual; 1e-6 leaves room for the conditioning of the 8-cell disc)."""
    assert _ratio_error(n, 8, 0.0) <= 1e-6


@pytest.mark.parametrize("nu", [0.0, 0.3, 0.5])
def test_full_stick_against_mindlin(nu):
    """k_t against Mindlin's 8Ga/(2 − ν) with Hertz's a (L = 3, E* = 210, R = 5): the same
    discretization error as k_n against 2E*a, 0.15% at a = 32 cells (measured); bound 1%."""
    state, a, _ = _sphere(129, 32, length=3.0, e_star=210.0, radius=5.0)
    k_t = bem.tangential_stiffness(state, poisson=nu)
    assert k_t == pytest.approx(closed.mindlin_stiffness(a, e_star=210.0, poisson=nu), rel=0.01)


FRACTIONS = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
PHYSICAL = [dict(length=1.0, e_star=1.0, radius=1.0), dict(length=3.0, e_star=210.0, radius=5.0)]


@pytest.fixture(scope="module", params=[(49, 0, 2), (48, 0, 2), (49, 1, 2), (49, 0, 1)],
                ids=["odd", "even", "odd-units", "odd-one-component"])
def cattaneo(request):
    """A 12-cell sphere loaded to Q/μP = 0.1 … 0.9 at ν = 0.3, μ = 0.3, with two traction components
    (the default) and with one. Cattaneo–Mindlin is itself the one-component approximation for
    ν ≠ 0: two components differ from it by what that approximation leaves out (measured below)."""
    n, units, components = request.param
    physical = PHYSICAL[units]
    state, a, force = _sphere(n, 12, **physical)
    path = bem.partial_slip(state, FRACTIONS, friction=0.3, poisson=0.3, components=components)
    return state, a, force, path, physical


def test_stick_radius(cattaneo):
    """Stick radius √(A_stick/π) against c = a(1 − Q/μP)^(1/3), with a = √(A/π) of the same
    lattice: a disc of cells has its radius to a fraction of a cell (measured 2026-11-27 ≤ 0.1 cell
    at a = 12, 24, 48 cells with one component and with two); bound half a cell."""
    state, _, _, path, physical = cattaneo
    spacing = physical["length"] / state.heights.shape[0]
    a_lattice = np.sqrt(state.contact_area / np.pi)
    c = np.sqrt(path.stick_areas / np.pi)
    assert np.max(np.abs(c - closed.stick_radius(a_lattice, FRACTIONS))) <= 0.5 * spacing


def test_tangential_displacement(cattaneo):
    """δ_x(Q) against 3μP(2 − ν)/(16Ga)[1 − (1 − Q/μP)^(2/3)] with Hertz's a and the applied P:
    measured 2026-11-27 with one component 0.41 % at a = 12 cells, 0.033 % at 24, 0.015 % at 48;
    with two 0.40 %, 0.082 %, 0.083 %: two components converge to 0.084 % off Cattaneo–Mindlin,
    the size of its one-component approximation at ν = 0.3; bound (Δ/a)² = 0.7%."""
    state, a, force, path, physical = cattaneo
    expected = closed.cattaneo_displacement(FRACTIONS, normal_force=force, friction=0.3, contact_radius=a,
                                            e_star=physical["e_star"], poisson=0.3)
    assert np.max(np.abs(path.displacements / expected - 1)) <= (1 / 12) ** 2


def test_tangent_stiffness(cattaneo):
    """k_t(Q)/k_t(0) against (1 − Q/μP)^(1/3): one component, the stick zone's full-stick stiffness;
    two, the tangent with the slipping tractions free to turn on the cone. One cell of the stick
    radius (c ≥ 5.6 cells at Q/μP = 0.9) is ≤ 1/5.6 of it; measured 2026-11-27 1.1 % at a = 12 cells
    (both), 0.32 % and 0.63 % at 24, 0.15 % and 0.15 % at 48 (one, two components); bound 3%."""
    _, _, _, path, _ = cattaneo
    measured = path.stiffnesses / path.full_stick_stiffness
    assert np.max(np.abs(measured / np.cbrt(1 - FRACTIONS) - 1)) <= 0.03


def test_path_bookkeeping(cattaneo):
    """Each load meets its force and Coulomb's bound: Σ q Δ² = f μP, |q| ≤ μp, stick ∪ slip = contact;
    the sphere is symmetric about y = 0, so δ_y = 0 (to 1e-8 of δ_x)."""
    state, _, force, path, _ = cattaneo
    last = path.states[-1]
    assert path.forces == pytest.approx(FRACTIONS * 0.3 * force, rel=1e-12)
    assert np.all(np.hypot(last.traction, last.traction_y) <= 0.3 * state.pressure * (1 + 1e-12))
    assert all(abs(s.displacement_y) <= 1e-8 * s.displacement for s in path.states)
    assert np.array_equal(last.stick | last.slip, state.contact)


def test_periodic_sphere_ratio():
    """Periodic half-space, a = 16 cells on 128² (a/L = 1/8): k_t/k_n within 1% of Mindlin's ratio
    (the images change k_n and k_t alike by O(a/L); measured 2026-11-27: 1.2e-4, against 7.2e-5 on
    the free half-space)."""
    state, _, _ = _sphere(128, 16, periodic=True)
    ratio = bem.tangential_stiffness(state, poisson=0.3) / bem.stiffness(state)
    assert ratio == pytest.approx(closed.stiffness_ratio(0.3), rel=0.01)


@pytest.mark.parametrize("bad", [-1.0, 0.6, float("nan")])
def test_bad_poisson(bad):
    state, _, _ = _sphere(33, 4)
    with pytest.raises(ValueError, match="poisson"):
        bem.tangential_stiffness(state, poisson=bad)


@pytest.mark.parametrize("kwargs, key", [(dict(friction=-0.1), "friction"),
                                         (dict(friction=float("nan")), "friction"),
                                         (dict(fractions=[1.0]), "fractions"),
                                         (dict(fractions=[0.5, 0.2]), "fractions")])
def test_bad_slip_arguments(kwargs, key):
    state, _, _ = _sphere(33, 4)
    arguments = dict(fractions=[0.5], friction=0.3) | kwargs
    with pytest.raises(ValueError, match=key):
        bem.partial_slip(state, arguments.pop("fractions"), poisson=0.3, **arguments)
