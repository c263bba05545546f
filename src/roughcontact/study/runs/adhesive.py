"""The adhesive run of a generated surface (``work_of_adhesion`` > 0): load, retract, pull-off.

A run with a work of adhesion ``w`` presses its surface into a half-space that sticks by the
mesh-dependent detachment criterion of Pohrt & Popov (:mod:`roughcontact.bem.adhesion`):

The detachment criterion attracts nothing outside the contact: a cell joins when its gap
closes, so loading follows the non-adhesive path and the adhesion acts on retracting. The
pull-off therefore depends on the preload: the smooth sphere reaches JKR's pull-off only when the
largest load's contact is wider than JKR's pull-off radius ``a³ = 9πwR²/(8E*)`` (by Hertz, a
largest load above ``(9/4)πwR``); ``pull_off.csv`` reports the ratio of the two
(``preload_radius_ratio``).

1. **Loading**, force-controlled, to the study's loads (:func:`roughcontact.bem.adhesion.adhesive_force_path`,
   approach steps of :data:`LOAD_STEPS` per ``d_ref``, the smooth body's approach at the largest
   load plus ``3 h_rms``): per load the approach, the contact cells and area and the stiffness
   ``k = dF/dd`` of the contact set held fixed (the flat-punch stiffness of the contact,
   :func:`roughcontact.bem.punch.contact_stiffness`: what a small oscillation measures, which moves
   no crack front). The same variables, over ``force``, as an elastic run.
2. **Retracting**, displacement-controlled, from the last loading approach ``d_max`` to
   ``−RETRACT_REACH · δ_c`` in :data:`RETRACT_STEPS` equal steps (``δ_c``: the JKR sphere's
   approach at pull-off, :func:`roughcontact.models.rough_adhesion.jkr_critical_approach`; a flat
   surface retracts to ``−d_max``), the first approach repeated: ``retract_depth``,
   ``retract_force`` and ``retract_contact_cells`` over ``retract``. Once the last cell has let
   go the force is 0 (exactly: nothing touches).
3. **Pull-off**: the least force of the retract path (the pull-off under load control), refined by
   :data:`REFINE` sub-steps between the retract approaches around it (continued from the retract
   path's contact set at the first of them, not replayed from the start), with the approach and the
   contact radius ``√(A/π)`` there.

Forces in ``e_star * length**2``, lengths in the study's length unit, like every run file.
"""
from __future__ import annotations

import logging

import numpy as np

from ...bem import adhesion
from ...bem.punch import contact_stiffness
from ...errors import ConvergenceError, IndentError
from ...models.paper import hertz_approach
from ...models.rough_adhesion import jkr_critical_approach
from .path import LoadPath
from ..config.defaults import capped_tol

__all__ = ["LOAD_STEPS", "RETRACT_STEPS", "RETRACT_REACH", "REFINE", "adhesive_run"]

logger = logging.getLogger(__name__)

#: approach steps per reference approach of the force-controlled loading
LOAD_STEPS = 400
#: retract approaches from d_max to the end of the retract path
RETRACT_STEPS = 64
#: the retract path ends this many JKR pull-off approaches δ_c beyond first touch
RETRACT_REACH = 3.0
#: sub-steps of the pull-off's refinement between two retract approaches
REFINE = 16


def _reference_approach(s) -> float:
    """``d_ref``: Hertz's approach at the largest load (a sphere;
    :func:`roughcontact.models.paper.hertz_approach`) plus three rms heights; a flat surface: six
    rms heights."""
    if s.kind == "flat":
        return 6.0 * s.h_rms
    return float(hertz_approach(s.forces()[-1], radius=s.radius, e_star=s.e_star)) + 3.0 * s.h_rms


def adhesive_run(z: np.ndarray, s, *, name: str, progress=None) -> dict:
    """The arrays of one adhesive run of the heights *z* with the settings *s*
    (:class:`~roughcontact.study.runs.jobs.JobSettings`, ``s.work_of_adhesion > 0``): the per-load
    variables of an elastic run (``force`` in force units) plus the retract path and the pull-off
    (module docstring). Raises :class:`~roughcontact.errors.IndentError` naming the run when a
    solve does not converge or the contact comes off while loading."""
    w, E, L = float(s.work_of_adhesion), s.e_star, s.length
    forces = s.forces()
    common = dict(length=L, e_star=E, work_of_adhesion=w, periodic=s.periodic, tol=capped_tol(s.tol),
                  maxiter=s.maxiter)
    stiffness = np.zeros(forces.size)

    def record(i, contact) -> str:   # a loading state: the flat-punch stiffness of its contact set
        stiffness[i] = contact_stiffness(contact, length=L, e_star=E, periodic=s.periodic, tol=1e-10)
        return (f"F/(E*L^2) = {forces[i] / (E * L**2):.3e}, contact cells = {int(np.count_nonzero(contact))}, "
                f"k/(E*L) = {stiffness[i] / (E * L):.4e}")

    follow = LoadPath(name, forces.size, record, progress=progress)
    with follow.failing(ConvergenceError, lambda exc: f"indent {name}: the adhesive solve did not converge ({exc}); "
                                                      "use more cells (grid.n) or loosen solver.tol"):
        loading = adhesion.adhesive_force_path(z, forces, step=_reference_approach(s) / LOAD_STEPS,
                                               on_state=follow, **common)
        if loading.depth.size != forces.size:
            raise IndentError(f"indent {name}: the adhesive contact came off while loading; raise "
                              f"forces.{s.kind}.from")
        d_max = float(loading.depth[-1])
        end = -d_max if s.kind == "flat" else -RETRACT_REACH * jkr_critical_approach(
            radius=s.radius, e_star=E, work_of_adhesion=w)
        retract = np.linspace(d_max, end, RETRACT_STEPS)
        depths, sets = np.r_[loading.depth, retract[1:]], []

        def keep(i, contact) -> str:   # a state of the path to pull-off: its contact set, to refine from
            sets.append(contact.copy())
            return f"d/L = {depths[i] / L:.4e}, contact cells = {int(np.count_nonzero(contact))}"

        path = adhesion.adhesive_path(z, depths, **common, on_state=LoadPath(name, depths.size, keep,
                                                                              what="retract path step"))
        first = loading.depth.size - 1                       # the retract path starts at d_max
        r_force, r_cells = path.force[first:], path.contact_cells[first:]
        j = int(np.argmin(r_force))
        lo, hi = max(j - 1, 0), min(j + 1, RETRACT_STEPS - 1)
        fine = np.linspace(retract[lo], retract[hi], 2 * REFINE + 1)
        refined = adhesion.adhesive_path(z, fine, **common, start=sets[first + lo])   # on from retract[lo]
    m = int(np.argmin(refined.force))
    better = refined.force[m] <= r_force[j]
    cell = (L / z.shape[0]) ** 2
    logger.info("%s: pull-off F/(E*L^2) = %.4e at d = %.4g", name, min(refined.force[m], r_force[j]) / (E * L**2),
                refined.depth[m] if better else retract[j])
    return {
        "force": forces,
        "depth": loading.depth, "stiffness": stiffness,
        "contact_area": loading.contact_cells * cell, "contact_cells": loading.contact_cells.astype("i8"),
        "iterations": loading.iterations.astype("i8"), "converged": np.ones(forces.size, dtype="i1"),
        "retract_depth": retract, "retract_force": r_force, "retract_contact_cells": r_cells.astype("i8"),
        "pull_off_force": float(refined.force[m] if better else r_force[j]),
        "pull_off_depth": float(refined.depth[m] if better else retract[j]),
        "pull_off_contact_radius": float(refined.contact_radius[m] if better else path.contact_radius[first + j]),
    }
