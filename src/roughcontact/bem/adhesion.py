"""Adhesive contact by the mesh-dependent detachment criterion of Pohrt & Popov.

R. Pohrt, V. L. Popov, "Adhesive contact simulation of elastic solids using local mesh-dependent
detachment criterion in boundary elements method", Facta Universitatis Mech. Eng. 13, 3-10
(2015). A cell of side ``Δx`` joins the contact when the deformed gap closes there, and leaves it
only when its tensile stress exceeds the critical stress

    σ_c = √(c · E* w / Δx),

so that the contact set, and with it the force, depends on the path: loading and unloading
differ (hysteresis), and the pull-off force is the most tensile force of the unloading path.

The constant. The edge of an adhesive contact is a crack tip: the normal stress ahead of it is
``σ(s) = −K/√(2πs)`` at the distance ``s``, with ``K = √(2E*w)`` for a rigid indenter on a
half-space of modulus ``E*`` (Griffith: ``G = K²/(2E*) = w``; JKR's edge stress
``√(wE*/(πs))`` is the same). If the element next to the tip carried the mean of that field over
its width, ``(1/Δx)∫₀^Δx K/√(2πs) ds = √(4E*w/(πΔx))``, the constant would be ``c = 4/π``.
The boundary elements carry a uniform pressure each, collocated at their centres, and the
contact's edge on a square grid is a staircase: the edge element's pressure is the continuum
stress nearer the tip than its mean. Calibrated on JKR (the smooth sphere's load-controlled
pull-off ``−(3/2)πwR``, contact radius at pull-off 10, 20 and 40 cells, measured 2026-11-24), the
pull-off scales as ``c`` and is ``0.527 c``, ``0.498 c`` and ``0.486 c`` times JKR's, converging
(geometrically, ratio 0.4) to ``0.478 c``: ``c = 2.1`` makes the method converge to JKR
(+10.9 %, +5.2 % and +1.4 % at 10, 20 and 40 cells); ``c = 4/π`` would converge to 61 % of it.
``tests/test_adhesion_bem.py`` checks it. Measured again 2026-11-25 with a finer retract through the
pull-off (steps of ``0.01 a_c²/R``, ``a_c`` JKR's pull-off radius; the figures above took steps of about
``0.035 a_c²/R``): +12.9 %, +6.0 %, +2.8 % and +0.6 % at 10, 20, 40 and 80 cells; without the path's
sampling (the force just before each detachment, from the fixed contact's linear response) +13.5 %,
+6.4 %, +3.5 % and +0.9 %. A coarser step misses more of the most tensile force between two detachments,
the more so the fewer the cells. ``tests/test_adhesion_jkr_convergence.py`` checks 10 to 40 cells
(80 cells on 200²: 4–5 minutes).

The solve at a given approach ``d`` (displacement control): on the contact set ``C`` the surface
follows the indenter, ``u_i = d − (z_i − min z)``, and the pressures solve ``K_CC p_C = u_C`` by
conjugate gradients (``‖K_CC p_C − u_C‖ ≤ tol ‖u_C‖``; on the free half-space the operator acts on
the bounding box of ``C`` only, exact there by the zero-padded convolution, and the whole grid's
displacement is computed once per update of ``C``); cells of ``C`` with ``p < −σ_c``
leave it, cells outside with a closed gap (``z_i − min z − d + u_i < 0``) join it, and the
solve repeats until ``C`` is unchanged. Each approach starts from the previous contact set and
pressures (warm start). Pressures are compressive positive, forces ``F = Σ p Δx²``.

The half-space is elastic: the adhesive paths take no ``hardness`` (passing one is a
``TypeError``); penetration-hardness plasticity (:mod:`roughcontact.bem.plastic`) is not combined
with adhesion. The Maugis–Dugdale cohesive zone is the other adhesive interaction
(:mod:`roughcontact.bem.cohesive`).
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from .._validate import check_finite_positive
from ..errors import ConvergenceError
from .active_sets import bounding_box
from .operators import operator_for

__all__ = ["DETACHMENT_CONSTANT", "AdhesivePath", "CohesivePath", "adhesive_force_path", "adhesive_path",
           "critical_stress"]

#: ``c`` of the detachment criterion ``σ_c = √(c E* w/Δx)``, calibrated on JKR (module docstring)
DETACHMENT_CONSTANT = 2.1


def critical_stress(*, e_star: float, work_of_adhesion: float, spacing: float,
                    constant: float = DETACHMENT_CONSTANT) -> float:
    """``σ_c = √(c E* w/Δx)``: the tensile stress at which a cell of side ``spacing`` detaches."""
    check_finite_positive("e_star", e_star)
    check_finite_positive("work_of_adhesion", work_of_adhesion)
    check_finite_positive("spacing", spacing)
    return math.sqrt(constant * e_star * work_of_adhesion / spacing)


@dataclasses.dataclass(frozen=True)
class AdhesivePath:
    """The states of a displacement-controlled adhesive path, one entry per approach.

    Attributes
    ----------
    depth : numpy.ndarray
        Approach ``d`` from first touch (length).
    force : numpy.ndarray
        ``F = Σ p Δx²`` (force; negative: tensile).
    contact_cells : numpy.ndarray
        Cells in contact.
    contact_radius : numpy.ndarray
        ``√(A/π)`` of the contact area ``A`` (length).
    iterations : numpy.ndarray
        Contact-set updates of each approach.
    pull_off_force : float
        The most tensile force of the path (force): the pull-off under load control.
    detach_depth : float
        The first approach of the path's unloading at which no cell is left in contact (NaN if
        the contact never comes off).
    """

    depth: np.ndarray
    force: np.ndarray
    contact_cells: np.ndarray
    contact_radius: np.ndarray
    iterations: np.ndarray
    pull_off_force: float
    detach_depth: float


def _cg(apply, rhs, x, *, tol, maxiter):
    """Conjugate gradients on the SPD ``apply`` from ``x``: ``‖apply(x) − rhs‖ ≤ tol ‖rhs‖``."""
    r = rhs - apply(x)
    p = r.copy()
    rr = float(r @ r)
    limit = (tol * float(np.linalg.norm(rhs))) ** 2
    for _ in range(maxiter):
        if rr <= limit:
            return x
        ap = apply(p)
        alpha = rr / float(p @ ap)
        x += alpha * p
        r -= alpha * ap
        rr_new = float(r @ r)
        p = r + (rr_new / rr) * p
        rr = rr_new
    if rr <= limit:
        return x
    raise ConvergenceError(f"conjugate gradients did not reach tol = {tol:g} in {maxiter} iterations")


class _Solver:
    """The solve at one approach (module docstring) on one grid: what the displacement- and
    force-controlled paths share."""

    def __init__(self, z, *, length, e_star, work_of_adhesion, periodic, constant, tol, maxiter, max_updates):
        z = np.asarray(z, dtype=float)
        if z.ndim != 2 or z.shape[0] != z.shape[1]:
            raise ValueError(f"z must be a square n x n array, got shape {z.shape}")
        check_finite_positive("length", length)
        n = z.shape[0]
        self.spacing = length / n
        self.sigma_c = critical_stress(e_star=e_star, work_of_adhesion=work_of_adhesion, spacing=self.spacing,
                                       constant=constant)
        self.operator = operator_for(n, length, e_star, periodic)
        self.heights = z - z.min()
        self.tol, self.maxiter, self.max_updates = tol, maxiter, max_updates

    def empty(self):
        """The state before first touch: ``(contact, pressure)``."""
        return np.zeros(self.heights.shape, dtype=bool), np.zeros(self.heights.shape)

    def settle(self, d: float, contact, pressure):
        """``(contact, pressure, updates)`` at the approach *d* from the state ``(contact, pressure)``
        (not modified)."""
        contact, pressure = contact.copy(), pressure.copy()
        heights, operator = self.heights, self.operator
        for update in range(self.max_updates):
            if not contact.any():
                contact = heights <= d        # first touch: every cell the rigid approach reaches
                pressure[:] = 0.0
                if not contact.any():
                    return contact, pressure, update + 1
            target = (d - heights)[contact]
            box = (slice(None), slice(None)) if operator.periodic else bounding_box(contact)
            inside = contact[box]

            def apply(values, inside=inside):
                field = np.zeros(inside.shape)
                field[inside] = values
                return operator(field)[inside]

            pressure[~contact] = 0.0
            pressure[contact] = _cg(apply, target, pressure[contact].copy(), tol=self.tol, maxiter=self.maxiter)
            gap = heights - d + operator(pressure)
            leave = contact & (pressure < -self.sigma_c)
            join = ~contact & (gap < 0.0)
            if not leave.any() and not join.any():
                return contact, pressure, update + 1
            contact = (contact & ~leave) | join
            pressure[~contact] = 0.0
        raise ConvergenceError(f"the contact set did not settle in {self.max_updates} updates at d = {d:g}")

    def force(self, pressure) -> float:
        return float(pressure.sum() * self.spacing**2)


def _path(records, solver, pull_off, detach_depth) -> AdhesivePath:
    arrays = {key: np.asarray([r[key] for r in records]) for key in
              ("depth", "force", "contact_cells", "contact_radius", "iterations")}
    return AdhesivePath(**arrays, pull_off_force=pull_off, detach_depth=detach_depth)


def _record(solver, d, contact, pressure, updates) -> dict:
    cells = int(np.count_nonzero(contact))
    return {"depth": float(d), "force": solver.force(pressure), "contact_cells": cells,
            "contact_radius": math.sqrt(cells * solver.spacing**2 / math.pi), "iterations": updates}


def adhesive_path(z, depths, *, length: float, e_star: float, work_of_adhesion: float, periodic: bool = False,
                  constant: float = DETACHMENT_CONSTANT, tol: float = 1e-10, maxiter: int = 2000,
                  max_updates: int = 2000, on_state=None, start=None) -> AdhesivePath:
    """Press the indenter *z* (``n × n`` heights, lowest first) along the approaches *depths*
    (length, from first touch; rising for loading, falling for unloading, in any sequence) into
    a half-space that sticks by the detachment criterion (module docstring).

    Parameters
    ----------
    z : array_like
        Indenter heights (length), ``n × n``.
    depths : array_like
        The approaches, in path order (length).
    length, e_star, work_of_adhesion : float
        Side of the grid, effective modulus, work of adhesion ``w`` (energy per area).
    periodic : bool
        Periodic half-space instead of the free one.
    constant : float
        ``c`` of ``σ_c = √(c E* w/Δx)``.
    tol, maxiter : float, int
        Keyword-only: the conjugate gradients' relative residual and iteration limit per solve.
    max_updates : int
        Most contact-set updates per approach.
    on_state : callable, optional
        Called as ``on_state(i, contact)`` with the contact set (boolean, ``n × n``) of each
        recorded approach ``i``, e.g. for the stiffness of the contact (the sets are not kept).
    start : array_like of bool, optional
        The contact set (``n × n``) to begin from instead of no contact: a state of an earlier path
        (e.g. from *on_state*), to continue that path from there without replaying it; its
        pressures are solved again at the first approach.

    Raises
    ------
    ConvergenceError
        A solve or the contact set does not settle within its limits.
    """
    solver = _Solver(z, length=length, e_star=e_star, work_of_adhesion=work_of_adhesion, periodic=periodic,
                     constant=constant, tol=tol, maxiter=maxiter, max_updates=max_updates)
    contact, pressure = solver.empty()
    if start is not None:
        start = np.asarray(start)
        if start.shape != contact.shape or start.dtype != bool:
            raise ValueError(f"start must be a boolean {contact.shape} contact set, got {start.dtype} {start.shape}")
        contact = start.copy()
    records, detach_depth = [], math.nan
    for d in np.asarray(depths, dtype=float):
        contact, pressure, updates = solver.settle(float(d), contact, pressure)
        records.append(_record(solver, d, contact, pressure, updates))
        if on_state is not None:
            on_state(len(records) - 1, contact)
        if records[-1]["contact_cells"] == 0 and math.isnan(detach_depth) and len(records) > 1 \
                and records[-2]["contact_cells"] > 0:
            detach_depth = float(d)
    pull_off = float(min(r["force"] for r in records)) if records else math.nan
    return _path(records, solver, pull_off, detach_depth)


def adhesive_force_path(z, forces, *, step: float, length: float, e_star: float, work_of_adhesion: float,
                        periodic: bool = False, constant: float = DETACHMENT_CONSTANT, tol: float = 1e-10,
                        maxiter: int = 2000, max_updates: int = 2000, force_tol: float = 1e-6,
                        max_steps: int = 10000, on_state=None) -> AdhesivePath:
    """The force-controlled path through the target *forces* (in path order; force): for each, the
    approach is moved from the last one in steps of *step* (length) along the path's branch until
    the force crosses the target, then bisected (every trial from the state before the crossing
    step) until ``|F − target| ≤ force_tol · max(|target|, |F|)``, keyword-only.

    On unloading, a target below the least force the branch holds cannot be reached: the contact
    jumps off. The steps go on down the branch (past its least force, where the force rises
    again; the discrete detachment makes it rise and fall by small steps on the way) until no cell
    is left; the path ends there: ``pull_off_force`` is the least force met (the load-controlled
    pull-off, to the resolution of *step*), ``detach_depth`` the approach where the last cell
    left; later targets have no entry.
    Other arguments as :func:`adhesive_path`.
    """
    check_finite_positive("step", step)
    solver = _Solver(z, length=length, e_star=e_star, work_of_adhesion=work_of_adhesion, periodic=periodic,
                     constant=constant, tol=tol, maxiter=maxiter, max_updates=max_updates)
    d = 0.0
    contact, pressure = solver.empty()
    force = 0.0
    least, records, detach_depth = math.inf, [], math.nan
    for target in np.asarray(forces, dtype=float):
        direction = 1.0 if target > force else -1.0
        for _ in range(max_steps):
            if abs(force - target) <= force_tol * max(abs(target), abs(force)):
                break
            d_next = d + direction * step
            c_next, p_next, _ = solver.settle(d_next, contact, pressure)
            f_next = solver.force(p_next)
            least = min(least, f_next)
            if (f_next - target) * direction >= 0:            # crossed: bisect within this step
                low, high = (d, d_next) if direction > 0 else (d_next, d)
                for _ in range(200):
                    mid = 0.5 * (low + high)
                    c_mid, p_mid, _ = solver.settle(mid, contact, pressure)
                    f_mid = solver.force(p_mid)
                    if abs(f_mid - target) <= force_tol * max(abs(target), abs(f_mid)):
                        break
                    if (f_mid - target) * direction >= 0:
                        high, low = (mid, low) if direction > 0 else (high, mid)
                    else:
                        low, high = (mid, high) if direction > 0 else (low, mid)
                d, contact, pressure, force = mid, c_mid, p_mid, f_mid
                break
            if direction < 0 and not c_next.any():   # the target was below every force of the branch
                detach_depth = d_next
                return _path(records, solver, float(least), detach_depth)
            d, contact, pressure, force = d_next, c_next, p_next, f_next
        else:
            raise ConvergenceError(f"the force {target:g} was not reached in {max_steps} steps of {step:g}")
        records.append(_record(solver, d, contact, pressure, 0))
        if on_state is not None:
            on_state(len(records) - 1, contact)
    return _path(records, solver, float(least) if records else math.nan, detach_depth)


@dataclasses.dataclass(frozen=True)
class CohesivePath(AdhesivePath):
    """An :class:`~roughcontact.bem.adhesion.AdhesivePath` of the cohesive-zone model, with its zone.

    Attributes
    ----------
    depth, force, contact_cells, contact_radius :
        As :class:`~roughcontact.bem.adhesion.AdhesivePath`: ``force`` includes the zone's tension,
        ``contact_cells`` are the cells in contact (``g = 0``, ``q > 0``).
    iterations : numpy.ndarray
        Updates of ``S`` (contact solves) of each approach.
    pull_off_force : float
        The most tensile force of the path (force): under load control, the pull-off.
    detach_depth : float
        The first approach at which no cell is left in contact (``g = 0``) after some were: the
        zone may still pull there (NaN if the contact never comes off).
    zone_cells : numpy.ndarray
        Cells of the cohesive zone per approach: within range, not in contact (``q = 0``).
    zone_radius : numpy.ndarray
        ``√((A_C + A_Z)/π)``: the radius of the area inside the zone's outer edge (length;
        Maugis' ``c``).
    fallback : numpy.ndarray
        Bool per approach: the ``"energy"`` edge rule's updates cycled and the ``"metastable"``
        rule settled the approach (module docstring, The edge).
    cohesive_stress : float
        ``σ₀`` (pressure).
    interaction_range : float
        ``δ_t = w/σ₀`` (length).
    """

    zone_cells: np.ndarray
    zone_radius: np.ndarray
    fallback: np.ndarray
    cohesive_stress: float
    interaction_range: float
