"""Convergence fuzzed for every kernel: load paths drawn over each kernel's parameter space.

Every test draws load paths with hypothesis and asserts that the kernel converges at every load;
where a closed form exists (a smooth sphere, a flat punch at the cap) it checks the answer too,
within a bound set by the grid (the bound's measurement is in the test's docstring).

What is drawn (:class:`Surface`, :func:`surfaces_of`): grids of ``n = 33 … 129`` cells a side (odd
and even), ``L = E* = 1``; smooth spheres (:func:`roughcontact.surfaces.paraboloid`), rough spheres
(:func:`~roughcontact.surfaces.rough_sphere`) and nominally flat rough surfaces
(:func:`~roughcontact.surfaces.self_affine`) with ``H = 0.1 … 0.9``, ``R = 0.25 … 1 L``,
``h_rms = 3·10⁻³ … 2·10⁻² L`` (log-uniform) and a random seed; the free or the periodic
half-space (flat surfaces: periodic only); a handful of loads (3 to 6, log-spaced over up to three
decades below the largest, in drawn order or sorted: loading and unloading; an adhesive path's
loading and retract, a Maugis–Dugdale path's approaches), and the kernel's own parameters (hardness,
work of adhesion, Maugis' λ, ν, μ, traction components, slip fractions).

Kernels: the elastic solve on the free (:func:`test_elastic_free`) and periodic
(:func:`test_elastic_periodic`) half-space; the hardness-capped solve through the public
``hardness=`` (:func:`test_hardness_capped`); the detachment-criterion adhesion
(:func:`test_detachment_adhesion`, :mod:`roughcontact.bem.adhesion`) and the Maugis–Dugdale
cohesive zone (:func:`test_maugis_dugdale`, :mod:`roughcontact.bem.cohesive`); the tangential
full-stick stiffness (:func:`test_full_stick`) and partial slip (:func:`test_partial_slip`).

Each drawn path is solved as drawn and once more with the heights multiplied by
``1 + 10⁻¹⁵ ξ`` (:func:`perturbed`; ``ξ`` a standard normal field seeded by the draw): a change at
round-off that breaks the ties of equal heights (the rings of a paraboloid, the flat face of a
punch) and must change nothing about convergence. Convergence means ``converged`` on every
:class:`~roughcontact.bem.ContactState`; for the kernels that raise
:class:`~roughcontact.errors.ConvergenceError` instead (adhesion, the tangential solves), that no
error is raised and every state meets its tolerance. A drawn path whose contact reaches the edge of
a free grid (:class:`~roughcontact.errors.DomainTooSmallError`, as drawn) is outside the solver's
domain and rejected (``hypothesis.reject``), not counted.

Runs. Quick (the default, part of the quick subset ``-m "not slurm and not workflow"``):
:data:`QUICK` paths per kernel (262 in all), derandomized (the same draws on every run), no
shrinking; 25–40 s for the file on two shared cores (2026-12-03). Long::

    ROUGHCONTACT_FUZZ_EXAMPLES=2000 python -m pytest tests/test_kernel_fuzz.py -q

draws that many paths per kernel at random (``--hypothesis-seed=N`` replays a run; a failure prints
its ``@reproduce_failure`` blob), shrinking a failure to a smaller one, and leaves the explicit
examples (draws that failed once) to the quick run; ``-k capped`` (or another
kernel's name: ``elastic``, ``detachment``, ``maugis``, ``full_stick``, ``partial_slip``) runs one
kernel. 200 paths per kernel took 7 min on two shared cores, so 2000 take more than an hour.
docs/guide/solver.md, "Convergence fuzzing".
"""
from __future__ import annotations

import dataclasses
import math
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, example, given, reject, settings
from hypothesis import strategies as st

from roughcontact import bem, surfaces
from roughcontact.bem.adhesion import adhesive_force_path, adhesive_path
from roughcontact.bem.cohesive import cohesive_path
from roughcontact.errors import DomainTooSmallError
from roughcontact.models import adhesion as adhesion_models
from roughcontact.models import paper
from roughcontact.models import tangential as tangential_models
from roughcontact.models.rough_adhesion import jkr_critical_approach

#: Paths per kernel of the quick run (derandomized); ``ROUGHCONTACT_FUZZ_EXAMPLES`` replaces them all.
QUICK = {"elastic_free": 60, "elastic_periodic": 50, "capped": 100, "detachment": 10, "maugis_dugdale": 10,
         "full_stick": 20, "partial_slip": 12}
#: Relative size of the perturbation of the heights (:func:`perturbed`).
NOISE = 1e-15
E_STAR = 1.0
LENGTH = 1.0
_LONG = os.environ.get("ROUGHCONTACT_FUZZ_EXAMPLES")


def fuzz(kernel: str):
    """The hypothesis settings of one kernel's test: the explicit examples and :data:`QUICK`
    derandomized paths without shrinking, or ``ROUGHCONTACT_FUZZ_EXAMPLES`` random ones with shrinking
    and without the explicit examples (the quick run's; a known failure would end the search at once)."""
    common = dict(deadline=None, database=None, suppress_health_check=[HealthCheck.too_slow])
    if _LONG:
        return settings(max_examples=int(_LONG), derandomize=False, print_blob=True,
                        phases=(Phase.generate, Phase.target, Phase.shrink), **common)
    return settings(max_examples=QUICK[kernel], derandomize=True,
                    phases=(Phase.explicit, Phase.generate), **common)


# --- what is drawn -------------------------------------------------------------------------------

@dataclasses.dataclass(frozen=True)
class Surface:
    """One drawn surface: ``kind`` ``"smooth"`` (paraboloid), ``"rough"`` (rough sphere),
    ``"flat"`` (self-affine, periodic) or ``"punch"`` (a flat-ended cylinder of radius ``radius``)."""

    n: int
    kind: str
    hurst: float
    radius: float
    h_rms: float
    seed: int

    @property
    def spacing(self) -> float:
        return LENGTH / self.n

    def heights(self) -> np.ndarray:
        if self.kind == "smooth":
            return surfaces.paraboloid(self.n, radius=self.radius, length=LENGTH)
        if self.kind == "rough":
            return surfaces.rough_sphere(self.n, radius=self.radius, hurst=self.hurst, h_rms=self.h_rms,
                                         length=LENGTH, seed=self.seed)
        if self.kind == "flat":
            return surfaces.self_affine(self.n, hurst=self.hurst, h_rms=self.h_rms, length=LENGTH, seed=self.seed)
        if self.kind == "punch":
            return np.where(surfaces.radial_distance(self.n, LENGTH) <= self.radius, 0.0, LENGTH)
        raise ValueError(self.kind)

    def rms_slope(self) -> float:
        """``√⟨|∇z|²⟩`` of the roughness (:func:`roughcontact.surfaces.self_affine_moments`)."""
        return math.sqrt(2 * surfaces.self_affine_moments(self.hurst, h_rms=self.h_rms, n=self.n,
                                                          length=LENGTH).m2)


def perturbed(heights: np.ndarray, seed: int) -> np.ndarray:
    """*heights* × (1 + :data:`NOISE` ξ), ξ a standard normal field of the seed *seed*."""
    return heights * (1.0 + NOISE * np.random.default_rng(seed).standard_normal(heights.shape))


def variants(surface: Surface):
    """``(name, heights)``: the drawn heights, then the perturbed ones."""
    z = surface.heights()
    return (("as drawn", z), ("perturbed", perturbed(z, surface.seed)))


GRIDS = st.integers(min_value=33, max_value=129)
HURSTS = st.floats(min_value=0.1, max_value=0.9)
RADII = st.floats(min_value=0.25, max_value=1.0)
H_RMS = st.floats(min_value=math.log10(3e-3), max_value=math.log10(2e-2)).map(lambda e: 10.0**e)
SEEDS = st.integers(min_value=0, max_value=2**16)


@st.composite
def surfaces_of(draw, kinds=("smooth", "rough", "flat")):
    """A :class:`Surface` of one of *kinds* with the module's ranges (a punch: its face's radius
    0.05 … 0.25 L)."""
    kind = draw(st.sampled_from(kinds))
    radius = draw(st.floats(min_value=0.05, max_value=0.25)) if kind == "punch" else draw(RADII)
    return Surface(n=draw(GRIDS), kind=kind, hurst=draw(HURSTS), radius=radius, h_rms=draw(H_RMS),
                   seed=draw(SEEDS))


@st.composite
def loads(draw, largest: float, *, decades: float = 3.0, sizes=(3, 6)):
    """3 to 6 forces log-spaced within *decades* below *largest*, in drawn order or sorted."""
    fractions = draw(st.lists(st.floats(min_value=0.0, max_value=1.0), min_size=sizes[0], max_size=sizes[1]))
    forces = [largest * 10.0 ** (-decades * (1.0 - x)) for x in fractions]
    return sorted(forces) if draw(st.booleans()) else forces


def hertz_force(contact_radius: float, radius: float) -> float:
    """The force at which Hertz's contact radius (:func:`roughcontact.models.paper.hertz_contact_radius`)
    is *contact_radius*: its inverse, ``F = 4E*a³/(3R)``."""
    return 4 * E_STAR * contact_radius**3 / (3 * radius)


#: The largest Hertz contact radius of a sphere's loads (L): the rough contact, wider, stays off the
#: free grid's edge at every drawn roughness.
LARGEST_CONTACT = 0.2


def largest_load(surface: Surface, periodic: bool) -> float:
    """The largest force of a drawn elastic path: a sphere's Hertz contact radius
    :data:`LARGEST_CONTACT`; a flat surface's mean pressure 0.05 E* h' (h' the rms slope: some 10 %
    of the surface in contact)."""
    if surface.kind == "flat":
        return 0.05 * E_STAR * surface.rms_slope() * LENGTH**2
    return hertz_force(LARGEST_CONTACT * LENGTH, surface.radius)


@st.composite
def elastic_paths(draw, kinds, periodic):
    """``(surface, periodic, forces)`` of an elastic path; *periodic* a bool or None (drawn)."""
    surface = draw(surfaces_of(kinds))
    if periodic is None:
        periodic = surface.kind == "flat" or draw(st.booleans())
    return surface, periodic, draw(loads(largest_load(surface, periodic)))


def solve_path(z, forces, **kwargs):
    return bem.load_path(z, forces, length=LENGTH, e_star=E_STAR, **kwargs)


def first_solve(solve, *args, **kwargs):
    """*solve* of the path as drawn; a contact that reaches a free grid's edge rejects the draw."""
    try:
        return solve(*args, **kwargs)
    except DomainTooSmallError:
        reject()


def assert_converged(states, what: str) -> None:
    failed = [(i, s.force, s.iterations, s.gap_error) for i, s in enumerate(states) if not s.converged]
    assert not failed, (f"{what}: not converged at {len(failed)} of {len(states)} loads "
                        f"(index, force, iterations, gap error): {failed}")


def assert_hertz(state, surface: Surface, what: str) -> None:
    """Depth against Hertz's (:func:`roughcontact.models.paper.hertz_approach`, i.e. F = (4/3) E*
    R^½ d^(3/2)) within 0.2 (Δ/a)², ``a`` Hertz's contact radius: the discretisation error of a
    paraboloid is second order in the cell over the contact radius (tests/test_contact.py), measured
    (2026-12-03, n = 33 … 128, R = 0.25 … 1, a = 1 … 32 cells) at most 0.08 (Δ/a)²."""
    expected = paper.hertz_approach(state.force, radius=surface.radius, e_star=E_STAR)
    a = paper.hertz_contact_radius(state.force, radius=surface.radius, e_star=E_STAR)
    bound = 0.2 * (surface.spacing / a) ** 2
    deviation = state.depth / expected - 1
    assert abs(deviation) <= bound, (f"{what}: depth {state.depth:.6g} vs Hertz {expected:.6g} at F = "
                                     f"{state.force:.4g} (a = {a / surface.spacing:.1f} cells): "
                                     f"{deviation:+.2e}, bound {bound:.2e}")


# --- elastic ------------------------------------------------------------------------------------

@fuzz("elastic_free")
@given(elastic_paths(kinds=("smooth", "rough"), periodic=False))
def test_elastic_free(path):
    """Spheres, smooth and rough, on the free half-space: every load converges; a smooth sphere
    follows Hertz (:func:`assert_hertz`)."""
    surface, periodic, forces = path
    for i, (name, z) in enumerate(variants(surface)):
        what = f"{surface}, {name}, forces {forces}"
        states = first_solve(solve_path, z, forces) if i == 0 else solve_path(z, forces)
        assert_converged(states, what)
        if surface.kind == "smooth":
            for state in states:
                assert_hertz(state, surface, what)


@fuzz("elastic_periodic")
@given(elastic_paths(kinds=("smooth", "rough", "flat"), periodic=True))
def test_elastic_periodic(path):
    """Nominally flat rough surfaces and spheres on the periodic half-space: every load converges."""
    surface, periodic, forces = path
    for name, z in variants(surface):
        assert_converged(solve_path(z, forces, periodic=True), f"{surface}, {name}, forces {forces}")


# --- hardness-capped ----------------------------------------------------------------------------

#: The largest ``F/(H A)`` of a punch of face ``A`` (:func:`capped_paths`).
FULL = 1 - 1e-9
#: The largest fully plastic footprint ``F/H`` of a drawn capped path (L²): a disc of radius 0.2 L on
#: the free grid, half the grid on the periodic one (below it, a state with ``p ≤ H`` exists).
PLASTIC_AREA = {False: math.pi * 0.2**2, True: 0.5}


@st.composite
def capped_paths(draw):
    """``(surface, periodic, hardness, forces)``: ``H/E*`` log-uniform in 10⁻⁴ … 1; the largest
    force the smaller of the elastic path's (:func:`largest_load`) and ``H`` × :data:`PLASTIC_AREA`;
    a punch of face ``A`` is pressed with ``θ H A``, ``θ = 0.05 … 1 − 10⁻⁹`` (:data:`FULL`: the face
    all but at the cap; at ``θ = 1`` a round-off excess of the force would need a cell off the face)."""
    surface = draw(surfaces_of(("smooth", "rough", "flat", "punch")))
    hardness = 10.0 ** draw(st.floats(min_value=-4.0, max_value=0.0))
    if surface.kind == "punch":
        face = np.count_nonzero(surface.heights() == 0.0) * surface.spacing**2
        thetas = st.lists(st.one_of(st.just(FULL), st.floats(min_value=0.05, max_value=FULL)), min_size=2, max_size=5)
        return surface, False, hardness, [theta * hardness * face for theta in draw(thetas)]
    periodic = surface.kind == "flat" or draw(st.booleans())
    largest = min(largest_load(surface, periodic), hardness * PLASTIC_AREA[periodic] * LENGTH**2)
    return surface, periodic, hardness, draw(loads(largest))


def check_capped(states, surface: Surface, periodic: bool, hardness: float, what: str) -> None:
    """Convergence; ``p ≤ H``; a state with every contact cell at the cap carries ``F = H A``; a
    punch (its face ``A``, the rest one ``L`` higher) carries ``F < H A`` on its face alone, at a depth
    below ``L``, however near ``F`` is to ``H A`` (the face then all but at the cap); a smooth sphere that
    has not flowed is Hertz's."""
    assert_converged(states, what)
    face = surface.heights() == 0.0
    for state in states:
        assert state.pressure.max() <= hardness, f"{what}: p = {state.pressure.max():.17g} > H at F = {state.force:g}"
        if np.all(state.pressure[state.contact] == hardness):
            assert state.force == pytest.approx(hardness * state.contact_area, rel=1e-12), \
                f"{what}: every contact cell at the cap, but F = {state.force:.17g} != H A"
        if surface.kind == "punch":
            off = np.count_nonzero(state.contact & ~face)
            share = state.force / (hardness * np.count_nonzero(face) * state.cell_area)
            assert not off and state.depth < LENGTH, \
                f"{what}: F = {share:.12f} H A, but {off} cells off the face in contact, depth {state.depth:.6g}"
        if surface.kind == "smooth" and not periodic and not np.any(state.plastic_displacement):
            assert_hertz(state, surface, what)


@fuzz("capped")
@given(capped_paths())
# Draws that failed, kept: the kernel before 1ccd172 stalled at 10 000 iterations on the last load of
# the perturbed path (gap error 1.09e-8 against tol 1e-8; the long run, 2026-12-03) ...
@example(path=(Surface(n=68, kind="flat", hurst=0.2574695499682754, radius=1.0, h_rms=0.01, seed=2), True, 0.1,
               [2.6802446047708025e-05, 0.0008475677637453536, 0.026802446047708026]))
# ... and the kernel of 1ccd172 refused the third load, a candidate set of fewer than F/H cells (fixed in c5861e1)
@example(path=(Surface(n=111, kind="flat", hurst=0.2563015872631935, radius=0.2904618854353566,
                       h_rms=0.01624446520733232, seed=0), True, 0.1,
               [0.0016657564397559992, 0.0015811388300841897, 0.03879300306526304, 0.002199035533620935, 5e-05,
                0.019504029360016523]))
# ... and on the perturbed paraboloid on the periodic grid, a plastic contact of 9 cells (45), it stopped after one
# (15) iterations at a gap error of 0.345 (0.069), "no step decreases the energy in floating point": a ring of equal
# heights left a hair below the cap (the long runs --hypothesis-seed=1 and 4, 2026-12-03; fixed in 8be63e0)
@example(path=(Surface(n=126, kind="smooth", hurst=0.5, radius=1.0, h_rms=0.01, seed=0), True, 0.00031622776601683794,
               [1.5811388300841899e-07, 1.5811388300841899e-07, 1.5811388300841899e-07]))
@example(path=(Surface(n=33, kind="smooth", hurst=0.5, radius=0.5299969461104379, h_rms=0.01, seed=0), True,
               0.04025356947999736, [0.001636483408000323, 2.0125902130092665e-05, 2.0125902130092665e-05]))
def test_hardness_capped(path):
    """Penetration-hardness plasticity through ``hardness=``: every load converges, ``p ≤ H``,
    and the closed forms of :func:`check_capped`."""
    surface, periodic, hardness, forces = path
    for i, (name, z) in enumerate(variants(surface)):
        what = f"{surface}, periodic={periodic}, H={hardness!r}, {name}, forces {forces}"
        kwargs = dict(periodic=periodic, hardness=hardness, edge_contact=surface.kind == "punch")
        states = first_solve(solve_path, z, forces, **kwargs) if i == 0 else solve_path(z, forces, **kwargs)
        check_capped(states, surface, periodic, hardness, what)


# --- adhesion -----------------------------------------------------------------------------------

@st.composite
def adhesive_spheres(draw):
    """``(surface, periodic, cells)``: a sphere, smooth or rough, free or periodic, and a length
    of the adhesion in cells (JKR's pull-off radius, Maugis' ℓ) of 3 … n/12."""
    surface = draw(surfaces_of(("smooth", "rough")))
    periodic = draw(st.booleans())
    cells = draw(st.floats(min_value=3.0, max_value=max(3.0, surface.n / 12)))
    return surface, periodic, cells


@st.composite
def detachment_paths(draw):
    """Loading to 3 … 6 forces of 0.2 … 4 |P_JKR| (force control, rising: the pipeline's loading), then
    retracting to 3 JKR pull-off approaches beyond first touch in 20 … 50 steps, w such that JKR's
    pull-off radius is the drawn number of cells."""
    surface, periodic, cells = draw(adhesive_spheres())
    a_c = cells * surface.spacing
    work = 8 * E_STAR * a_c**3 / (9 * math.pi * surface.radius**2)   # jkr_pull_off's a³ = 9πwR²/(8E*)
    pull_off, _ = adhesion_models.jkr_pull_off(radius=surface.radius, e_star=E_STAR, work_of_adhesion=work)
    forces = sorted(draw(loads(4 * abs(pull_off), decades=math.log10(20))))
    return surface, periodic, work, forces, draw(st.integers(min_value=20, max_value=50))


@fuzz("detachment")
@given(detachment_paths())
def test_detachment_adhesion(path):
    """The detachment criterion (:mod:`roughcontact.bem.adhesion`) along the adhesive run's two paths
    (:mod:`roughcontact.study.runs.adhesive`): every target force is reached and every approach
    settles (no :class:`~roughcontact.errors.ConvergenceError`). A smooth free sphere preloaded
    beyond 1.5 |P_JKR| pulls off at JKR's ``−(3/2)πwR`` within 3 Δ/a_c (``a_c`` JKR's pull-off
    radius): the module's convergence is first order in the cell (+13 % at 10 cells), and the retract
    path's steps sample the cell-by-cell detachment; measured (2026-12-03, 310 random draws of this
    test's smooth free spheres, 3 … 10.7 cells) at most 1.6 Δ/a_c. (At 3 cells the bound only
    catches a pull-off of the wrong size: the check is of the kernel, not of the method's accuracy.)"""
    surface, periodic, work, forces, steps = path
    common = dict(length=LENGTH, e_star=E_STAR, work_of_adhesion=work, periodic=periodic)
    d_ref = float(paper.hertz_approach(max(forces), radius=surface.radius, e_star=E_STAR)) + 3 * surface.h_rms
    back = -3 * jkr_critical_approach(radius=surface.radius, e_star=E_STAR, work_of_adhesion=work)
    for i, (name, z) in enumerate(variants(surface)):
        what = f"{surface}, periodic={periodic}, w={work!r}, {name}, forces {forces}, {steps} steps"
        loading = first_solve(adhesive_force_path, z, forces, step=d_ref / 100, **common) if i == 0 else \
            adhesive_force_path(z, forces, step=d_ref / 100, **common)
        assert loading.depth.size == len(forces), f"{what}: {loading.depth.size} of {len(forces)} loads reached"
        np.testing.assert_allclose(loading.force, forces, rtol=1e-6, err_msg=what)
        depths = np.r_[loading.depth, np.linspace(loading.depth[-1], back, steps)[1:]]
        retract = first_solve(adhesive_path, z, depths, **common) if i == 0 else adhesive_path(z, depths, **common)
        assert retract.depth.size == depths.size, what
        if surface.kind == "smooth" and not periodic and max(forces) >= 1.5 * abs(
                adhesion_models.jkr_pull_off(radius=surface.radius, e_star=E_STAR, work_of_adhesion=work)[0]):
            jkr, a_c = adhesion_models.jkr_pull_off(radius=surface.radius, e_star=E_STAR, work_of_adhesion=work)
            bound = 3.0 * surface.spacing / a_c
            assert abs(retract.pull_off_force / jkr - 1) <= bound, \
                f"{what}: pull-off {retract.pull_off_force / jkr:.4f} x JKR, bound {bound:.3f}"


@st.composite
def maugis_paths(draw):
    """Maugis' λ log-uniform in 0.1 … 3, ℓ the drawn cells; approaches from −1 to 1 … 2 ℓ²/R in
    4 … 8 steps and back to −1.5 ℓ²/R in 15 … 40."""
    surface, periodic, cells = draw(adhesive_spheres())
    lam = 10.0 ** draw(st.floats(min_value=-1.0, max_value=math.log10(3.0)))
    ell = cells * surface.spacing
    work = adhesion_models.maugis_work_of_adhesion(ell, radius=surface.radius, e_star=E_STAR)
    stress = adhesion_models.maugis_cohesive_stress(lam, radius=surface.radius, e_star=E_STAR, work_of_adhesion=work)
    top = draw(st.floats(min_value=1.0, max_value=2.0))
    unit = ell**2 / surface.radius
    depths = np.r_[np.linspace(-1, top, draw(st.integers(4, 8))), np.linspace(top, -1.5, draw(st.integers(15, 40)))]
    return surface, periodic, lam, cells, work, stress, depths * unit


@fuzz("maugis_dugdale")
@given(maugis_paths())
def test_maugis_dugdale(path):
    """The Maugis–Dugdale cohesive zone (:mod:`roughcontact.bem.cohesive`, energy edge rule) along a
    load–unload path: every approach settles (no :class:`~roughcontact.errors.ConvergenceError`). A
    smooth free sphere pulls off at Maugis' force (:func:`roughcontact.models.adhesion.maugis_dugdale_pull_off`)
    within 0.6 Δ/(c − a), ``c − a = (m − 1) ā ℓ`` the width of Maugis' cohesive zone at pull-off: the
    error is first order in the cell over the zone's width (module docstring), measured (2026-12-03,
    370 random draws of this test's smooth free spheres, ℓ = 3 … 10.7 cells, λ = 0.1 … 3) at most
    0.32 Δ/(c − a) (and 21 %, at a zone of 2 cells)."""
    surface, periodic, lam, cells, work, stress, depths = path
    common = dict(length=LENGTH, e_star=E_STAR, work_of_adhesion=work, cohesive_stress=stress, periodic=periodic)
    for i, (name, z) in enumerate(variants(surface)):
        what = f"{surface}, periodic={periodic}, lambda={lam!r}, ell={cells!r} cells, {name}"
        result = first_solve(cohesive_path, z, depths, **common) if i == 0 else cohesive_path(z, depths, **common)
        assert result.depth.size == depths.size, what
        if surface.kind == "smooth" and not periodic:
            pull_off = adhesion_models.maugis_dugdale_pull_off(lam)
            maugis = pull_off.force * math.pi * work * surface.radius
            bound = 0.6 / ((pull_off.m - 1) * pull_off.a * cells)
            assert abs(result.pull_off_force / maugis - 1) <= bound, \
                f"{what}: pull-off {result.pull_off_force / maugis:.4f} x Maugis', bound {bound:.3f}"


# --- tangential ---------------------------------------------------------------------------------

POISSON = st.floats(min_value=0.0, max_value=0.5)
#: ``Q/(μP)`` of a partial-slip load: 0 or 10⁻¹² … 0.95. (Fractions of 10⁻²⁰⁰ and below do not converge:
#: the tractions' squares underflow; found by this test, 2026-12-03, and left out as no physical load.)
SLIP_FRACTIONS = st.one_of(st.just(0.0), st.floats(min_value=1e-12, max_value=0.95))
COMPONENTS = st.sampled_from((1, 2))


@fuzz("full_stick")
@given(elastic_paths(kinds=("smooth", "rough", "flat"), periodic=None), POISSON, COMPONENTS)
def test_full_stick(path, poisson, components):
    """The full-stick tangential stiffness (:func:`roughcontact.bem.tangential_stiffness`) of every
    state of a normal path: the normal path converges and every stiffness solve converges (no
    :class:`~roughcontact.errors.ConvergenceError`) to a finite positive value. A smooth free
    sphere's ``k_t/k_n`` is Mindlin's ``2(1 − ν)/(2 − ν)``
    (:func:`roughcontact.models.tangential.stiffness_ratio`) within 0.03 Δ/a, ``a = √(A/π)`` from 2 cells
    (a smaller contact is a cell or a few, not a circle): tests/test_tangential_sphere.py's
    0.02 Δ/a (8 … 32 cells, one component), measured (2026-12-03, 2 … 32 cells, ν = 0 … 0.5, one
    and two components) at most 0.014 Δ/a."""
    surface, periodic, forces = path
    for i, (name, z) in enumerate(variants(surface)):
        what = f"{surface}, periodic={periodic}, nu={poisson!r}, {components} components, {name}, forces {forces}"
        states = first_solve(solve_path, z, forces, periodic=periodic) if i == 0 else \
            solve_path(z, forces, periodic=periodic)
        assert_converged(states, what)
        for state in states:
            k_t = bem.tangential_stiffness(state, poisson=poisson, components=components)
            assert math.isfinite(k_t) and k_t > 0, f"{what}: k_t = {k_t} at F = {state.force:g}"
            a = math.sqrt(state.contact_area / math.pi)
            if surface.kind == "smooth" and not periodic and a >= 2 * surface.spacing:
                ratio = k_t / bem.stiffness(state) / tangential_models.stiffness_ratio(poisson)
                assert abs(ratio - 1) <= 0.03 * surface.spacing / a, \
                    f"{what}: k_t/k_n {ratio:.6f} x Mindlin's at a = {a / surface.spacing:.1f} cells"


@fuzz("partial_slip")
@given(elastic_paths(kinds=("smooth", "rough", "flat"), periodic=None), POISSON, COMPONENTS,
       st.floats(min_value=0.1, max_value=1.0),
       st.lists(SLIP_FRACTIONS, min_size=2, max_size=6).map(sorted))
def test_partial_slip(path, poisson, components, friction, fractions):
    """Cattaneo–Mindlin partial slip (:func:`roughcontact.bem.partial_slip`) along ``Q = f μP`` at the
    last two loads of a normal path: every tangential load converges (no
    :class:`~roughcontact.errors.ConvergenceError`; ``error ≤ tol``) and carries ``Q = f μP``. A
    smooth free sphere's tangent ``k_t(Q)/k_t(0)`` is Cattaneo–Mindlin's ``(1 − f)^(1/3)``
    (:func:`roughcontact.models.tangential.cattaneo_stiffness_ratio`), where its contact radius is 3 cells
    or more (below, the stick zone is a few cells that stick or slip whole), within half a cell of the stick
    radius ``c``, 0.5 Δ/c (tests/test_tangential_sphere.py's half-cell bound of ``c``), measured
    (2026-12-03, a = 3 … 24 cells, one and two components) at most 0.28 Δ/c."""
    surface, periodic, forces = path
    for i, (name, z) in enumerate(variants(surface)):
        what = (f"{surface}, periodic={periodic}, nu={poisson!r}, mu={friction!r}, {components} components, "
                f"{name}, forces {forces}, fractions {fractions}")
        states = first_solve(solve_path, z, forces, periodic=periodic) if i == 0 else \
            solve_path(z, forces, periodic=periodic)
        assert_converged(states, what)
        for state in states[-2:]:
            slip = bem.partial_slip(state, fractions, friction=friction, poisson=poisson, components=components)
            for s in slip.states:
                assert s.converged and s.error <= state.tol, f"{what}: f = {s.fraction}, error {s.error:.2e}"
            np.testing.assert_allclose(slip.forces, np.asarray(fractions) * friction * state.force, rtol=1e-12,
                                       atol=1e-300, err_msg=what)
            if surface.kind == "smooth" and not periodic and state.contact_area >= math.pi * (3 * surface.spacing) ** 2:
                measured = slip.stiffnesses / slip.full_stick_stiffness
                expected = tangential_models.cattaneo_stiffness_ratio(fractions)
                stick = np.sqrt(slip.stick_areas / math.pi)
                bound = 0.5 * surface.spacing / np.maximum(stick, surface.spacing)
                assert np.all(np.abs(measured / expected - 1) <= bound), \
                    f"{what}: k_t(Q)/k_t(0) / Cattaneo's - 1 = {measured / expected - 1} at F = {state.force:g}"
