"""Constrained conjugate-gradient solves of one load, on windows or candidate cells.

The kernels solve on one window of the grid (or on a set of cells with a
dense influence matrix) for a prescribed total ``Σ p``:

* :func:`polonsky_keer` — force-controlled constrained conjugate gradients of
  Polonsky & Keer, Wear 231, 206 (1999), ``p ≥ 0``;
* :func:`capped_kernel` — the same with ``0 ≤ p ≤ H``
  (:func:`roughcontact.plastic.bounded_polonsky_keer`).

:func:`equilibrium` decides where they run:

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

Both arguments hold with a hardness cap too: a cell with pressure still has
``g ≤ 0``, and the acceptance tests are a posteriori.

:func:`punch_stiffness` is the flat-punch force on a footprint (the exact
tangent stiffness, Barber, Proc. R. Soc. A 459, 53 (2003)), by conjugate
gradients (Hestenes & Stiefel 1952, ``scipy.sparse.linalg.cg``).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.sparse.linalg import LinearOperator, cg

from .operators import DenseOperator
from .plastic import bounded_polonsky_keer

__all__ = ["DENSE_CELLS", "capped_kernel", "equilibrium", "polonsky_keer", "punch_stiffness",
           "solve_candidates"]

#: Incremental displacement updates between two exact (FFT) recomputations.
_REFRESH = 50
#: Periodic contacts whose cells that can touch are at most this many, and punch
#: stiffness solves on at most this many cells, use a dense influence matrix
#: (2000² doubles = 32 MB; a product costs ≈ 0.4 ms against ≈ 4 ms per FFT at 513²).
DENSE_CELLS = 2000


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


def polonsky_keer(lift, operator, total, pressure, tol, maxiter):
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


def _window_box(mask: np.ndarray, operator) -> tuple[slice, slice]:
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


def _start_pressure(previous, lift, depth_bound):
    """Starting pressure on some cells: ``previous`` (a neighbouring solution on the
    same cells, or ``None``) where it is positive anywhere, else unit pressure on the
    cells with ``lift ≤ depth_bound``."""
    if previous is not None and np.any(previous > 0):
        return np.maximum(previous, 0.0)
    return (lift <= depth_bound).astype(float)


def solve_candidates(lift, operator, total, initial, tol, maxiter, depth_bound, kernel):
    """Periodic contact solved on the cells that can touch, with a dense influence matrix.

    A periodic displacement satisfies ``u ≥ G_min Σp`` (``G_min < 0`` the most
    negative kernel value), so a contact cell, where ``lift = d − u``, has
    ``lift ≤ d + |G_min| Σp``. With ``d ≤ depth_bound`` every contact cell is among
    the candidates ``lift ≤ depth_bound + |G_min| Σp``, and a solution on them whose
    depth is ``≤ depth_bound`` leaves a positive gap everywhere else: it is the
    solution on the whole grid. Restricting the cells that may touch makes the body
    more compliant, so a larger depth from the candidates bounds the true one and a
    second pass with it as the bound succeeds. Returns ``None`` (use the FFT
    solver) when the candidates are more than :data:`DENSE_CELLS`. ``kernel`` is
    :func:`polonsky_keer` or a :func:`capped_kernel` (the argument holds for it
    too: a contact cell still has ``g ≤ 0``).
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
        start = _start_pressure(None if initial is None else initial.reshape(-1)[cells],
                                flat_lift[cells], depth_bound)
        p_cells, depth, spent, converged, error = kernel(
            flat_lift[cells], dense, total, start, tol, maxiter - iterations)
        iterations += spent
        if depth <= depth_bound or not converged or iterations >= maxiter:
            break
        depth_bound, initial = depth, np.zeros(n * n)
        initial[cells] = p_cells
    pressure = np.zeros(n * n)
    pressure[cells] = p_cells
    return pressure.reshape(n, n), depth, iterations, converged, error


def equilibrium(lift, operator, total, initial, depth_bound, tol, maxiter, periodic, kernel):
    """Windowed (non-periodic) or candidate-cell (periodic) solve of one load with ``kernel``.

    Parameters
    ----------
    lift : numpy.ndarray
        ``(n, n)`` indenter heights above the depth reference (length unit).
    operator : FreeSpaceOperator or PeriodicOperator
    total : float
        Required ``Σ p`` (force/Δ²).
    initial : numpy.ndarray or None
        Starting pressure on the grid (warm start).
    depth_bound : float or None
        Guess of an upper bound of the depth that sizes the first window or
        candidate set (``None``: the depth touching the 64 lowest cells;
        ``inf``: the whole grid). Only efficiency depends on it.
    tol, maxiter :
        Passed to ``kernel``; ``maxiter`` bounds the iterations of all passes.
    periodic : bool
    kernel : callable
        :func:`polonsky_keer` or a :func:`capped_kernel`.

    Returns
    -------
    tuple
        ``(pressure, depth, iterations, converged, error, window)``, the
        pressure on the whole grid and ``window`` the slices of the last pass.
    """
    n = lift.shape[0]
    full = (slice(0, n), slice(0, n))
    if initial is None or not np.any(initial > 0):
        initial = None
    if depth_bound is None:  # cold start: the depth that touches the 64 lowest cells
        depth_bound = np.quantile(lift, min(1.0, 64.0 / lift.size))
    if periodic:
        window = full
        solution = None
        if math.isfinite(depth_bound) and depth_bound > 0:
            solution = solve_candidates(lift, operator, total, initial, tol, maxiter,
                                        depth_bound, kernel)
        if solution is None:  # from the neighbouring solution, or uniform pressure
            start = _start_pressure(initial, lift, math.inf)
            solution = kernel(lift, operator, total, start, tol, maxiter)
        p, depth, iterations, converged, error = solution
        return p, depth, iterations, converged, error, window
    iterations = 0
    while True:
        window = _window_box(lift <= depth_bound, operator)
        local = lift[window]
        start = _start_pressure(None if initial is None else initial[window], local, depth_bound)
        p_window, depth, spent, converged, error = kernel(
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
    return p, depth, iterations, converged, error, window


def capped_kernel(lift, operator, total, pressure, tol, maxiter, *, hardness):
    """:func:`~roughcontact.plastic.bounded_polonsky_keer` with the elastic kernel's signature."""
    return bounded_polonsky_keer(lift, operator, total, hardness, pressure, tol, maxiter)


def punch_stiffness(operator, footprint: np.ndarray, tol: float) -> float:
    """``Σ p`` of a rigid flat punch of unit depth on ``footprint`` (multiply by ``Δ²``).

    Solves ``K_cc p = 1`` on the cells ``c`` of the bool window ``footprint``
    (symmetric positive definite) by conjugate gradients, stopped when
    ``‖K_cc p − 1‖ ≤ tol ‖1‖``; a dense matrix on at most :data:`DENSE_CELLS`
    cells, FFT products otherwise.
    """
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
    return float(punch.sum())
