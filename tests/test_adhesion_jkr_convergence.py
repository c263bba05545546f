"""The detachment criterion (roughcontact.bem.adhesion) against JKR as the contact grows in cells.

The smooth sphere on the free half-space, w set so that JKR's pull-off radius ``a_c`` is 10, 20 or 40
cells. Approaches are in units of ``a_c²/R``; the conjugate gradients stop at a relative residual of 1e-6
(the default 1e-10 gives the same pull-offs and a(F) errors to four digits at 10 to 40 cells, in twice
the time).

* The pull-off: loaded to 0.65 and 1.3 (the contact 1.15 ``a_c``), then retracted from -0.26 to -0.44 in
  steps of 0.01 (the least force is at -0.41, -0.33 and -0.31); grids of 2.5 ``a_c`` (25², odd, 50², 100²).
  Loading to 2 and retracting along the whole branch gives the same pull-off to four digits.
* The a(F) curve: loaded to 2 in four steps (the contact 1.46 ``a_c``), retracted from 0.5 to -0.2 in steps
  of 0.05 along JKR's branch and on through the pull-off as above; grids of 3.3, 3.2 and 3 ``a_c`` (33²,
  64², 120²).

Measured 2026-11-25 with these paths: the pull-off is 1.129, 1.060 and 1.028 times JKR's at 10, 20 and 40
cells (1.006 at 80 cells on 200², 4–5 min on this machine with or without the window of the contact,
whose box is most of that grid: not run here); the contact radius on the branch
exceeds JKR's a(F) by at most 6.1 %, 4.8 % and 1.1 %."""
from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from roughcontact.bem.adhesion import adhesive_path
from roughcontact.models import adhesion
from roughcontact.surfaces import paraboloid

#: the retract through the pull-off (a_c²/R)
PULL_OFF = np.linspace(-0.26, -0.44, 19)
#: the short loading before it, and the long loading and JKR's branch for a(F) (a_c²/R)
SHORT_LOAD = np.array([0.65, 1.3])
LONG_LOAD = np.linspace(0.5, 2.0, 4)
BRANCH = np.linspace(0.5, -0.2, 15)
#: a(F) is compared where the tension is below this fraction of JKR's pull-off: nearer it, da/dF of JKR's
#: branch diverges and the method's excess tension has no JKR radius at all
BRANCH_FORCE = 0.9
#: JKR's pull-off radius in cells: grid of the pull-off path, grid of the a(F) path
PULL_OFF_GRIDS = {10: 25, 20: 50, 40: 100}
BRANCH_GRIDS = {10: 33, 20: 64, 40: 120}
#: the pull-off / JKR's - 1 allowed: measured +12.9 %, +6.0 %, +2.8 % (above), plus 2 % at 10 cells and
#: 1.7 % at 20 and 40. The step of 0.01 a_c²/R misses the least force between two detachments: the method's
#: own pull-off (the force just before each detachment, found from the fixed contact's linear response) is
#: +13.5 %, +6.4 %, +3.5 %; the margin covers a different sampling of that saw-tooth on another platform.
PULL_OFF_TOLERANCE = {10: 0.15, 20: 0.077, 40: 0.045}
#: the largest |a / a_JKR(F) - 1| allowed: measured 6.1 %, 4.8 % and 1.1 %, plus 2 %, 2 % and 1 % (the path
#: samples the saw-tooth of the detachments at arbitrary phases: steps of 0.1 instead of 0.05 lower the
#: largest error by 2.6, 1.7 and 0.4 % at 10, 20 and 40 cells)
BRANCH_TOLERANCE = {10: 0.081, 20: 0.068, 40: 0.021}


def _sphere(cells: int, n: int):
    """``(heights, a_c, w, JKR's pull-off force)`` for JKR's pull-off radius of *cells* cells on ``n²``."""
    a_c = cells / n
    w = 8 * a_c**3 / (9 * math.pi)
    force, _ = adhesion.jkr_pull_off(radius=1.0, e_star=1.0, work_of_adhesion=w)
    return paraboloid(n, radius=1.0), a_c, w, force


def _path(z, depths, *, w):
    return adhesive_path(z, depths, length=1.0, e_star=1.0, work_of_adhesion=w, tol=1e-6)


def _jkr_radius(force: float, *, a_c: float, w: float) -> float:
    """JKR's contact radius at *force* on the stable branch (``a ≥ a_c``)."""
    def excess(a):
        return float(adhesion.jkr(a, radius=1.0, e_star=1.0, work_of_adhesion=w).force) - force
    return brentq(excess, a_c, 10 * a_c, xtol=1e-14 * a_c)


def _pull_off(cells: int, n: int):
    """``(pull-off / JKR's, index of the least force in PULL_OFF)``."""
    z, a_c, w, jkr = _sphere(cells, n)
    path = _path(z, np.concatenate([SHORT_LOAD, PULL_OFF]) * a_c**2, w=w)
    return path.pull_off_force / jkr, int(np.argmin(path.force)) - len(SHORT_LOAD)


def _branch_errors(cells: int, n: int) -> np.ndarray:
    """``a / a_JKR(F) - 1`` at the unloading states from the first detachment to the least force, where the
    tension is below BRANCH_FORCE of JKR's pull-off."""
    z, a_c, w, jkr = _sphere(cells, n)
    path = _path(z, np.concatenate([LONG_LOAD, BRANCH, PULL_OFF]) * a_c**2, w=w)
    loaded = len(LONG_LOAD)
    unload = slice(loaded, loaded + int(np.argmin(path.force[loaded:])) + 1)
    force, radius = path.force[unload], path.contact_radius[unload]
    use = (path.contact_cells[unload] < path.contact_cells[loaded - 1]) & (force >= BRANCH_FORCE * jkr)
    return np.array([r / _jkr_radius(f, a_c=a_c, w=w) - 1 for f, r in zip(force[use], radius[use])])


@pytest.fixture(scope="module")
def pull_offs():
    return {cells: _pull_off(cells, n) for cells, n in PULL_OFF_GRIDS.items()}


@pytest.fixture(scope="module")
def branches():
    return {cells: _branch_errors(cells, n) for cells, n in BRANCH_GRIDS.items()}


@pytest.mark.parametrize("cells", sorted(PULL_OFF_GRIDS))
def test_pull_off_is_inside_the_fine_steps(pull_offs, cells):
    """The least force lies inside the retract of 0.01 steps, not at its ends (else it is not resolved)."""
    _, index = pull_offs[cells]
    assert 0 < index < len(PULL_OFF) - 1, f"{cells} cells: least force at step {index} of {len(PULL_OFF)}"


@pytest.mark.parametrize("cells", sorted(PULL_OFF_TOLERANCE))
def test_pull_off_within_the_method_error(pull_offs, cells):
    ratio, _ = pull_offs[cells]
    assert abs(ratio - 1) <= PULL_OFF_TOLERANCE[cells], \
        f"{cells} cells: pull-off {ratio:.4f} x JKR, allowed 1 +- {PULL_OFF_TOLERANCE[cells]}"


def test_pull_off_error_decreases_with_the_cells(pull_offs):
    errors = [abs(pull_offs[cells][0] - 1) for cells in sorted(pull_offs)]
    assert all(fine < coarse for coarse, fine in itertools.pairwise(errors)), \
        f"pull-off errors at {sorted(pull_offs)} cells: {np.round(errors, 4).tolist()}"


def test_pull_off_on_odd_and_even_grids():
    """10 cells on 24² (apex off the grid's centre) and 25² (at it): the free half-space is translation
    invariant, so the same pull-off to the solves' tolerance."""
    odd, _ = _pull_off(10, 25)
    even, _ = _pull_off(10, 24)
    assert even == pytest.approx(odd, rel=1e-5), f"pull-off / JKR: 24² {even:.6f}, 25² {odd:.6f}"


@pytest.mark.parametrize("cells", sorted(BRANCH_GRIDS))
def test_branch_has_states_to_compare(branches, cells):
    assert branches[cells].size >= 5, f"{cells} cells: {branches[cells].size} states on JKR's branch"


@pytest.mark.parametrize("cells", sorted(BRANCH_TOLERANCE))
def test_contact_radius_follows_jkr(branches, cells):
    worst = float(np.max(np.abs(branches[cells])))
    assert worst <= BRANCH_TOLERANCE[cells], \
        f"{cells} cells: a(F) up to {worst:.2%} from JKR's, allowed {BRANCH_TOLERANCE[cells]:.1%}"


def test_contact_radius_error_decreases_with_the_cells(branches):
    worst = [float(np.max(np.abs(branches[cells]))) for cells in sorted(branches)]
    assert all(fine < coarse for coarse, fine in itertools.pairwise(worst)), \
        f"largest a(F) errors at {sorted(branches)} cells: {np.round(worst, 4).tolist()}"
