"""The loads of a partial-slip path, one or two traction components (:func:`roughcontact.bem.partial_slip`).

Each load runs a kernel (:func:`roughcontact.bem.slip.slip_kernel` for ``q_x`` alone,
:func:`roughcontact.bem.slip_vector.vector_slip_kernel` for ``(q_x, q_y)``) on the contact cells
of a window (the free half-space) or of the grid (periodic), with influence products by a dense
matrix on few cells and by FFT otherwise, warm-started from the previous load.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.sparse.linalg import cg

from ..errors import ConvergenceError
from .active_sets import DENSE_BYTES, dense_limit
from .punch import punch_stiffness
from .slip import slip_kernel
from .slip_vector import VectorSlipSolution, vector_slip_kernel, vector_tangent_stiffness

__all__ = ["one_component_loads", "two_component_loads"]


class _DenseInfluence:
    """``v ↦ K v`` by a dense influence matrix on the contact cells, restrictable to a subset."""

    def __init__(self, matrix):
        self.matrix = matrix
        self.self_coefficient = float(matrix[0, 0])

    def __call__(self, values):
        return self.matrix @ values

    def restrict(self, cells):
        return self.matrix[np.ix_(cells, cells)].__matmul__


def _influence(operator, footprint, cells):
    """``v ↦ K v`` on the flat contact *cells* of the window *footprint*: dense or by FFT."""
    if cells.size <= dense_limit(operator):
        return _DenseInfluence(operator.influence_matrix(*np.unravel_index(cells, footprint.shape)))
    field = np.zeros(footprint.shape)
    flat = field.reshape(-1)

    def apply(values):
        flat[cells] = values
        return operator(field).reshape(-1)[cells]

    return apply


def _pair_dense_limit(pair) -> int:
    """Most cells on which the two-component products use a dense ``2m × 2m`` matrix: periodic, the
    normal :func:`~roughcontact.bem.active_sets.dense_limit` (a product of the four times larger
    matrix against two FFTs over the grid; measured on 513², 1647 cells: 4.8 ms against 11 ms) within
    :data:`~roughcontact.bem.active_sets.DENSE_BYTES`; free, half of it (the windows' FFTs are small:
    a sphere of 1810 cells, 3.1 s dense against 0.8 s by FFT for five loads)."""
    if pair.periodic:
        return min(dense_limit(pair), math.isqrt(DENSE_BYTES // 8) // 2)
    return dense_limit(pair) // 2


def _pair_influence(pair, footprint, cells):
    """``(v_x, v_y) ↦ K (v_x, v_y)`` (flat, stacked) on the contact *cells* of *footprint* by the
    two-component operator *pair*: a dense matrix on at most :func:`_pair_dense_limit` cells, else
    two-field FFT products."""
    if cells.size <= _pair_dense_limit(pair):
        return _DenseInfluence(pair.influence_matrix(*np.unravel_index(cells, footprint.shape)))
    fields = np.zeros((2,) + footprint.shape)
    flat = fields.reshape(2, -1)
    m = cells.size

    def apply(values):
        flat[0, cells], flat[1, cells] = values[:m], values[m:]
        ux, uy = pair(fields[0], fields[1])
        return np.concatenate([ux.reshape(-1)[cells], uy.reshape(-1)[cells]])

    apply.self_coefficient = pair.self_coefficient
    return apply


def _stick_stiffness(apply, operator, stick_window, stick, tol) -> float:
    """``Σ q`` of ``K q = 1`` on the stick cells (multiply by ``Δ²``): on the dense matrix's
    submatrix when there is one, else :func:`~roughcontact.bem.punch.punch_stiffness`."""
    if not stick.any():
        return 0.0
    if isinstance(apply, _DenseInfluence):
        matrix = apply.matrix[np.ix_(stick, stick)]
        ones = np.ones(matrix.shape[0])
        solution, info = cg(matrix, ones, x0=ones / matrix[0, 0], rtol=tol, atol=0.0,
                            maxiter=10 * ones.size + 100)
        if info != 0:
            raise ConvergenceError(f"the stick zone's stiffness solve did not converge in {info} iterations")
        return float(solution.sum())
    return punch_stiffness(operator, stick_window, tol)


def _failed(fraction, maxiter, error):
    return ConvergenceError(f"partial slip at Q/(mu P) = {fraction:g} did not converge in {maxiter} products "
                            f"(error {error:.3g})")


def one_component_loads(operator, footprint, cells, bound, fractions, *, tol, maxiter, stiffness, k0):
    """``q_x`` alone (:func:`~roughcontact.bem.slip.slip_kernel`) per fraction: a list of
    ``(q (2, m), slip, (δ_x, 0), k_t, products, error)``; ``k_t`` over ``Δ²`` (``k0`` at
    ``f = 0``, ``nan`` without *stiffness*)."""
    apply = _influence(operator, footprint, cells)
    q = np.zeros(cells.size)  # the first warm start is then q ∝ p
    loads = []
    for fraction in fractions:
        total = fraction * bound.sum()
        if fraction == 0.0 or not cells.size:
            q = np.zeros(cells.size)
            loads.append((np.zeros((2, cells.size)), np.zeros(cells.size, bool), (0.0, 0.0), k0, 0, 0.0))
            continue
        # feasible warm start: the previous tractions, raised towards μp to the new force
        room = bound - q
        start = q + (total - q.sum()) * room / room.sum()
        solution = slip_kernel(apply, bound, total, start, tol=tol, maxiter=maxiter)
        if not solution.converged:
            raise _failed(fraction, maxiter, solution.error)
        k = math.nan
        if stiffness:
            stick_window = np.zeros(footprint.shape, dtype=bool)
            stick_window.reshape(-1)[cells[~solution.slip]] = True
            k = _stick_stiffness(apply, operator, stick_window, ~solution.slip, tol)
        q = solution.traction
        loads.append((np.array([q, np.zeros_like(q)]), solution.slip, (solution.displacement, 0.0), k,
                      solution.iterations, solution.error))
    return loads


def two_component_loads(pair, footprint, cells, bound, fractions, *, tol, maxiter, stiffness, k0):
    """``(q_x, q_y)`` (:func:`~roughcontact.bem.slip_vector.vector_slip_kernel`) per fraction, as
    :func:`one_component_loads`; ``k_t`` the tangent ``dQ_x/dδ_x`` at ``Q_y = 0``
    (:func:`~roughcontact.bem.slip_vector.vector_tangent_stiffness`)."""
    apply = _pair_influence(pair, footprint, cells)
    q = np.zeros((2, cells.size))
    loads = []
    for fraction in fractions:
        total = fraction * bound.sum()
        if fraction == 0.0 or not cells.size:
            q = np.zeros((2, cells.size))
            loads.append((q.copy(), np.zeros(cells.size, bool), (0.0, 0.0), k0, 0, 0.0))
            continue
        # the previous tractions, raised along x towards the cone to the new force
        room = np.maximum(bound - np.hypot(*q), 0.0)
        start = q.copy()
        start[0] += (total - q[0].sum()) * room / room.sum()
        solution = vector_slip_kernel(apply, bound, total, start, tol=tol, maxiter=maxiter)
        if not solution.converged:
            raise _failed(fraction, maxiter, solution.error)
        k = math.nan
        if stiffness:
            k = vector_tangent_stiffness(apply, solution, bound, tol=tol, maxiter=maxiter)
        q = solution.traction
        loads.append((q, solution.slip, solution.displacement, k, solution.iterations, solution.error))
    return loads


def two_component_full_stick(pair, footprint, cells, *, tol, maxiter) -> float:
    """Full-stick ``Q_x/δ_x`` at ``Q_y = 0`` with both components on *cells*, over ``Δ²``."""
    apply = _pair_influence(pair, footprint, cells)
    stuck = VectorSlipSolution(np.zeros((2, cells.size)), np.zeros(cells.size, bool), (1.0, 0.0), 0, True, 0.0)
    return vector_tangent_stiffness(apply, stuck, np.ones(cells.size), tol=tol, maxiter=maxiter)
