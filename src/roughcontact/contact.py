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

For the periodic half-space the mean displacement is undefined; ``u`` has zero
mean and ``depth`` is the approach of the indenter to the mean plane of the
deformed surface, counted from first touch.

Algorithms: force-controlled constrained conjugate gradients of Polonsky &
Keer, Wear 231, 206 (1999); the exact tangent stiffness as the force of a
rigid flat punch with the current contact set as footprint (the incremental
analogy of Barber, Proc. R. Soc. A 459, 53 (2003)), solved by conjugate
gradients (Hestenes & Stiefel 1952, ``scipy.sparse.linalg.cg``).

Windowing (non-periodic only): a compressive load pushes the surface away
(``u > 0``), so a cell can only be in contact where ``z − min z ≤ d``. The
solver bounds ``d`` from above, solves on the bounding box of that region,
and accepts the result only if every cell outside the box has
``z − min z > d``, in which case it is the solution on the whole grid;
otherwise it enlarges the box and solves again.

Candidate cells (periodic): the periodic displacement can be negative but not
below ``G_min Σp`` (``G_min`` the kernel's minimum), so a contact cell has
``z − min z ≤ d + |G_min| Σp``. While those cells number at most
:data:`DENSE_CELLS` (small loads on a nominally flat surface), the solver works
on them alone with a dense influence matrix, accepts the result when its depth
is within the bound, and otherwise solves again with the larger bound. The punch
stiffness on at most :data:`DENSE_CELLS` cells uses the dense matrix too.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator

import numpy as np
from scipy.sparse.linalg import LinearOperator, cg

from ._validate import check_finite_positive, check_grid_size
from .operators import DenseOperator, operator_for

__all__ = [
    "ContactState",
    "DomainTooSmallError",
    "solve",
    "load_path",
    "iter_load_path",
    "stiffness",
    "displacement",
]

#: Default maximum number of conjugate-gradient iterations per solve.
DEFAULT_MAXITER = 10_000
#: Incremental displacement updates between two exact (FFT) recomputations.
_REFRESH = 50
#: Periodic contacts whose cells that can touch are at most this many, and punch
#: stiffness solves on at most this many cells, use a dense influence matrix
#: (2000² doubles = 32 MB; a product costs ≈ 0.4 ms against ≈ 4 ms per FFT at 513²).
DENSE_CELLS = 2000


class DomainTooSmallError(RuntimeError):
    """Pressure reached the edge of a non-periodic grid: the domain is too small."""


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
    heights, length, e_star, periodic, tol, edge_contact :
        The problem that was solved (``heights`` is the caller's array, not a copy).
    window : tuple of slice
        Rows and columns of the grid on which the last solve ran.
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
    window: tuple[slice, slice]
    edge_contact: bool = False

    @property
    def cell_area(self) -> float:
        """Area ``Δ²`` of one grid cell."""
        return (self.length / self.heights.shape[0]) ** 2

    @property
    def contact_area(self) -> float:
        """Real contact area: cells in contact × ``Δ²``."""
        return float(np.count_nonzero(self.contact)) * self.cell_area

    def gap(self) -> np.ndarray:
        """Gap ``(z − min z) − d + u`` on the whole grid (one full-grid convolution)."""
        u = displacement(self.pressure, length=self.length, e_star=self.e_star,
                         periodic=self.periodic)
        return (self.heights - self.heights.min()) - self.depth + u


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


def _gap_state(gap, pressure, support):
    """Depth, relative complementarity error and the penetrating free cells of a gap field.

    ``gap`` and ``pressure`` are flat views of the window, ``support`` the flat
    indices of the contact set ``c = {p > 0}``. The depth ``d`` is the mean gap
    over ``c``; the error is ``max(max_c |g − d|, max_(not c) (d − g)) / d``;
    the penetrating free cells are ``{p = 0, g < d}`` (flat indices).
    """
    depth = float(gap[support].mean())
    inner = float(np.abs(gap[support] - depth).max())
    candidates = np.flatnonzero(gap < depth)
    below = candidates[pressure[candidates] == 0.0]
    outer = depth - float(gap[below].min()) if below.size else 0.0
    return depth, max(inner, outer) / abs(depth), below


def _polonsky_keer(lift, operator, total, pressure, tol, maxiter):
    """Polonsky & Keer (1999) CG on one window; returns (p, depth, iterations, converged, error).

    ``lift`` are the heights above the lowest point, ``total`` the required
    ``Σ p`` (force/Δ²). Stopping test, with ``g = lift + u(p)`` and ``ḡ`` its
    mean over the contact set ``c = {p > 0}``:
    ``max_c |g − ḡ| ≤ tol·ḡ`` and ``min_(not c) (g − ḡ) ≥ −tol·ḡ``.

    The contact set is kept as an index array, so that besides the one
    convolution an iteration makes only a few passes over the window (the
    gap, the search for penetrating free cells, the update of ``u``).
    One convolution instead of P&K's two: the new pressure is
    ``s (p − τ t + Δp)`` where ``Δp`` (clipped and overlapping cells) is
    usually a handful of cells, so ``u`` is updated as
    ``s (u − τ K t + K Δp)`` with ``K Δp`` summed column by column. ``u`` is
    recomputed by FFT when ``Δp`` is large, every ``_REFRESH`` updates, and
    before convergence is accepted.
    """
    pressure = pressure * (total / pressure.sum())
    flat_pressure = pressure.reshape(-1)
    support = np.flatnonzero(flat_pressure)
    displacement = operator(pressure)
    exact, since_exact = True, 0
    direction = np.zeros_like(pressure)
    flat_direction = direction.reshape(-1)
    direction_support = support
    gap = np.empty_like(pressure)
    flat_gap = gap.reshape(-1)
    conjugate = False
    norm_old = 1.0
    error = math.inf
    column_limit = operator.column_limit(pressure.shape)
    for iteration in range(maxiter + 1):
        np.add(displacement, lift, out=gap)
        depth, error, below = _gap_state(flat_gap, flat_pressure, support)
        if error <= tol and not exact:
            displacement, exact, since_exact = operator(pressure), True, 0
            np.add(displacement, lift, out=gap)
            depth, error, below = _gap_state(flat_gap, flat_pressure, support)
        if error <= tol:
            return pressure, depth, iteration, True, error
        if iteration == maxiter:
            break
        residual = flat_gap[support] - depth
        norm = float(residual @ residual)
        values = residual + (norm / norm_old) * flat_direction[support] if conjugate else residual
        norm_old = norm
        flat_direction[direction_support] = 0.0
        flat_direction[support] = values
        direction_support = support
        response = operator(direction)
        on_contact = response.reshape(-1)[support]
        curvature = float((on_contact - on_contact.mean()) @ values)
        step = norm / curvature if curvature > 0 else 1.0 / operator.self_coefficient
        trial = flat_pressure[support] - step * values
        clipped = trial <= 0.0
        flat_pressure[support] = np.where(clipped, 0.0, trial)
        # cells with zero pressure and a negative gap enter the contact set
        overlap = np.concatenate([below, support[clipped & (residual < 0.0)]])
        flat_pressure[overlap] = -step * (flat_gap[overlap] - depth)
        conjugate = overlap.size == 0
        # Δp = p − (p_old − τ t): nonzero on the clipped and the entering free cells
        changed = np.concatenate([support[clipped], below])
        delta = np.concatenate([flat_pressure[support[clipped]] - trial[clipped],
                                flat_pressure[below]])
        support = np.concatenate([support[~clipped], overlap])  # disjoint parts
        scale = total / flat_pressure[support].sum()
        flat_pressure[support] *= scale
        if len(changed) <= column_limit and since_exact < _REFRESH:
            response *= step
            displacement -= response
            operator.add_columns(displacement, delta, changed)
            displacement *= scale
            exact, since_exact = False, since_exact + 1
        else:
            displacement, exact, since_exact = operator(pressure), True, 0
    return pressure, depth, maxiter, False, error


def _box(mask: np.ndarray, operator) -> tuple[slice, slice]:
    """Window covering ``mask``, grown to the largest size with the same FFT cost."""
    n = mask.shape[0]
    window = []
    for axis in (1, 0):
        lines = np.flatnonzero(mask.any(axis=axis))
        lo, hi = int(lines[0]), int(lines[-1]) + 1
        size = operator.window_size(hi - lo)
        lo = max(0, min(lo - (size - (hi - lo)) // 2, n - size))
        window.append(slice(lo, lo + size))
    return tuple(window)


def _start(previous, lift, depth_bound):
    """Starting pressure on some cells: ``previous`` (a neighbouring solution on the
    same cells, or ``None``) where it is positive anywhere, else unit pressure on the
    cells with ``lift ≤ depth_bound``."""
    if previous is not None and np.any(previous > 0):
        return np.maximum(previous, 0.0)
    return (lift <= depth_bound).astype(float)


def _solve_candidates(lift, operator, total, initial, tol, maxiter, depth_bound):
    """Periodic contact solved on the cells that can touch, with a dense influence matrix.

    A periodic displacement satisfies ``u ≥ G_min Σp`` (``G_min < 0`` the most
    negative kernel value), so a contact cell, where ``lift = d − u``, has
    ``lift ≤ d + |G_min| Σp``. With ``d ≤ depth_bound`` every contact cell is among
    the candidates ``lift ≤ depth_bound + |G_min| Σp``, and a solution on them whose
    depth is ``≤ depth_bound`` leaves a positive gap everywhere else: it is the
    solution on the whole grid. Restricting the cells that may touch makes the body
    more compliant, so a larger depth from the candidates bounds the true one and a
    second pass with it as the bound succeeds. Returns ``None`` (use the FFT
    solver) when the candidates are more than :data:`DENSE_CELLS`.
    """
    n = lift.shape[0]
    flat_lift = lift.reshape(-1)
    reach = -operator.min_coefficient * total
    iterations = 0
    while True:
        cells = np.flatnonzero(flat_lift <= depth_bound + reach)
        if cells.size > DENSE_CELLS:
            return None
        dense = DenseOperator(operator.influence_matrix(*np.divmod(cells, n)))
        start = _start(None if initial is None else initial.reshape(-1)[cells], flat_lift[cells],
                       depth_bound)
        p_cells, depth, spent, converged, error = _polonsky_keer(
            flat_lift[cells], dense, total, start, tol, maxiter - iterations)
        iterations += spent
        if depth <= depth_bound or not converged or iterations >= maxiter:
            break
        depth_bound, initial = depth, np.zeros(n * n)
        initial[cells] = p_cells
    pressure = np.zeros(n * n)
    pressure[cells] = p_cells
    return pressure.reshape(n, n), depth, iterations, converged, error


def _solve(heights, force, length, e_star, periodic, tol, maxiter, initial, depth_bound,
           edge_contact):
    n = heights.shape[0]
    operator = operator_for(n, float(length), float(e_star), bool(periodic))
    lift = heights - heights.min()
    total = force / (length / n) ** 2
    full = (slice(0, n), slice(0, n))
    if initial is None or not np.any(initial > 0):
        initial = None
    if depth_bound is None:  # cold start: the depth that touches the 64 lowest cells
        depth_bound = np.quantile(lift, min(1.0, 64.0 / lift.size))
    if periodic:
        window = full
        solution = None
        if math.isfinite(depth_bound) and depth_bound > 0:
            solution = _solve_candidates(lift, operator, total, initial, tol, maxiter, depth_bound)
        if solution is None:  # from the neighbouring solution, or uniform pressure
            start = _start(initial, lift, math.inf)
            solution = _polonsky_keer(lift, operator, total, start, tol, maxiter)
        p, depth, iterations, converged, error = solution
    else:
        iterations = 0
        while True:
            window = _box(lift <= depth_bound, operator)
            local = lift[window]
            start = _start(None if initial is None else initial[window], local, depth_bound)
            p_window, depth, spent, converged, error = _polonsky_keer(
                local, operator, total, start, tol, maxiter - iterations)
            iterations += spent
            outside = np.ones((n, n), dtype=bool)
            outside[window] = False
            lowest_outside = lift[outside].min(initial=math.inf)
            if depth < lowest_outside or not converged or iterations >= maxiter:
                break
            # The box solution is an upper bound of the true depth: one more
            # enlargement (at most 4× the bound) suffices or progresses.
            depth_bound = min(depth, 4.0 * depth_bound) if depth_bound > 0 else depth
            initial = np.zeros((n, n))
            initial[window] = p_window
        p = np.zeros((n, n))
        p[window] = p_window
        edge = np.concatenate([p[0], p[-1], p[:, 0], p[:, -1]])
        if not edge_contact and np.any(edge > 0):
            raise DomainTooSmallError(
                f"the contact reached the edge of the {n}x{n} non-periodic grid at "
                f"force {force:g}: enlarge the grid (length and n) or lower the load "
                f"(a finite indenter whose face is the whole grid: edge_contact=True)")
    return ContactState(
        force=float(p.sum() * (length / n) ** 2), depth=float(depth), pressure=p,
        contact=p > 0, iterations=int(iterations), converged=bool(converged),
        gap_error=float(error), heights=heights, length=float(length), e_star=float(e_star),
        periodic=bool(periodic), tol=float(tol), window=window, edge_contact=bool(edge_contact))


def _check_solver_args(length, e_star, tol, maxiter):
    check_finite_positive("length", length)
    check_finite_positive("e_star", e_star)
    check_finite_positive("tol", tol)
    if isinstance(maxiter, bool) or not isinstance(maxiter, int) or maxiter < 1:
        raise ValueError(f"maxiter must be a positive integer, got {maxiter!r}")


def solve(heights, *, force: float, length: float, e_star: float, periodic: bool = False,
          tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, initial=None,
          windowed: bool = True, edge_contact: bool = False) -> ContactState:
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
    bound = None if windowed else math.inf
    return _solve(heights, float(force), length, e_star, periodic, tol, maxiter, initial, bound,
                  edge_contact)


def iter_load_path(heights, forces, *, length: float, e_star: float, periodic: bool = False,
                   tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, edge_contact: bool = False,
                   progress=None) -> Iterator[ContactState]:
    """Solve at each of ``forces`` in order, yielding each state as soon as it is solved.

    Same parameters and result per force as :func:`solve`. Each solve is
    warm-started from the previous state only, so a caller that drops each
    state after processing it keeps at most two pressure arrays alive.
    Non-periodic solves also inherit a depth bound: ``d(F)`` is concave with
    ``d(0) = 0`` (the contact set grows with the load, so ``dF/dd`` does not
    decrease), hence ``d(F) ≤ d(F₀)·max(1, F/F₀)`` with ``F₀`` the previous force.

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
    return _iter_states(heights, forces, length, e_star, periodic, tol, maxiter, edge_contact,
                        progress)


def _iter_states(heights, forces, length, e_star, periodic, tol, maxiter, edge_contact, progress):
    previous = None
    for i, force in enumerate(forces):
        initial = None if previous is None else previous.pressure
        bound = None if previous is None else previous.depth * max(1.0, force / previous.force)
        state = _solve(heights, force, length, e_star, periodic, tol, maxiter, initial, bound,
                       edge_contact)
        if progress is not None:
            progress(i + 1, len(forces), state)
        previous = state
        yield state


def load_path(heights, forces, *, length: float, e_star: float, periodic: bool = False,
              tol: float = 1e-8, maxiter: int = DEFAULT_MAXITER, edge_contact: bool = False,
              progress=None) -> list[ContactState]:
    """All states of :func:`iter_load_path` as a list (same parameters and states).

    ``progress``, if given, is called as ``progress(i, len(forces), state)``
    after each solve.
    """
    return list(iter_load_path(heights, forces, length=length, e_star=e_star, periodic=periodic,
                               tol=tol, maxiter=maxiter, edge_contact=edge_contact,
                               progress=progress))


def stiffness(state: ContactState, *, method: str = "punch", tol: float | None = None,
              rel_step: float = 1e-3) -> float:
    """Incremental normal stiffness ``k = dF/dd`` at ``state`` (force/length).

    Parameters
    ----------
    state : ContactState
    method : {"punch", "difference"}
        ``"punch"`` (default): the exact tangent stiffness of the discrete
        problem: the force of a rigid flat punch whose footprint is the contact
        set, pressed by unit depth, i.e. ``Δ² Σ p`` with ``K_cc p = 1`` on the
        contact set ``c`` (symmetric positive definite; conjugate gradients,
        stopped when ``‖K_cc p − 1‖ ≤ tol ‖1‖``). Between changes of the
        contact set ``F(d)`` is linear with exactly this slope.
        ``"difference"``: the central difference quotient
        ``(F₊ − F₋)/(d₊ − d₋)`` of two extra solves at ``F(1 ± rel_step)``,
        as in Pohrt & Popov (2013).
    tol : float, optional
        Tolerance of the punch solve (default: ``state.tol``), keyword-only.
    rel_step : float
        Relative force step of the difference quotient.

    Returns
    -------
    float
        Stiffness; ``inf`` for a periodic contact covering the whole grid.
    """
    if method == "difference":
        check_finite_positive("rel_step", rel_step)
        if rel_step >= 1:
            raise ValueError(f"rel_step must be < 1, got {rel_step!r}")
        tol = state.tol if tol is None else tol
        check_finite_positive("tol", tol)
        # d(F) is increasing and concave: d(F(1 ± ε)) ≤ d(F)·(1 + ε) bounds both windows.
        upper, lower = (
            _solve(state.heights, state.force * (1 + sign * rel_step), state.length, state.e_star,
                   state.periodic, tol, DEFAULT_MAXITER, state.pressure,
                   state.depth * (1 + rel_step), state.edge_contact)
            for sign in (1, -1))
        return (upper.force - lower.force) / (upper.depth - lower.depth)
    if method != "punch":
        raise ValueError(f"method must be 'punch' or 'difference', got {method!r}")
    tol = state.tol if tol is None else tol
    check_finite_positive("tol", tol)
    n = state.heights.shape[0]
    if state.periodic and np.all(state.contact):
        return math.inf
    operator = operator_for(n, state.length, state.e_star, state.periodic)
    footprint = state.contact[state.window]
    count = int(np.count_nonzero(footprint))
    if count <= DENSE_CELLS:
        system = operator.influence_matrix(*np.nonzero(footprint))
    else:
        field = np.zeros(footprint.shape)

        def matvec(values):
            field[footprint] = values.ravel()
            return operator(field)[footprint]

        system = LinearOperator((count, count), matvec=matvec, dtype=float)
    unit_depth = np.ones(count)
    start = unit_depth / operator.self_coefficient
    punch, info = cg(system, unit_depth, x0=start, rtol=tol, atol=0.0, maxiter=10 * count + 100)
    if info != 0:
        raise RuntimeError(f"the flat-punch stiffness solve did not converge in {info} iterations")
    return float(punch.sum() * state.cell_area)
