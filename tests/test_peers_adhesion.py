"""roughcontact's cohesive zone against tamaas' Maugis functional on the same rough sphere.

tamaas (2.9) adds adhesion to its Polonsky–Keer–Rey solver on the periodic half-space only, whose
operator coincides with roughcontact's ``PeriodicOperator`` to round-off; its
``MaugisAdhesionFunctional`` is the Dugdale law of :mod:`roughcontact.bem.cohesive` taken
literally, i.e. the ``"metastable"`` edge rule. The adapter and the convention mapping (mean gap
for the approach, ``rho = w/σ₀``) are ``TamaasAdhesionPeer`` in ``benchmarks/peers.py``.

The law is not convex: at an approach several states can satisfy it (cells at the zone's edge
that are consistent both inside and outside it), and each code's iteration picks one. Where the
two pick the same state — the same cells in contact and in the zone — it is the unique solution of
a convex problem with that zone, and the forces differ only by the solvers' tolerances (tamaas'
``1e-8`` on its own error, ours ``1e-10`` on the gap): measured 10⁻¹⁰–10⁻⁸ relative. Where they
pick different states the force differs by about the tension of the cells that differ,
``σ₀ Δx²`` each (measured 0.6–1.4 cells here, up to 5 on another seed).
"""

import math

import numpy as np
import pytest

pytest.importorskip("tamaas")

from roughcontact import surfaces  # noqa: E402
from roughcontact.bem.cohesive import cohesive_path  # noqa: E402
from roughcontact.models import adhesion  # noqa: E402
from test_peers import _load_peers  # noqa: E402  (benchmarks/peers.py, loaded once per use)

N = 80
LENGTH = 1.0
E_STAR = 1.0
RADIUS = 0.5
SEED = 1
#: Maugis' parameter 1, his length ℓ = (πwR²/K)^{1/3} 8 cells: a zone a few cells wide, 150-250 cells in all
LAMBDA = 1.0
ELL = 8 * LENGTH / N
#: Approach to 1 ℓ²/R and retract to −0.8 ℓ²/R, where a small contact is still held (tamaas' error
#: measure is undefined once nothing touches: such an approach runs to its iteration cap).
DEPTHS = np.concatenate([np.linspace(-0.5, 1.0, 4), np.linspace(1.0, -0.8, 8)[1:]])

#: Same state: forces equal to the solvers' tolerances (measured ≤ 1.5e-8 relative).
SAME_STATE_RTOL = 1e-6
#: Different states: at most this many cells' tension σ₀Δx² apart (measured ≤ 1.4).
CELLS = 3.0
#: tamaas' states satisfy the Dugdale law (measured ≤ 1e-9 σ₀).
LAW_RESIDUAL = 1e-7


def _problem(n: int, lam: float, ell: float, seed: int) -> dict:
    """The rough sphere of *seed* on ``n²`` and the Dugdale law of Maugis' *lam* at his length *ell*
    (``w`` from ``ℓ³ = πwR²/K``), the approaches DEPTHS in units of ``ℓ²/R``."""
    w = adhesion.maugis_work_of_adhesion(ell, radius=RADIUS, e_star=E_STAR)
    sigma = adhesion.maugis_cohesive_stress(lam, radius=RADIUS, e_star=E_STAR, work_of_adhesion=w)
    heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=0.7, h_rms=1e-3, length=LENGTH, seed=seed)
    return dict(heights=heights, depths=DEPTHS * ell**2 / RADIUS, work_of_adhesion=w, cohesive_stress=sigma)


def _ours(problem):
    return cohesive_path(problem["heights"], problem["depths"], length=LENGTH, e_star=E_STAR,
                         work_of_adhesion=problem["work_of_adhesion"], cohesive_stress=problem["cohesive_stress"],
                         periodic=True, edge_rule="metastable")


def _tamaas(problem):
    peer = _load_peers().TamaasAdhesionPeer(problem["heights"], length=LENGTH, e_star=E_STAR,
                                            work_of_adhesion=problem["work_of_adhesion"],
                                            cohesive_stress=problem["cohesive_stress"], tol=1e-8, max_iter=2000)
    return peer.path(problem["depths"])


@pytest.fixture(scope="module")
def problem():
    return _problem(N, LAMBDA, ELL, SEED)


@pytest.fixture(scope="module")
def ours(problem):
    return _ours(problem)


@pytest.fixture(scope="module")
def tamaas(problem):
    return _tamaas(problem)


def _cell_tension(problem):
    return problem["cohesive_stress"] * (LENGTH / N) ** 2


def test_tamaas_states_satisfy_the_dugdale_law(tamaas):
    assert tamaas.converged.all(), f"tamaas above its tolerance at approaches {np.flatnonzero(~tamaas.converged)}"
    assert tamaas.law_residual.max() <= LAW_RESIDUAL, f"law residual {tamaas.law_residual.max():.2e} σ₀"


def test_pull_off_matches_tamaas(problem, ours, tamaas):
    """Both reach the most tensile force at the same approach in the same state."""
    i, j = int(np.argmin(ours.force)), int(np.argmin(tamaas.force))
    assert i == j, f"pull-off at approach {i} here, {j} in tamaas"
    assert (ours.contact_cells[i], ours.zone_cells[i]) == (tamaas.contact_cells[i], tamaas.zone_cells[i])
    relative = abs(tamaas.pull_off_force / ours.pull_off_force - 1)
    assert relative <= SAME_STATE_RTOL, (
        f"pull-off {ours.pull_off_force!r} vs tamaas {tamaas.pull_off_force!r} (relative {relative:.2e})")


def test_force_at_first_touch_matches_tamaas(ours, tamaas):
    """The approach d = 0 (rigid bodies touching) on the loading: the same state in both."""
    i = int(np.flatnonzero(DEPTHS == 0.0)[0])
    assert (ours.contact_cells[i], ours.zone_cells[i]) == (tamaas.contact_cells[i], tamaas.zone_cells[i])
    relative = abs(tamaas.force[i] / ours.force[i] - 1)
    assert relative <= SAME_STATE_RTOL, f"force {ours.force[i]!r} vs tamaas {tamaas.force[i]!r} ({relative:.2e})"


def test_path_matches_tamaas_to_a_few_cells(problem, ours, tamaas):
    """Over the whole path the two differ at most by the tension of a few cells (the branch each
    picks where the law has several solutions)."""
    cells = np.abs(tamaas.force - ours.force) / _cell_tension(problem)
    assert cells.max() <= CELLS, f"force differences in cells' tension σ₀Δx²: {np.round(cells, 2)}"


#: The benchmark's interaction (``benchmarks/adhesion.py``), λ = 0.5, on a grid small enough for a test:
#: ℓ 12 cells, a zone around a contact up to 35 cells across, a pull-off of 1 000 cells' tension σ₀Δx².
HALF_N = 96
HALF_LAMBDA = 0.5
HALF_ELL = 12 * LENGTH / HALF_N
#: Issue #23's target for the pull-off (measured 5e-10 here: the same state at the same approach).
PULL_OFF_RTOL = 1e-3


@pytest.fixture(scope="module")
def half():
    problem = _problem(HALF_N, HALF_LAMBDA, HALF_ELL, seed=0)
    return _ours(problem), _tamaas(problem)


def test_pull_off_matches_tamaas_at_the_benchmarks_lambda(half):
    """λ = 0.5: the pull-offs to 10⁻³, over the approaches where tamaas converged (all but the last,
    −0.8 ℓ²/R, where no cell touches and its error measure is undefined)."""
    ours, tamaas = half
    assert tamaas.converged[:-1].all(), f"tamaas above its tolerance at {np.flatnonzero(~tamaas.converged)}"
    assert tamaas.law_residual[:-1].max() <= LAW_RESIDUAL
    pull_off = tamaas.force[tamaas.converged].min()
    relative = abs(ours.pull_off_force / pull_off - 1)
    assert relative <= PULL_OFF_RTOL, f"pull-off {ours.pull_off_force!r} vs tamaas {pull_off!r} ({relative:.2e})"
