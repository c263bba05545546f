"""Penetration-hardness plasticity: contact pressure capped at a hardness ``H``.

The half-space is elastic-perfectly plastic in the simplest surface sense
(Almqvist, Sahlin, Larsson & Glavatskih, "On the dry elasto-plastic contact of
nominally flat surfaces", Tribol. Int. 40, 574 (2007), doi:10.1016/j.triboint.2005.11.008;
the same model as ContactMechanics' ``PlasticNonSmoothContactSystem``, Weber et
al., Nat. Commun. 9, 888 (2018)): a cell carries at most the pressure ``H``;
where it would need more, the indenter penetrates it and the overlap becomes
a permanent (plastic) displacement of the surface. Plastic flow creates no
elastic field of its own.

With ``g = lift + u(p) − d`` the gap (``lift`` the indenter's heights above the
reference, ``u`` the elastic displacement, ``d`` the depth) the discrete
problem at force ``F = Σ p Δ²`` is the convex quadratic programme

    minimise ½ pᵀK p + pᵀ lift   subject to   0 ≤ p ≤ H,  Σ p = F/Δ²,

whose optimality conditions, with the depth ``d`` the multiplier of the force
constraint, are

* ``p = 0``       ⇒ ``g ≥ 0``  (no contact),
* ``0 < p < H``   ⇒ ``g = 0``  (elastic contact),
* ``p = H``       ⇒ ``g ≤ 0``  (plastic: the cell flows by ``−g``).

:func:`bounded_polonsky_keer` solves them by Polonsky & Keer's force-controlled
constrained conjugate gradients (Wear 231, 206 (1999)) with the box constraint
``0 ≤ p ≤ H``, as ContactMechanics' ``constrained_conjugate_gradients(hardness=...)``
does: conjugate gradients on the free cells ``0 < p < H``, cells projected onto
the box, cells that violate their condition sent back into the free set, and
the force restored by water-filling (:func:`water_fill`). These set changes are
heuristic; should they stall, projected gradients (:func:`project`), which
converge for any convex quadratic programme, finish the solve. After a solve
the plastic displacement of a cell at the cap is its overlap ``−g``
(:func:`plastic_flow`); it is added to the indenter's heights for the next
load (the surface stays flattened).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["STALL", "bounded_polonsky_keer", "plastic_flow", "project", "water_fill"]


def water_fill(pressure: np.ndarray, total: float, hardness: float, order: np.ndarray) -> None:
    """Restore ``Σ p = total`` in place on the free cells ``0 < p < H``, keeping ``p ≤ H``.

    The cells at the cap keep ``H``; the free cells are scaled by the ``λ``
    with ``Σ_free min(λ p, H) = total − H·#capped`` (water-filling: free cells
    that reach ``H`` join the capped ones), the analogue of Polonsky & Keer's
    rescaling of the contact pressures. If even ``H`` on every free cell is not
    enough, they all get ``H`` and the remainder goes, ``H`` per cell, to the
    unloaded cells in increasing ``order`` (the bearing-area fill), the last one
    taking what is left. If the capped cells alone exceed ``total``, the cells
    with the smallest ``order`` among them keep ``H`` (one takes the rest) and
    all others are unloaded.

    Parameters
    ----------
    pressure : numpy.ndarray
        Flat array of pressures, ``0 ≤ p ≤ H``, modified in place.
    total : float
        Required ``Σ p`` (force/Δ²), > 0.
    hardness : float
        Cap ``H`` (pressure unit).
    order : numpy.ndarray
        Flat array ranking cells for the fills (smallest first), e.g. the gap.
    """
    capped = pressure >= hardness
    free = np.flatnonzero((pressure > 0.0) & ~capped)
    target = total - hardness * np.count_nonzero(capped)
    if target < 0:
        _fill(pressure, np.flatnonzero(capped), total, hardness, order, reset=True)
        return
    if hardness * free.size <= target:
        pressure[free] = hardness
        _fill(pressure, np.flatnonzero(pressure == 0.0), target - hardness * free.size,
              hardness, order, reset=False)
        return
    values = np.sort(pressure[free])[::-1]
    # With the m largest capped: λ_m = (target − m H)/(sum of the others); the first m
    # whose largest uncapped value stays ≤ H under λ_m is the solution (λ_m grows with m).
    rest = values.sum() - np.concatenate([[0.0], np.cumsum(values[:-1])])
    scale = (target - hardness * np.arange(values.size)) / rest
    capped_free = int(np.argmax(scale * values <= hardness))
    pressure[free] = np.minimum(pressure[free] * scale[capped_free], hardness)


def _fill(pressure, cells, amount, hardness, order, *, reset):
    """Put ``amount`` on ``cells``, ``H`` per cell in increasing ``order``, the last one
    the rest; with ``reset`` the pressure is zeroed first."""
    if reset:
        pressure[:] = 0.0
    count = min(int(amount // hardness), cells.size)
    chosen = cells[np.argsort(order[cells], kind="stable")[: count + 1]]
    pressure[chosen[:count]] = hardness
    if chosen.size > count:
        pressure[chosen[count]] = amount - hardness * count


def project(values: np.ndarray, total: float, hardness: float) -> np.ndarray:
    """Euclidean projection of ``values`` onto ``{0 ≤ p ≤ H, Σ p = total}``.

    The projection is ``clip(values − λ, 0, H)`` with ``λ`` the root of the
    decreasing, piecewise linear ``Σ clip(values − λ, 0, H) = total``, found by
    bisection until the bracket is two adjacent doubles; the sum's remaining
    difference (of the order of the bracket) is spread over the free cells.
    """
    low, high = float(values.min()) - hardness, float(values.max())
    for _ in range(200):
        middle = 0.5 * (low + high)
        if middle in (low, high):
            break
        if np.clip(values - middle, 0.0, hardness).sum() > total:
            low = middle
        else:
            high = middle
    result = np.clip(values - low, 0.0, hardness)
    free = (result > 0.0) & (result < hardness)
    if free.any():
        result[free] += (total - result.sum()) / np.count_nonzero(free)
        np.clip(result, 0.0, hardness, out=result)
    return result


def _depth(gap, free, capped, zero):
    """The multiplier ``d``: the mean gap on the free cells; with none, the middle of the
    interval ``max_capped g ≤ d ≤ min_zero g`` that the other conditions allow."""
    if free.any():
        return float(gap[free].mean())
    upper = float(gap[capped].max()) if capped.any() else math.nan
    lower = float(gap[zero].min()) if zero.any() else upper
    return 0.5 * (upper + lower) if capped.any() else lower


def _optimality(gap, p, hardness):
    """``(d, error)``: the multiplier and ``max(max_f |g − d|, max_(p=0) (d − g),
    max_(p=H) (g − d)) / |d|``, with ``f`` the free cells ``0 < p < H``."""
    zero = p <= 0.0
    capped = p >= hardness
    free = ~(zero | capped)
    depth = _depth(gap, free, capped, zero)
    residual = gap - depth
    inner = float(np.abs(residual[free]).max(initial=0.0))
    outer = float(-residual[zero].min(initial=0.0))
    upper = float(residual[capped].max(initial=0.0))
    return depth, max(inner, outer, upper) / abs(depth)


#: Projected-gradient steps between two exact recomputations of the displacement.
_REFRESH = 50
#: Iterations without a new smallest error after which the conjugate-gradient phase
#: of :func:`bounded_polonsky_keer` gives way to projected gradients.
STALL = 50


def bounded_polonsky_keer(lift, operator, total, hardness, pressure, tol, maxiter):
    """Force-controlled constrained CG with ``0 ≤ p ≤ H`` on one window.

    Parameters
    ----------
    lift : numpy.ndarray
        Indenter heights above the depth reference (length unit), any shape
        the ``operator`` accepts.
    operator : callable
        Influence operator, ``u = operator(p)``; needs ``self_coefficient``.
    total : float
        Required ``Σ p`` (force/Δ²).
    hardness : float
        Cap ``H`` (pressure unit), > 0.
    pressure : numpy.ndarray
        Starting pressure (same shape as ``lift``); projected onto the box and
        filled to ``total``.
    tol : float
        Bound on the relative violation of the optimality conditions (module
        docstring). With ``g = lift + u`` and ``d`` the mean of ``g`` over the
        free cells ``f = {0 < p < H}``, iteration stops when
        ``max(max_f |g − d|, max_(p=0) (d − g), max_(p=H) (g − d)) ≤ tol·|d|``.
    maxiter : int
        Maximum iterations (both phases).

    Returns
    -------
    tuple
        ``(pressure, depth, iterations, converged, error)`` as
        :func:`roughcontact.bem.solver.polonsky_keer` (``error`` the left side of
        the stopping test divided by ``|d|``).

    Notes
    -----
    Conjugate-gradient phase, one iteration: the residual ``r = g − d`` on the
    free cells gives the conjugate direction ``t = r + (‖r‖²/‖r_old‖²) t_old``
    (steepest descent after a cell changed sides) and the step
    ``τ = ‖r‖²/(tᵀ(K t − mean_f K t))`` (Polonsky & Keer 1999);
    ``p ← p − τ t`` on the free cells. Cells at 0 with ``g < d`` and cells at
    ``H`` with ``g > d`` change sides with ``p = −τ' r`` and ``p = H − τ' r``,
    ``τ' = min(τ, 1/K_ii)`` (at most what closes the cell's own gap);
    everything is projected onto ``[0, H]`` and the force restored by
    :func:`water_fill`. The set changes are heuristic and can cycle, so after
    :data:`STALL` iterations without a new smallest error the solve continues
    from the best iterate with projected gradients, which converge for any
    convex quadratic programme (Bertsekas, Nonlinear Programming, 2nd ed.
    1999, Prop. 2.3.3): ``p ← p + θ s``, ``s = P(p − α g) − p`` with ``P``
    :func:`project`, ``α = sᵀs/(sᵀKs)`` of the previous step (Barzilai &
    Borwein, IMA J. Numer. Anal. 8, 141 (1988); first ``1/K_ii``) and the
    exact line search ``θ = min(1, −gᵀs/(sᵀKs))`` of the quadratic objective
    ``½ pᵀK p + pᵀ lift``.
    """
    shape = lift.shape
    flat_lift = lift.reshape(-1)
    p = np.clip(pressure.reshape(-1), 0.0, hardness)
    water_fill(p, total, hardness, flat_lift)
    direction = np.zeros_like(p)
    norm_old = 1.0
    conjugate = False
    step = 1.0 / operator.self_coefficient
    best = (math.inf, p, 0)
    for iteration in range(maxiter + 1):
        gap = flat_lift + operator(p.reshape(shape)).reshape(-1)
        depth, error = _optimality(gap, p, hardness)
        if error <= tol:
            return p.reshape(shape), depth, iteration, True, error
        if error < best[0]:
            best = (error, p, iteration)
        if iteration == maxiter or iteration - best[2] >= STALL:
            break
        zero = p <= 0.0
        capped = p >= hardness
        free = ~(zero | capped)
        residual = gap - depth
        values = np.where(free, residual, 0.0)
        norm = float(values @ values)
        if conjugate:
            values += (norm / norm_old) * np.where(free, direction, 0.0)
        direction = values
        norm_old = norm if norm > 0 else 1.0
        if norm > 0:
            response = operator(values.reshape(shape)).reshape(-1)[free]
            curvature = float((response - response.mean()) @ values[free])
            step = norm / curvature if curvature > 0 else 1.0 / operator.self_coefficient
        trial = p - step * values
        entering = (zero & (residual < 0.0)) | (free & (trial <= 0.0) & (residual < 0.0))
        released = capped & (residual > 0.0)
        # a cell changing sides moves by at most what closes its own gap alone
        single = min(step, 1.0 / operator.self_coefficient)
        trial[entering] = -single * residual[entering]
        trial[released] = hardness - single * residual[released]
        np.clip(trial, 0.0, hardness, out=trial)
        conjugate = not (entering.any() or released.any())
        p = trial
        water_fill(p, total, hardness, residual)
    if iteration == maxiter:
        return p.reshape(shape), depth, maxiter, False, error
    return _projected_gradient(flat_lift, shape, operator, total, hardness, best[1], tol,
                               maxiter, iteration + 1)


def _projected_gradient(flat_lift, shape, operator, total, hardness, p, tol, maxiter, spent):
    """Projected-gradient phase of :func:`bounded_polonsky_keer` from the feasible ``p``."""
    def apply(field):
        return operator(field.reshape(shape)).reshape(-1)

    displacement, exact = apply(p), True
    step = 1.0 / operator.self_coefficient
    for iteration in range(spent, maxiter + 1):
        if not exact and (iteration - spent) % _REFRESH == 0:
            displacement, exact = apply(p), True
        depth, error = _optimality(flat_lift + displacement, p, hardness)
        if error <= tol and not exact:  # accept only on an exact displacement
            displacement, exact = apply(p), True
            depth, error = _optimality(flat_lift + displacement, p, hardness)
        if error <= tol:
            return p.reshape(shape), depth, iteration, True, error
        gap = flat_lift + displacement
        if iteration == maxiter:
            break
        direction = project(p - step * gap, total, hardness) - p
        response = apply(direction)
        curvature = float(direction @ response)
        if curvature <= 0:
            break
        slope = float(gap @ direction)
        theta = min(1.0, -slope / curvature) if slope < 0 else 0.0
        p = p + theta * direction
        np.clip(p, 0.0, hardness, out=p)
        displacement += theta * response
        exact = False
        step = float(direction @ direction) / curvature
    return p.reshape(shape), depth, iteration, False, error


def plastic_flow(lift, displacement, pressure, depth, hardness):
    """Cells that flowed and their plastic displacement, after a bounded solve.

    Parameters
    ----------
    lift, displacement, pressure : numpy.ndarray
        Heights above the reference, elastic displacement and pressure on the
        cells solved (same shape).
    depth : float
        Depth of the solve.
    hardness : float
        The cap ``H``.

    Returns
    -------
    plastic : numpy.ndarray
        Bool, cells at the cap whose gap ``g = lift + u − d`` is negative.
    increment : numpy.ndarray
        ``−g`` on those cells, 0 elsewhere (length unit, ≥ 0): the overlap
        that becomes permanent.
    """
    gap = lift + displacement - depth
    plastic = (pressure >= hardness) & (gap < 0.0)
    return plastic, np.where(plastic, -gap, 0.0)
