"""Constrained conjugate-gradient kernels: the solve of one load on one window or set of cells.

* :func:`polonsky_keer` — force-controlled constrained conjugate gradients of
  Polonsky & Keer, Wear 231, 206 (1999), ``p ≥ 0``;
* :func:`capped_kernel` — the same problem with ``0 ≤ p ≤ H``
  (:func:`roughcontact.bem.bounded.bounded_cg`).

Both return a :class:`~roughcontact.bem.result.KernelResult`.

Where they run (windows, candidate cells, working sets) is decided by
:func:`roughcontact.bem.active_sets.equilibrium`.
"""

from __future__ import annotations

import math

import numpy as np

from .bounded import bounded_cg
from .preconditioner import fourier_inverse
from .result import KernelResult

__all__ = ["KernelResult", "capped_kernel", "polonsky_keer"]

#: Incremental displacement updates between two exact (FFT) recomputations.
_REFRESH = 50
#: The conjugate direction survives cells entering the contact set while they are at
#: most this fraction of it and hold at most :data:`_RESTART_SHARE` of ``‖r‖²``
#: (Polonsky & Keer restart on any entering cell).
_RESTART_FRACTION = 0.01
_RESTART_SHARE = 0.1
#: Iterations without a new smallest error after which every entering cell restarts
#: the direction again (the original rule).
_STALL = 30
#: Polonsky–Keer recomputes ``u`` in single precision (operators with ``single``)
#: while the error exceeds this (see :func:`polonsky_keer`, Precision).
_SINGLE_ERROR = 1e-4

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


def polonsky_keer(lift, operator, total, pressure, tol, maxiter, *, boundary_terms=None):
    """Preconditioned Polonsky & Keer (1999) CG on one window; returns a :class:`KernelResult`.

    ``lift`` are the heights above the lowest point, ``total`` the required
    ``Σ p`` (force/Δ²). Stopping test, with ``g = lift + u(p)`` and ``ḡ`` its
    mean over the contact set ``c = {p > 0}``:
    ``max_c |g − ḡ| ≤ tol·ḡ`` and ``min_(not c) (g − ḡ) ≥ −tol·ḡ``.

    One iteration: the working set ``W = c ∪ b`` holds the contact set and the
    penetrating free cells ``b = {p = 0, g < ḡ}``; the residual is ``r = g − ḡ``
    on ``W``; the preconditioned residual ``z = P_W M r`` applies the FFT-based
    approximate inverse ``M = E*|q|/2`` of the half-space on the window and removes
    the mean on ``W`` (the force constraint; :mod:`roughcontact.bem.preconditioner`,
    after Vollebregt's BCCG-FD, J. Comput. Phys. 257, 333 (2014),
    doi:10.1016/j.jcp.2013.10.042); the direction is ``t = z + (rᵀz/r_oldᵀz_old) t_old``,
    the step ``τ = rᵀt / tᵀ(K t − mean_W K t)`` (P&K's eq. (5)), and
    ``p ← max(p − τ t, 0)`` on ``W`` rescaled to ``Σ p = total``. The penetrating
    cells enter through the same step (P&K give them ``−τ r`` after the step
    on ``c``). Operators without a cell size (the dense matrices of the working
    sets) take ``M = I``: then this is P&K's unpreconditioned iteration.
    Preconditioning cuts the iterations of the largest load of the default sphere
    path 2.0–2.5× on 513² … 4097² (benchmarks/large_grid.py); they still grow with
    the grid, in the first iterations after the warm start, which find the contact set.

    The contact set is kept as an index array, so that besides the one
    convolution (and the preconditioner's transform on the unpadded window, a
    quarter of its cost) an iteration makes only a few passes over the window.
    One convolution instead of P&K's two: the new pressure is
    ``s (p − τ t + Δp)`` where ``Δp`` (the clipped cells) is
    usually a handful of cells, so ``u`` is updated as
    ``s (u − τ K t + K Δp)`` with ``K Δp`` summed column by column. ``u`` is
    recomputed by FFT when ``Δp`` is large, every ``_REFRESH`` updates, and
    before convergence is accepted.

    ``boundary_terms=k`` (default ``None``: off) corrects the preconditioner at the working set's boundary:
    ``z = P_W (M_WW − M_WF [m₀⁻¹ Σ_{j≤k} N^j] M_FW) r``, ``F`` the window's cells outside ``W``,
    ``M_FF = m₀ (I − N)``, ``m₀`` the diagonal of ``M``; its exact form (``k → ∞``) is the Schur complement
    ``((M⁻¹)_WW)⁻¹``, the inverse of the window's half-space restricted to ``W``, where ``M_WW`` alone
    overestimates that inverse at the boundary cells (:meth:`FourierInverse.__call__`). It costs ``k + 1``
    more FFT pairs on the window per iteration and cuts the iterations of the default sphere path by
    17–32 % (``k`` = 0 … 3) on 257² … 1025², but not their growth with the grid, and leaves the time per
    load unchanged (``k`` ≤ 1) or longer (``benchmarks/fixed_set.py``, ``docs/guide/solver.md``).

    Restarts: Polonsky & Keer reset the direction ``t`` whenever a cell enters
    the contact set. After a warm start at a larger load, cells enter and leave
    at the rim of the contact spots for tens of iterations, and the reset makes
    all of them steepest-descent steps. Here ``t`` stays conjugate while the
    entering cells are at most :data:`_RESTART_FRACTION` of the contact set and
    hold at most :data:`_RESTART_SHARE` of ``‖r‖²`` (their ``t_old`` is 0, so a
    large share means a stale direction), with a reset when ``rᵀt ≤ 0``; after
    :data:`_STALL` iterations without a new smallest error every entering cell
    resets ``t`` again.

    Precision: with an operator that offers ``single`` (both grid operators, not
    the dense one) and ``tol <`` :data:`_SINGLE_ERROR`, the response ``K t`` of
    every direction is convolved in single precision (relative error ≈ 10⁻⁶, a
    third cheaper), and so are the recomputations of ``u`` while the error
    exceeds :data:`_SINGLE_ERROR` (the first iterations after a warm start, in
    which the contact set is found). Then ``u`` is recomputed in double precision
    and ``t`` reset; later recomputations, the one before acceptance included,
    are in double precision. The single-precision error of the updates
    ``−τ K t`` shrinks with the residual, as in inexact Krylov methods whose
    products may grow less accurate as they converge (Simoncini & Szyld, SIAM J.
    Sci. Comput. 25, 454 (2003)); the accepted state meets the stopping test
    in double precision.
    """
    if boundary_terms is not None and (isinstance(boundary_terms, bool) or not isinstance(boundary_terms, int)
                                       or boundary_terms < 0):
        raise ValueError(f"boundary_terms must be None or an integer >= 0, got {boundary_terms!r}")
    # C order: the flat views below must share memory with the arrays they update
    pressure = np.ascontiguousarray(pressure * (total / pressure.sum()))
    shape = pressure.shape
    flat_pressure = pressure.reshape(-1)
    support = np.flatnonzero(flat_pressure)
    inverse = fourier_inverse(operator)
    single = tol < _SINGLE_ERROR and hasattr(operator, "single")
    respond = convolve = operator.single if single else operator
    displacement = convolve(pressure)
    exact, since_exact = True, 0
    direction = np.zeros_like(pressure)
    flat_direction = direction.reshape(-1)
    direction_support = support
    gap = np.empty_like(pressure)
    flat_gap = gap.reshape(-1)
    conjugate, entered = False, 0
    fraction, best_error, best_iteration = _RESTART_FRACTION, math.inf, 0
    slope_old = 1.0
    error = math.inf
    column_limit = operator.column_limit(shape)
    for iteration in range(maxiter + 1):
        np.add(displacement, lift, out=gap)
        depth, error, below = _gap_state(flat_gap, flat_pressure, support)
        if single and error < _SINGLE_ERROR:  # double precision from here on
            single, convolve, conjugate = False, operator, False
            displacement, exact, since_exact = operator(pressure), True, 0
            np.add(displacement, lift, out=gap)
            depth, error, below = _gap_state(flat_gap, flat_pressure, support)
        if error <= tol and not exact:
            displacement, exact, since_exact = operator(pressure), True, 0
            np.add(displacement, lift, out=gap)
            depth, error, below = _gap_state(flat_gap, flat_pressure, support)
        if error <= tol:
            return KernelResult(pressure=pressure, depth=depth, iterations=iteration, converged=True,
                                error=error)
        if iteration == maxiter:
            break
        working = np.concatenate([support, below])
        residual = flat_gap[working] - depth
        if inverse is None:
            values = residual - residual.mean()
        else:
            values = inverse(shape, working, residual, boundary_terms=boundary_terms)
        norm = float(residual @ values)
        slope = norm
        if error < best_error:
            best_error, best_iteration = error, iteration
        elif iteration - best_iteration >= _STALL:
            fraction = 0.0  # no progress: restart on every entering cell from now on
        if conjugate and entered:  # the newcomers are the last cells of the contact set
            newcomers = residual[support.size - entered: support.size]
            conjugate = float(newcomers @ newcomers) <= _RESTART_SHARE * float(residual @ residual)
        if conjugate and slope_old > 0.0:
            candidate = values + (norm / slope_old) * flat_direction[working]
            candidate_slope = float(residual @ candidate)
            if candidate_slope > 0.0:
                values, slope = candidate, candidate_slope
        slope_old = norm
        flat_direction[direction_support] = 0.0
        flat_direction[working] = values
        direction_support = working
        response = respond(direction)
        on_working = response.reshape(-1)[working]
        curvature = float((on_working - on_working.mean()) @ values)
        if curvature > 0:
            step = slope / curvature
        else:
            step = 1.0 / operator.self_coefficient if inverse is None else 1.0
        trial = flat_pressure[working] - step * values
        clipped = trial <= 0.0
        flat_pressure[working] = np.where(clipped, 0.0, trial)
        # Δp = p − (p_old − τ t): nonzero on the clipped cells
        changed = working[clipped]
        delta = -trial[clipped]
        new_support = working[~clipped]
        entered = int(np.count_nonzero(~clipped[support.size:]))
        conjugate = entered <= fraction * new_support.size
        support = new_support
        scale = total / flat_pressure[support].sum()
        flat_pressure[support] *= scale
        if len(changed) <= column_limit and since_exact < _REFRESH:
            response *= step
            displacement -= response
            operator.add_columns(displacement, delta, changed)
            displacement *= scale
            exact, since_exact = False, since_exact + 1
        else:
            displacement, exact, since_exact = convolve(pressure), True, 0
    return KernelResult(pressure=pressure, depth=depth, iterations=maxiter, converged=False, error=error,
                        diagnosis=f"{maxiter} iterations spent, relative gap error {error:.3g} > tol {tol:.3g}")


def capped_kernel(lift, operator, total, pressure, tol, maxiter, *, hardness):
    """:func:`~roughcontact.bem.bounded.bounded_cg` with the elastic kernel's signature."""
    return bounded_cg(lift, operator, total, hardness, pressure, tol=tol, maxiter=maxiter)
