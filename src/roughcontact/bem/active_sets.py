"""Where the kernels of :mod:`roughcontact.bem.solver` run: windows, candidate cells, working sets.

:func:`equilibrium` solves one load on the whole grid by solving on a smaller
set of cells and checking a posteriori that the result holds on the whole grid:

Windowing (non-periodic only): a compressive load pushes the surface away
(``u > 0``), so a cell can only be in contact where ``z − min z ≤ d``. The
solver bounds ``d`` from above, solves on the bounding box of that region,
and accepts the result only if every cell outside the box has
``z − min z > d``, in which case it is the solution on the whole grid;
otherwise it enlarges the box and solves again.

Candidate cells (periodic): the periodic displacement can be negative but not
below ``G_min Σp`` (``G_min`` the kernel's minimum), so a contact cell has
``z − min z ≤ d + |G_min| Σp``. While those cells number at most
:func:`dense_limit` (small loads on a nominally flat surface), the solver works
on them alone with a dense influence matrix, accepts the result when its depth
is within the bound, and otherwise solves again with the larger bound.

Working set (periodic, warm-started): when the candidates are too many, an
active-set scheme solves on a working set ``W`` (the previous contact set and
the cells that were closest to touching) with a dense matrix, computes the gap
of that solution on the whole grid with one FFT convolution and accepts it when
no cell outside ``W`` penetrates; otherwise the penetrating cells join ``W``
(:func:`solve_working_set`). The punch stiffness on at most :func:`dense_limit`
cells uses a dense matrix too (:mod:`roughcontact.bem.punch`).

All these arguments hold with a hardness cap too: a cell with pressure still
has ``g ≤ 0``, and the acceptance tests are a posteriori.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .operators import DenseOperator

__all__ = ["DENSE_BYTES", "DENSE_CELLS", "WORKING_MARGIN", "bounding_box", "dense_limit", "equilibrium",
           "solve_candidates", "solve_working_set"]

#: Dense influence matrices on at most this many cells on a grid (or padded window)
#: of 513² (2000² doubles = 32 MB; a product costs about as much as an FFT
#: convolution of 513²); :func:`dense_limit` scales it with the FFT cost.
DENSE_CELLS = 2000
#: Largest dense influence matrix on any grid, in bytes (4096² doubles).
DENSE_BYTES = 128 * 2**20
#: The first working set of a warm-started periodic solve adds to the previous contact
#: set ``c₀`` the ``⌈WORKING_MARGIN |c₀| (F/F₀ − 1)⌉ + 16`` free cells with the
#: smallest previous gap (see :func:`solve_working_set`).
WORKING_MARGIN = 1.5
#: Tolerance of the working-set solves until no cell outside penetrates (then ``tol``).
_LOOSE_TOL = 1e-4
#: At most ``|W|/_GROWTH + 16`` penetrating cells (the deepest) join ``W`` at a time.
_GROWTH = 4


def bounding_box(mask: np.ndarray) -> tuple[slice, slice]:
    """Rows and columns of the bounding box of the true cells of *mask* (not empty)."""
    rows, cols = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
    return slice(int(rows[0]), int(rows[-1]) + 1), slice(int(cols[0]), int(cols[-1]) + 1)


def _window_box(mask: np.ndarray, operator) -> tuple[slice, slice]:
    """Window covering ``mask``, grown to the largest size with the same FFT cost."""
    n = mask.shape[0]
    window = []
    for side in bounding_box(mask):
        lo, hi = side.start, side.stop
        size = operator.window_size(hi - lo)
        lo = max(0, min(lo - (size - (hi - lo)) // 2, n - size))
        window.append(slice(lo, lo + size))
    return tuple(window)


def _lowest_outside(lift: np.ndarray, window: tuple[slice, slice]) -> float:
    """Smallest ``lift`` outside ``window`` (``inf`` if none), from the four strips around it
    (views: no copy of the grid)."""
    rows, cols = window
    strips = (lift[: rows.start], lift[rows.stop:], lift[rows, : cols.start], lift[rows, cols.stop:])
    return min((float(strip.min()) for strip in strips if strip.size), default=math.inf)


def _start_pressure(previous, lift, depth_bound):
    """Starting pressure on some cells: ``previous`` (a neighbouring solution on the
    same cells, or ``None``) where it is positive anywhere, else unit pressure on the
    cells with ``lift ≤ depth_bound``."""
    if previous is not None and np.any(previous > 0):
        return np.maximum(previous, 0.0)
    return (lift <= depth_bound).astype(float)


def solve_candidates(lift, operator, total, initial, tol, maxiter, depth_bound, kernel, min_cells=0):
    """Periodic contact solved on the cells that can touch, with a dense influence matrix.

    A periodic displacement satisfies ``u ≥ G_min Σp`` (``G_min < 0`` the most
    negative kernel value), so a contact cell, where ``lift = d − u``, has
    ``lift ≤ d + |G_min| Σp``. With ``d ≤ depth_bound`` every contact cell is among
    the candidates ``lift ≤ depth_bound + |G_min| Σp``, and a solution on them whose
    depth is ``≤ depth_bound`` leaves a positive gap everywhere else: it is the
    solution on the whole grid. Restricting the cells that may touch makes the body
    more compliant, so a larger depth from the candidates bounds the true one and a
    second pass with it as the bound succeeds. Returns ``None`` (use the working set
    or the FFT solver) when the candidates are more than :func:`dense_limit`. ``kernel`` is
    :func:`polonsky_keer` or a :func:`capped_kernel` (the argument holds for it
    too: a contact cell still has ``g ≤ 0``). Fewer candidates than ``min_cells`` (with a cap
    ``H``, ``⌈Σp/H⌉``: the fewest cells that carry the load) also return ``None``.
    """
    n = lift.shape[0]
    flat_lift = lift.reshape(-1)
    reach = -operator.min_coefficient * total
    iterations = 0
    while True:
        cells = np.flatnonzero(flat_lift <= depth_bound + reach)
        if cells.size > dense_limit(operator) or cells.size < min_cells:
            return None
        dense = DenseOperator(operator.influence_matrix(*np.divmod(cells, n)))
        start = _start_pressure(None if initial is None else initial.reshape(-1)[cells],
                                flat_lift[cells], depth_bound)
        result = kernel(flat_lift[cells], dense, total, start, tol, maxiter - iterations)
        iterations += result.iterations
        if result.depth <= depth_bound or not result.converged or iterations >= maxiter:
            break
        depth_bound, initial = result.depth, np.zeros(n * n)
        initial[cells] = result.pressure
    pressure = np.zeros(n * n)
    pressure[cells] = result.pressure
    return dataclasses.replace(result, pressure=pressure.reshape(n, n), iterations=iterations)


def dense_limit(operator) -> int:
    """Most cells on which a dense influence matrix replaces FFT convolutions.

    A dense product on ``m`` cells costs ``∝ m²`` (and building the matrix about 50
    products), an FFT convolution of ``N`` cells ``∝ N log N``; :data:`DENSE_CELLS`
    is the break-even on the periodic 513² grid. Periodic grids convolve all
    ``N = n²`` cells whatever the contact, so there the limit is
    ``DENSE_CELLS · max(1, (N log N / (513² log 513²))^(1/2))``, at most the cells of
    a :data:`DENSE_BYTES` matrix (4096 from 1025² on). Free-space windows grow with
    the contact, so their break-even stays at :data:`DENSE_CELLS`.
    """
    if not operator.periodic:
        return DENSE_CELLS
    cells = operator.n**2
    scale = max(1.0, math.sqrt(cells * math.log2(max(cells, 2)) / (513**2 * math.log2(513**2))))
    return min(int(DENSE_CELLS * scale), math.isqrt(DENSE_BYTES // 8))


def _grown(storage: np.ndarray, used: int, size: int, limit: int) -> np.ndarray:
    """``storage`` (its ``used × used`` block kept) with room for ``size × size``, grown
    by half again beyond ``size`` (at most ``limit``) when it is too small."""
    if storage.shape[0] >= size:
        return storage
    grown = np.empty((min(limit, size + size // 2),) * 2)
    grown[:used, :used] = storage[:used, :used]
    return grown


def solve_working_set(lift, operator, total, initial, tol, maxiter, kernel, min_cells=0):
    """Warm-started periodic contact solved on a working set of cells with a dense matrix.

    An active-set scheme with an a posteriori test, like the windows: solve on a
    working set ``W`` (the other cells held at ``p = 0``) with the dense influence
    matrix ``K_WW``, compute the gap ``g = lift + K p`` of that solution on the
    whole grid with one FFT convolution, and accept it when no cell outside ``W``
    penetrates, ``min_(not W) g ≥ d``: the solution on ``W`` then meets the
    stopping test of :func:`polonsky_keer` on the whole grid, so it is the
    whole-grid solution. Otherwise the deepest penetrating cells (at most
    ``|W|/4 + 16`` at a time) join ``W``, the matrix grows by their rows and
    columns, and the solve continues from the current pressure. Until no cell
    outside penetrates, the solves on ``W`` stop at the looser tolerance
    :data:`_LOOSE_TOL`; the accepted one has met ``tol``.

    The first working set is the contact set ``c₀`` of ``initial`` (the previous
    load's solution, total ``F₀``) and the ``⌈WORKING_MARGIN |c₀| (F/F₀ − 1)⌉ + 16``
    free cells with the smallest gap under ``initial``: the cells that come into
    contact as the load grows are mostly those that were closest to it (on the
    1025² flat path two or three FFTs in all, instead of 40–70).

    Returns ``None`` (use the FFT solver) when the first working set exceeds
    :func:`dense_limit` cells; when a later one would, the solve continues on
    the whole grid by FFT from the last pressure. ``kernel`` is
    :func:`polonsky_keer` or a :func:`capped_kernel` (the test holds for it too); the first
    working set has at least ``min_cells`` cells (with a cap ``H``, ``⌈Σp/H⌉``).
    """
    n = lift.shape[0]
    limit = dense_limit(operator)
    flat_lift = lift.reshape(-1)
    previous = np.maximum(initial, 0.0).reshape(-1)
    support = np.flatnonzero(previous)
    if support.size > limit:
        return None
    gap = flat_lift + operator(previous.reshape(n, n)).reshape(-1)
    gap[support] = -math.inf
    extra = math.ceil(WORKING_MARGIN * support.size * max(total / previous.sum() - 1.0, 0.0)) + 16
    extra = min(max(extra, min_cells - support.size + 16), n * n - support.size)
    if support.size + extra > limit:
        return None
    cells = np.sort(np.argpartition(gap, support.size + extra - 1)[: support.size + extra])
    rows, cols = np.divmod(cells, n)
    storage = np.empty((0, 0))
    storage = _grown(storage, 0, cells.size, limit)
    matrix = operator.influence_matrix(rows, cols, out=storage[: cells.size, : cells.size])
    start = previous[cells]
    iterations = 0
    round_tol = max(tol, _LOOSE_TOL)
    while True:
        result = kernel(flat_lift[cells], DenseOperator(matrix), total, start, round_tol,
                        maxiter - iterations)
        iterations += result.iterations
        p_cells = result.pressure
        pressure = np.zeros(n * n)
        pressure[cells] = p_cells
        if not result.converged:
            break
        gap = flat_lift + operator(pressure.reshape(n, n)).reshape(-1)
        gap[cells] = math.inf
        entering = np.flatnonzero(gap < result.depth)
        if entering.size == 0 and round_tol == tol:
            break
        if iterations >= maxiter:  # a solution on W, not (yet) on the grid
            result = dataclasses.replace(
                result, converged=False,
                diagnosis=f"{iterations} iterations spent on working sets of up to {cells.size} cells; "
                          f"{entering.size} cells outside the last one still penetrate")
            break
        if entering.size == 0:
            round_tol, start = tol, p_cells
            continue
        most = cells.size // _GROWTH + 16
        if entering.size > most:  # the deepest first: the others may lift off
            entering = np.sort(entering[np.argpartition(gap[entering], most - 1)[:most]])
        if cells.size + entering.size > limit:  # continue on the whole grid
            result = kernel(lift, operator, total, pressure.reshape(n, n), tol, maxiter - iterations)
            return result.spent(iterations)
        old, size = cells.size, cells.size + entering.size
        new_rows, new_cols = np.divmod(entering, n)
        storage = _grown(storage, old, size, limit)
        operator.influence_matrix(rows, cols, new_rows, new_cols, out=storage[:old, old:size])
        storage[old:size, :old] = storage[:old, old:size].T
        operator.influence_matrix(new_rows, new_cols, out=storage[old:size, old:size])
        matrix = storage[:size, :size]
        cells = np.concatenate([cells, entering])
        rows, cols = np.concatenate([rows, new_rows]), np.concatenate([cols, new_cols])
        start = np.concatenate([p_cells, np.zeros(entering.size)])
    return dataclasses.replace(result, pressure=pressure.reshape(n, n), iterations=iterations)


def equilibrium(lift, operator, total, initial, depth_bound, tol, maxiter, periodic, kernel, min_cells=0):
    """Windowed (non-periodic) or candidate-cell / working-set (periodic) solve of one load.

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
    min_cells : int
        The fewest cells that can carry ``total`` (a capped kernel's ``⌈total/H⌉``; 0: any):
        the periodic candidate and working sets are at least this large.

    Returns
    -------
    tuple
        ``(result, window)``: the :class:`~roughcontact.bem.result.KernelResult` with the
        pressure on the whole grid and the iterations of all passes, and ``window`` the
        slices of the last pass.
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
                                        depth_bound, kernel, min_cells)
            if solution is None and initial is not None:
                solution = solve_working_set(lift, operator, total, initial, tol, maxiter,
                                             kernel, min_cells)
        if solution is None:  # from the neighbouring solution, or uniform pressure
            start = _start_pressure(initial, lift, math.inf)
            solution = kernel(lift, operator, total, start, tol, maxiter)
        return solution, window
    iterations = 0
    while True:
        window = _window_box(lift <= depth_bound, operator)
        local = lift[window]
        start = _start_pressure(None if initial is None else initial[window], local, depth_bound)
        result = kernel(local, operator, total, start, tol, maxiter - iterations)
        iterations += result.iterations
        lowest_outside = _lowest_outside(lift, window)
        if result.depth < lowest_outside or not result.converged or iterations >= maxiter:
            break
        # The box solution is an upper bound of the true depth: one more
        # enlargement (at most 4× the bound) suffices or progresses.
        depth = result.depth
        depth_bound = min(depth, 4.0 * depth_bound) if depth_bound > 0 else depth
        initial = np.zeros((n, n))
        initial[window] = result.pressure
    p = np.zeros((n, n))
    p[window] = result.pressure
    return dataclasses.replace(result, pressure=p, iterations=iterations), window
