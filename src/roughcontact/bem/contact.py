"""Frictionless normal contact of a rigid indenter with an elastic half-space.

Conventions (units are the caller's; nothing assumes ``L = 1`` or ``E* = 1``):

* ``heights`` ``z`` is the indenter's shape on an ``n × n`` grid of cells of side
  ``Δ = length/n``, measured from the undeformed half-space towards the indenter.
* ``depth`` ``d`` is the rigid-body approach counted from first touch
  (``d = 0`` when ``min z`` just touches).
* ``u`` is the surface displacement of the half-space (positive into it). The
  gap ``g = (z − min z) − d + u`` is 0 wherever the pressure is positive and
  ``≥ 0`` elsewhere; pressure ``p ≥ 0`` everywhere.
* ``force = Σ p Δ²``.
* With a ``hardness`` ``H`` (penetration-hardness plasticity, module
  :mod:`roughcontact.bem.plastic`) the pressure is capped at ``H``, cells at the
  cap may have ``g < 0`` and flow by ``−g``, and the accumulated plastic
  displacement ``δ ≥ 0`` enters the gap as ``g = (z − min z) + δ − d + u``.

For the periodic half-space the mean displacement is undefined; ``u`` has zero
mean and ``depth`` is the approach of the indenter to the mean plane of the
deformed surface, counted from first touch.

Algorithms (modules :mod:`roughcontact.bem.solver`, :mod:`roughcontact.bem.active_sets`
(the windows of non-periodic solves, the candidate cells and working sets of
periodic ones) and :mod:`roughcontact.bem.punch`):
force-controlled constrained conjugate gradients of Polonsky & Keer, Wear 231,
206 (1999), with the box ``0 ≤ p ≤ H`` when a hardness is given; the exact
unloading stiffness (:mod:`roughcontact.bem.incremental`) as the force of a rigid flat punch with the current
contact set as footprint (the incremental analogy of Barber, Proc. R. Soc. A
459, 53 (2003)), solved by conjugate gradients (Hestenes & Stiefel 1952,
``scipy.sparse.linalg.cg``) with mixed-precision iterative refinement.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from collections.abc import Iterator

import numpy as np

from .._defaults import DEFAULT_MAXITER as _DEFAULT_MAXITER
from .._validate import check_finite_positive, check_grid_size
from ..errors import ConvergenceError, DomainTooSmallError
from .active_sets import equilibrium
from .operators import operator_for
from .plastic import plastic_flow
from .solver import capped_kernel, polonsky_keer

__all__ = [
    "ContactState",
    "displacement",
    "iter_load_path",
    "load_path",
    "solve",
]

#: Default maximum number of conjugate-gradient iterations per solve (its home: roughcontact._defaults).
DEFAULT_MAXITER = _DEFAULT_MAXITER


@dataclasses.dataclass(frozen=True, eq=False)
class ContactState:
    """Equilibrium of a rigid indenter pressed into an elastic half-space.

    Attributes
    ----------
    force : float
        Total normal force ``Σ p Δ²`` (force unit).
    depth : float
        Rigid-body approach from first touch (length unit).
    pressure : numpy.ndarray
        ``(n, n)`` contact pressure per cell, ``≥ 0`` (force/length²).
    contact : numpy.ndarray
        ``(n, n)`` bool, cells with positive pressure.
    iterations : int
        Conjugate-gradient iterations spent (all windows included).
    converged : bool
        Whether the stopping test of :func:`solve` was met within ``maxiter``.
    gap_error : float
        Final ``max(max_c |g|, max_(not c) (−g)) / d``: the relative violation
        of complementarity that the stopping test bounds by ``tol``.
    heights, length, e_star, periodic, tol, maxiter, edge_contact :
        The problem that was solved (``heights`` is the caller's array, not a copy,
        without plastic flattening).
    window : tuple of slice
        Rows and columns of the grid on which the last solve ran.
    hardness : float or None
        Penetration hardness ``H`` that capped the pressure (pressure unit, like
        ``e_star``); ``None`` for an elastic half-space.
    plastic : numpy.ndarray
        ``(n, n)`` bool, cells that flowed in this solve: at ``p = H`` with a
        negative gap before the flow. All ``False`` when ``hardness`` is ``None``.
    plastic_displacement : numpy.ndarray
        ``(n, n)`` permanent depression of the half-space (length unit, ``≥ 0``),
        cumulative over the load history up to and including this state: the
        indenter acts as if its heights were ``heights + plastic_displacement``.
        Read-only; all zero (a broadcast view, no memory) when nothing flowed.
    diagnosis : str
        Empty when converged; otherwise the kernel's one sentence on why it stopped, what it
        tried and where the stopping test is violated
        (:attr:`roughcontact.bem.result.KernelResult.diagnosis`).
    """

    force: float
    depth: float
    pressure: np.ndarray
    contact: np.ndarray
    iterations: int
    converged: bool
    gap_error: float
    heights: np.ndarray
    length: float
    e_star: float
    periodic: bool
    tol: float
    maxiter: int
    window: tuple[slice, slice]
    edge_contact: bool = False
    hardness: float | None = None
    plastic: np.ndarray | None = None
    plastic_displacement: np.ndarray | None = None
    diagnosis: str = ""

    def __post_init__(self):
        shape = self.heights.shape
        if self.plastic is None:
            object.__setattr__(self, "plastic", np.broadcast_to(False, shape))
        if self.plastic_displacement is None:
            object.__setattr__(self, "plastic_displacement", np.broadcast_to(0.0, shape))

    @property
    def cell_area(self) -> float:
        """Area ``Δ²`` of one grid cell."""
        return (self.length / self.heights.shape[0]) ** 2

    @property
    def contact_area(self) -> float:
        """Real contact area: cells in contact × ``Δ²``."""
        return float(np.count_nonzero(self.contact)) * self.cell_area

    def gap(self) -> np.ndarray:
        """Gap ``(z − min z) + δ − d + u`` on the whole grid (one full-grid convolution),
        ``δ`` the plastic displacement (after this state's flow: 0 on the plastic cells)."""
        u = displacement(self.pressure, length=self.length, e_star=self.e_star,
                         periodic=self.periodic)
        lift = self.heights - self.heights.min()
        if self.hardness is not None:
            lift = lift + self.plastic_displacement
        return lift - self.depth + u


def _check_heights(heights) -> np.ndarray:
    heights = np.asarray(heights, dtype=float)
    if heights.ndim != 2 or heights.shape[0] != heights.shape[1]:
        raise ValueError(f"heights must be a square 2-D array, got shape {heights.shape}")
    check_grid_size(heights.shape[0])
    if not np.all(np.isfinite(heights)):
        raise ValueError("heights must be finite")
    return heights


def displacement(pressure, *, length: float, e_star: float, periodic: bool = False) -> np.ndarray:
    """Surface displacement ``u`` of the half-space under the cell pressures ``pressure``."""
    pressure = _check_heights(pressure)
    check_finite_positive("length", length)
    check_finite_positive("e_star", e_star)
    return operator_for(pressure.shape[0], float(length), float(e_star), bool(periodic))(pressure)


def _solve(heights, force, length, e_star, periodic, tol, maxiter, initial, depth_bound,
           edge_contact, hardness=None, prior_plastic=None):
    n = heights.shape[0]
    operator = operator_for(n, float(length), float(e_star), bool(periodic))
    lift = heights - heights.min()
    if prior_plastic is not None:
        lift = lift + prior_plastic
    total = force / (length / n) ** 2
    p = None
    iterations = 0
    # Elastic first, unless the warm start sits at the cap and the load grows: a hardness
    # above the elastic peak pressure then returns the elastic solution itself, and
    # unloading (elastic until the cap is reached again) starts from the elastic solution.
    if (hardness is None or initial is None or not np.any(initial >= hardness)
            or initial.sum() >= total):
        result, window = equilibrium(
            lift, operator, total, initial, depth_bound, tol, maxiter, periodic, polonsky_keer)
        p, depth, iterations = result.pressure, result.depth, result.iterations
        if hardness is not None and p.max() > hardness:
            # the capped solution is softer: its depth exceeds the elastic one
            depth_bound = depth if depth_bound is None else max(depth_bound, depth)
            initial, p = p, None
    if p is None:
        # At most H per cell: at least total/H cells carry the load, and they all have
        # lift ≤ d (u ≥ 0), so d is at least the bearing-area depth (the total/H-th
        # lowest lift); a first window or candidate set below it could not carry the load.
        cells = math.ceil(total / hardness)
        if cells > lift.size:
            raise ValueError(f"force {force:g} exceeds hardness × grid area "
                             f"{hardness * length**2:g}: no state with p ≤ hardness exists")
        bearing = float(np.partition(lift, cells - 1, axis=None)[cells - 1])
        depth_bound = bearing if depth_bound is None else max(depth_bound, bearing)
        kernel = functools.partial(capped_kernel, hardness=float(hardness))
        result, window = equilibrium(
            lift, operator, total, initial, depth_bound, tol, max(maxiter - iterations, 1),
            periodic, kernel, min_cells=cells)
        p, depth, iterations = result.pressure, result.depth, iterations + result.iterations
    if not periodic:
        edge = np.concatenate([p[0], p[-1], p[:, 0], p[:, -1]])
        if not edge_contact and np.any(edge > 0):
            raise DomainTooSmallError(
                f"the contact reached the edge of the {n}x{n} non-periodic grid at "
                f"force {force:g}: enlarge the grid (length and n) or lower the load "
                f"(a finite indenter whose face is the whole grid: edge_contact=True)")
    flowed, plastic_displacement = None, prior_plastic
    if hardness is not None:
        flowed = np.zeros((n, n), dtype=bool)
        flowed[window], increment = plastic_flow(lift[window], operator(p[window]), p[window],
                                                 depth, hardness)
        if flowed.any():
            plastic_displacement = np.zeros((n, n)) if prior_plastic is None else prior_plastic.copy()
            plastic_displacement[window] += increment
            plastic_displacement.flags.writeable = False
    return ContactState(
        force=float(p.sum() * (length / n) ** 2), depth=float(depth), pressure=p,
        contact=p > 0, iterations=int(iterations), converged=bool(result.converged),
        gap_error=float(result.error), diagnosis=result.diagnosis, heights=heights, length=float(length), e_star=float(e_star),
        periodic=bool(periodic), tol=float(tol), maxiter=int(maxiter), window=window,
        edge_contact=bool(edge_contact),
        hardness=None if hardness is None else float(hardness), plastic=flowed,
        plastic_displacement=plastic_displacement)


def _converged(state: ContactState, method: str) -> ContactState:
    """*state* if it met its stopping test, else the :class:`ConvergenceError` of an extra solve."""
    if not state.converged:
        raise ConvergenceError(f"the extra contact solve of stiffness(method={method!r}) at force "
                               f"{state.force:g} did not converge in {state.iterations} iterations "
                               f"(tol = {state.tol:g}); raise maxiter or loosen tol")
    return state


def _check_solver_args(length, e_star, tol, maxiter):
    check_finite_positive("length", length)
    check_finite_positive("e_star", e_star)
    check_finite_positive("tol", tol)
    if isinstance(maxiter, bool) or not isinstance(maxiter, int) or maxiter < 1:
        raise ValueError(f"maxiter must be a positive integer, got {maxiter!r}")


def solve(heights, *, force: float, length: float, e_star: float, periodic: bool = False,
          tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, initial=None,
          windowed: bool = True, edge_contact: bool = False, hardness: float | None = None,
          plastic_displacement=None) -> ContactState:
    """Contact of a rigid indenter of shape ``heights`` pressed by a normal ``force``.

    Parameters
    ----------
    heights : array_like, shape (n, n)
        Indenter shape ``z`` (length unit), see the module conventions.
    force : float
        Total normal force (force unit), > 0.
    length : float
        Side of the grid (length unit); cells have side ``length/n``.
    e_star : float
        Effective modulus of the half-space (force/length²).
    periodic : bool
        Periodic half-space (nominally flat surfaces) instead of a free one.
    tol : float
        Bound on the relative violation of complementarity, keyword-only.
        With ``g`` the gap and ``c`` the contact set, iteration stops when
        ``max_c |g| ≤ tol·d`` and ``min_(not c) g ≥ −tol·d``.
        The force is matched to round-off at every iteration.
    maxiter : int
        Maximum conjugate-gradient iterations; when reached the state is
        returned with ``converged=False``.
    initial : array_like, optional
        Pressure to start from (warm start), e.g. a neighbouring load's.
    windowed : bool
        Solve non-periodic contacts on a window around the contact, periodic
        ones on the cells that can touch while they are few (module
        docstring); ``False`` solves on the whole grid by FFT, for
        verification. Both give the same solution within ``tol``.
    edge_contact : bool
        Non-periodic only: allow pressure on the grid's edge cells, for a
        finite indenter whose face is the whole grid (e.g. a nominally flat
        rough punch of side ``length``). By default such a contact means the
        grid is too small for the body and raises.
    hardness : float, optional
        Penetration hardness ``H`` (pressure unit, like ``e_star``): the
        pressure is capped at ``H`` and cells at the cap flow (module
        :mod:`roughcontact.bem.plastic`). The stopping test then reads, with ``f``
        the cells with ``0 < p < H``: ``max_f |g| ≤ tol·d``,
        ``min_(p=0) g ≥ −tol·d`` and ``max_(p=H) g ≤ tol·d``. The elastic
        solution is computed first and returned unchanged when its peak
        pressure is ``≤ H``. ``None`` (default): elastic.
    plastic_displacement : array_like, optional
        Permanent depression from an earlier load history (length unit,
        ``≥ 0``, e.g. ``state.plastic_displacement``), added to ``heights``;
        ``depth`` stays counted from the first touch of ``heights``.

    Returns
    -------
    ContactState

    Raises
    ------
    DomainTooSmallError
        If the pressure of a non-periodic contact reaches the edge of the grid
        and ``edge_contact`` is false.
    """
    heights = _check_heights(heights)
    check_finite_positive("force", force)
    _check_solver_args(length, e_star, tol, maxiter)
    if initial is not None:
        initial = np.asarray(initial, dtype=float)
        if initial.shape != heights.shape:
            raise ValueError(f"initial must have the shape of heights {heights.shape}, "
                             f"got {initial.shape}")
    hardness, plastic_displacement = _check_plastic_args(heights, hardness, plastic_displacement)
    bound = None if windowed else math.inf
    return _solve(heights, float(force), length, e_star, periodic, tol, maxiter, initial, bound,
                  edge_contact, hardness, plastic_displacement)


def _check_plastic_args(heights, hardness, plastic_displacement):
    if hardness is not None:
        check_finite_positive("hardness", hardness)
        hardness = float(hardness)
    if plastic_displacement is not None:
        plastic_displacement = np.asarray(plastic_displacement, dtype=float)
        if plastic_displacement.shape != heights.shape:
            raise ValueError(f"plastic_displacement must have the shape of heights "
                             f"{heights.shape}, got {plastic_displacement.shape}")
        if not np.all(np.isfinite(plastic_displacement)) or np.any(plastic_displacement < 0):
            raise ValueError("plastic_displacement must be finite and >= 0")
    return hardness, plastic_displacement


def iter_load_path(heights, forces, *, length: float, e_star: float, periodic: bool = False,
                   tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, edge_contact: bool = False,
                   hardness: float | None = None, plastic_displacement=None,
                   progress=None) -> Iterator[ContactState]:
    """Solve at each of ``forces`` in order, yielding each state as soon as it is solved.

    Same parameters and result per force as :func:`solve`. Each solve is
    warm-started from the previous state only, so a caller that drops each
    state after processing it keeps at most two pressure arrays alive.
    Non-periodic solves also inherit a depth bound: ``d(F)`` is concave with
    ``d(0) = 0`` (the contact set grows with the load, so ``dF/dd`` does not
    decrease), hence ``d(F) ≤ d(F₀)·max(1, F/F₀)`` with ``F₀`` the previous force.
    (With a ``hardness`` the bound only sizes the first window: a window is
    accepted by its own test, whatever the bound.)

    With a ``hardness`` each solve starts from the plastic displacement of the
    previous state (the first from ``plastic_displacement``, default none), so
    the surface stays flattened along the path; a lower force than the
    previous one unloads elastically until the cap is reached again.

    The arguments are checked when this function is called, not at the first
    ``next``. ``progress``, if given, is called as ``progress(i, len(forces),
    state)`` after each solve, before the state is yielded.

    Yields
    ------
    ContactState
        One per force, in the order of ``forces``.
    """
    heights = _check_heights(heights)
    _check_solver_args(length, e_star, tol, maxiter)
    forces = [float(f) for f in np.atleast_1d(np.asarray(forces, dtype=float))]
    for f in forces:
        check_finite_positive("forces", f)
    hardness, plastic_displacement = _check_plastic_args(heights, hardness, plastic_displacement)
    return _iter_states(heights, forces, length, e_star, periodic, tol, maxiter, edge_contact,
                        hardness, plastic_displacement, progress)


def _iter_states(heights, forces, length, e_star, periodic, tol, maxiter, edge_contact, hardness,
                 plastic_displacement, progress):
    previous = None
    for i, force in enumerate(forces):
        initial = None if previous is None else previous.pressure
        bound = None if previous is None else previous.depth * max(1.0, force / previous.force)
        if previous is not None and hardness is not None:
            plastic_displacement = previous.plastic_displacement
        state = _solve(heights, force, length, e_star, periodic, tol, maxiter, initial, bound,
                       edge_contact, hardness, plastic_displacement)
        if progress is not None:
            progress(i + 1, len(forces), state)
        previous = state
        yield state


def load_path(heights, forces, *, length: float, e_star: float, periodic: bool = False,
              tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, edge_contact: bool = False,
              hardness: float | None = None, plastic_displacement=None,
              progress=None) -> list[ContactState]:
    """All states of :func:`iter_load_path` as a list (same parameters and states).

    ``progress``, if given, is called as ``progress(i, len(forces), state)``
    after each solve.
    """
    return list(iter_load_path(heights, forces, length=length, e_star=e_star, periodic=periodic,
                               tol=tol, maxiter=maxiter, edge_contact=edge_contact,
                               hardness=hardness, plastic_displacement=plastic_displacement,
                               progress=progress))
