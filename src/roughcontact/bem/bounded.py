"""The hardness-capped kernel: force-controlled contact with ``0 ≤ p ≤ H``, convergent by construction.

The problem (:mod:`roughcontact.bem.plastic`) is the strictly convex quadratic programme

    minimise ``E(p) = ½ pᵀK p + pᵀ lift``   over   ``Ω = {0 ≤ p ≤ H, Σ p = T}``,

``K`` the symmetric positive definite influence operator, ``T`` the force over ``Δ²``. Its
minimiser ``p*`` is unique. :func:`bounded_cg` combines two kinds of step, as the
modified proportioning method with reduced gradient projections (MPRGP: Dostál & Schöberl,
Comput. Optim. Appl. 30, 23 (2005), doi:10.1007/s10589-005-4557-7) and GPCG (Moré & Toraldo,
SIAM J. Optim. 1, 93 (1991), doi:10.1137/0801008) do for bound constraints, with the force
constraint carried by the projection :func:`project`:

* **conjugate-gradient steps on the face**: the cells strictly between the bounds
  (``F = {0 < p < H}``) move along preconditioned conjugate directions with the mean removed on
  ``F`` (the force stays ``T``), the preconditioner the elastic kernel's FFT approximate inverse
  (:mod:`roughcontact.bem.preconditioner`, Vollebregt's BCCG-FD, J. Comput. Phys. 257, 333 (2014),
  doi:10.1016/j.jcp.2013.10.042); a step that would leave the box stops at the first bound it
  meets (that cell joins the bound) and restarts the directions;
* **projected-gradient steps** ``p ← P(p − α r)``, ``r = g − d`` the gap residual, ``P`` the
  Euclidean projection onto ``Ω``, with the Barzilai–Borwein length ``α = sᵀs/sᵀKs`` of the
  previous one (IMA J. Numer. Anal. 8, 141 (1988)) halved until the Armijo condition
  ``E(p⁺) − E(p) ≤ μ rᵀ(p⁺ − p)`` holds along the projected arc (Bertsekas, IEEE Trans.
  Autom. Control 21, 174 (1976); Calamai & Moré, Math. Program. 39, 93 (1987),
  doi:10.1007/BF02592073). They release cells from the bounds and bring in new ones: one is
  taken when the cells at a bound that want to leave it carry more of the residual than the
  face (MPRGP's proportioning test ``‖β‖ > Γ ‖φ‖``), when the face has one cell, and at least
  every :data:`GRADIENT_EVERY` iterations.

Termination (the argument the tests fuzz). No step increases ``E``: a conjugate-gradient step
minimises the convex ``E`` along a descent direction (``rᵀt = φᵀz > 0``, ``z`` the
preconditioned residual), and a truncated one stops short of that minimum; a projected-gradient
step decreases ``E`` by at least ``μ‖s‖²/α ≥ μ λ_min ‖s‖²``, ``s = p⁺ − p``, since
``rᵀs ≤ −‖s‖²/α`` for a projection. Projected-gradient steps come at least every
:data:`GRADIENT_EVERY` iterations and ``E`` is bounded below on ``Ω``, so ``Σ ‖s_k‖² < ∞``
over them and ``‖s_k‖ → 0``. For a strongly convex quadratic programme ``‖p − p*‖`` is bounded
by a multiple of ``‖P(p − α r) − p‖`` (Luo & Tseng, Ann. Oper. Res. 46, 157 (1993)), so
``E(p_k) → E(p*)`` along those steps, hence along all steps (``E`` is monotone), and
``E(p) − E(p*) ≥ ½ λ_min ‖p − p*‖²`` gives ``p_k → p*``. The gap ``g = lift + K p`` then
converges to ``g*``, which meets the optimality conditions exactly, and every term of the
stopping test tends to 0: it is met after finitely many iterations for any ``tol`` above the
rounding floor of the gap (a few ``10⁻¹⁵ |g|``). There the Armijo condition can no longer be
decided (no projected step has a negative slope, on an exactly recomputed displacement): the kernel
then stops and says so (:attr:`KernelResult.diagnosis`) instead of cycling.
"""

from __future__ import annotations

import math

import numpy as np

from .preconditioner import fourier_inverse
from .result import KernelResult

__all__ = ["GRADIENT_EVERY", "SNAP", "bounded_cg", "optimality", "project"]

#: Cells this close to a bound, relative to ``H``, are put on it (by :func:`project` and after each
#: conjugate-gradient step): a move of at most ``SNAP·H`` per cell, below any tolerance on the gap.
SNAP = 1e-12
#: Most iterations between two projected-gradient steps (the termination argument needs them).
GRADIENT_EVERY = 50
#: Incremental displacement updates between two exact (FFT) recomputations.
_REFRESH = 50
#: ``Γ`` of the proportioning test ``‖β‖ > Γ ‖φ‖`` (Dostál & Schöberl use 1).
_PROPORTION = 1.0
#: ``μ`` of the Armijo condition.
_ARMIJO = 1e-4
#: Halvings of ``α`` before a projected-gradient step is declared undecidable in floating point.
_BACKTRACKS = 50


def project(values: np.ndarray, total: float, hardness: float) -> np.ndarray:
    """Euclidean projection of ``values`` onto ``{0 ≤ p ≤ H, Σ p = total}``.

    The projection is ``clip(values − λ, 0, H)`` with ``λ`` the root of the nonincreasing,
    piecewise linear ``S(λ) = Σ clip(values − λ, 0, H) = total``, found by Newton steps
    ``λ ← λ + (S(λ) − total)/m(λ)`` (``m`` the cells strictly inside the box, the slope's
    magnitude; exact on the segment) safeguarded by bisection of a bracket ``S(lo) ≥ total ≥
    S(hi)`` (Cominetti, Mascarenhas & Silva, Math. Program. Comput. 6, 151 (2014)); it ends when
    ``S(λ) = total`` to rounding or the bracket is two adjacent doubles. Cells within
    :data:`SNAP` ``· H`` of a bound are put on it, and the sum's remaining difference is spread
    over the cells strictly inside the box. Requires
    ``0 ≤ total ≤ H · values.size``.
    """
    low, high = float(values.min()) - hardness, float(values.max())
    guess = high
    scale = max(total, hardness)
    for _ in range(200):
        result = np.clip(values - guess, 0.0, hardness)
        excess = float(result.sum()) - total
        if abs(excess) <= 1e-14 * scale:
            break
        if excess > 0:
            low = guess
        else:
            high = guess
        inside = np.count_nonzero((result > 0.0) & (result < hardness))
        step = guess + excess / inside if inside else math.nan
        guess = step if low < step < high else 0.5 * (low + high)
        if guess in (low, high):
            result = np.clip(values - low, 0.0, hardness)
            break
    return _restore_total(_snap(result, hardness), total, hardness)


def _depth(gap, free, capped, zero):
    """The multiplier ``d``: the mean gap on the free cells; with none, the middle of the
    interval ``max_capped g ≤ d ≤ min_zero g`` that the other conditions allow."""
    if free.any():
        return float(gap[free].mean())
    upper = float(gap[capped].max()) if capped.any() else math.nan
    lower = float(gap[zero].min()) if zero.any() else upper
    return 0.5 * (upper + lower) if capped.any() else lower


def optimality(gap: np.ndarray, pressure: np.ndarray, hardness: float) -> tuple[float, float]:
    """``(d, error)``: the multiplier and the stopping test's left side,
    ``max(max_f |g − d|, max_(p=0) (d − g), max_(p=H) (g − d)) / |d|``, ``f`` the cells
    ``0 < p < H`` (flat arrays)."""
    zero = pressure <= 0.0
    capped = pressure >= hardness
    free = ~(zero | capped)
    depth = _depth(gap, free, capped, zero)
    residual = gap - depth
    inner = float(np.abs(residual[free]).max(initial=0.0))
    outer = float(-residual[zero].min(initial=0.0))
    upper = float(residual[capped].max(initial=0.0))
    return depth, max(inner, outer, upper) / abs(depth)


class _Counts:
    """What the kernel did, for the diagnosis of a solve that ends unconverged."""

    def __init__(self, size):
        self.conjugate = self.gradient = self.backtracks = self.truncated = self.refreshes = 0
        self.switches = np.zeros(size, dtype=np.int32)

    def diagnosis(self, reason, shape, gap, p, hardness, depth):
        worst = np.argsort(-self.switches, kind="stable")[:5]
        worst = worst[self.switches[worst] > 1]
        cells = ", ".join(f"{tuple(int(i) for i in np.unravel_index(c, shape))} ×{int(self.switches[c])}"
                          for c in worst) or "none"
        zero, capped = p <= 0.0, p >= hardness
        violation = np.where(zero, np.maximum(depth - gap, 0.0),
                             np.where(capped, np.maximum(gap - depth, 0.0), np.abs(gap - depth)))
        first = int(np.argmax(violation))
        where = tuple(int(i) for i in np.unravel_index(first, shape))
        side = "at 0" if zero[first] else ("at the cap" if capped[first] else "free")
        return (f"{reason}; tried {self.conjugate} conjugate-gradient steps ({self.truncated} stopped "
                f"at a bound), {self.gradient} projected-gradient steps ({self.backtracks} halvings of "
                f"the step), {self.refreshes} exact recomputations; cells that changed sides most: "
                f"{cells}; largest violation at cell {where} ({side}, "
                f"{violation[first] / abs(depth):.3g} of the depth)")


def bounded_cg(lift, operator, total, hardness, pressure, *, tol, maxiter) -> KernelResult:
    """Force-controlled contact with ``0 ≤ p ≤ H`` on one window (module docstring: the method and
    its termination argument).

    Parameters
    ----------
    lift : numpy.ndarray
        Indenter heights above the depth reference (length unit), any shape the ``operator``
        accepts.
    operator : callable
        Influence operator, ``u = operator(p)``; needs ``self_coefficient``. Grid operators (with a
        ``spacing``) precondition the conjugate-gradient steps; dense ones do not.
    total : float
        Required ``Σ p`` (force/Δ²), ``0 < total ≤ H · lift.size``.
    hardness : float
        Cap ``H`` (pressure unit), > 0.
    pressure : numpy.ndarray
        Starting pressure (same shape as ``lift``); projected onto ``Ω``.
    tol : float
        Stopping test, with ``g = lift + u`` and ``d`` the mean of ``g`` over the free cells
        ``f = {0 < p < H}`` (:func:`optimality`):
        ``max(max_f |g − d|, max_(p=0) (d − g), max_(p=H) (g − d)) ≤ tol·|d|``, checked on an
        exactly recomputed ``u``.
    maxiter : int
        Most iterations (one step each).

    Returns
    -------
    KernelResult
        With a :attr:`~KernelResult.diagnosis` when unconverged: what was tried, the cells that
        changed sides most and the largest violation.
    """
    shape = lift.shape
    flat_lift = lift.reshape(-1)
    size = flat_lift.size
    if not 0.0 < total <= hardness * size * (1.0 + 1e-12):
        raise ValueError(f"total {total!r} is not in (0, hardness × cells = {hardness * size!r}]")
    inverse = fourier_inverse(operator)

    def apply(field):
        return operator(field.reshape(shape)).reshape(-1)

    p = _start(np.asarray(pressure, dtype=float).reshape(-1), total, hardness)
    displacement, exact, since_exact = apply(p), True, 0
    alpha = 1.0 / operator.self_coefficient
    alpha_range = (1e-6 * alpha, 1e6 * alpha)
    counts = _Counts(size)
    previous_class = _classes(p, hardness)
    direction = np.zeros(size)
    face, slope_old, since_gradient = None, 1.0, 0
    reason = f"{maxiter} iterations spent"
    for iteration in range(maxiter + 1):
        gap = flat_lift + displacement
        depth, error = optimality(gap, p, hardness)
        if error <= tol and not exact:  # accept only on an exact displacement
            displacement, exact, since_exact = apply(p), True, 0
            counts.refreshes += 1
            gap = flat_lift + displacement
            depth, error = optimality(gap, p, hardness)
        if error <= tol:
            return KernelResult(pressure=p.reshape(shape), depth=depth, iterations=iteration,
                                converged=True, error=error)
        if iteration == maxiter:
            break
        classes = _classes(p, hardness)
        counts.switches += classes != previous_class
        previous_class = classes
        residual = gap - depth
        free = np.flatnonzero(classes == 1)
        phi = residual[free] - residual[free].mean() if free.size else residual[free]
        entering = np.minimum(residual[classes == 0], 0.0)    # at 0, wanting pressure
        leaving = np.maximum(residual[classes == 2], 0.0)     # at the cap, wanting less
        chopped = float(entering @ entering + leaving @ leaving)
        if (free.size < 2 or since_gradient >= GRADIENT_EVERY
                or chopped > _PROPORTION**2 * float(phi @ phi)):
            step = _gradient_step(p, residual, alpha, total, hardness, apply, counts)
            if step is None:
                if not exact:   # the updated displacement may hide the descent: recompute, retry
                    displacement, exact, since_exact = apply(p), True, 0
                    counts.refreshes += 1
                    continue
                reason = ("no step decreases the energy in floating point (the rounding floor of the "
                          f"gap, error {error:.3g} > tol {tol:.3g})")
                break
            p, response, alpha = step[0], step[1], min(max(step[2], alpha_range[0]), alpha_range[1])
            face, since_gradient = None, 0
        else:
            values = phi if inverse is None else inverse(shape, free, phi)
            slope = float(phi @ values)
            if face is not None and np.array_equal(face, free) and slope_old > 0.0:
                candidate = values + (slope / slope_old) * direction[free]
                if float(phi @ candidate) > 0.0:
                    values = candidate
            slope_old = slope
            direction[:] = 0.0
            direction[free] = values
            response = apply(direction)
            on_face = response[free]
            curvature = float((on_face - on_face.mean()) @ values)
            descent = float(phi @ values)
            if curvature <= 0.0 or descent <= 0.0:
                since_gradient = GRADIENT_EVERY  # a projected-gradient step next
                face = None
                continue
            tau = descent / curvature
            current = p[free]
            with np.errstate(divide="ignore", invalid="ignore"):
                room = np.where(values > 0.0, current / values,
                                np.where(values < 0.0, (current - hardness) / values, math.inf))
            limit = int(np.argmin(room))
            counts.conjugate += 1
            since_gradient += 1
            if tau < room[limit]:
                p[free] = _snap(current - tau * values, hardness)
                face = free
            else:  # stop at the first bound; that cell joins it
                tau = float(room[limit])
                moved = current - tau * values
                moved[limit] = 0.0 if values[limit] > 0.0 else hardness
                p[free] = _snap(np.clip(moved, 0.0, hardness, out=moved), hardness)
                counts.truncated += 1
                face, since_gradient = None, GRADIENT_EVERY  # expansion: a projected-gradient step next
            response *= -tau
        since_exact += 1
        if since_exact >= _REFRESH:
            p = _restore_total(p, total, hardness)
            displacement, exact, since_exact = apply(p), True, 0
            counts.refreshes += 1
        else:
            displacement += response
            exact = False
    gap = flat_lift + displacement
    return KernelResult(pressure=p.reshape(shape), depth=depth, iterations=iteration, converged=False,
                        error=error,
                        diagnosis=counts.diagnosis(reason, shape, gap, p, hardness, depth))


def _snap(p, hardness):
    """*p* with the cells within :data:`SNAP` ``· H`` of a bound put on it, in place: the rounding of
    ``λ`` in :func:`project`, or of a step that takes a ring of cells of equal heights to a bound
    together, would leave them a hair inside, counted free with the residual of a bound cell."""
    p[p <= SNAP * hardness] = 0.0
    p[p >= (1.0 - SNAP) * hardness] = hardness
    return p


def _start(pressure, total, hardness):
    """A point of ``Ω`` near ``pressure``: its projection onto the cells where it is positive
    (the others stay unloaded) when they can carry ``total`` at the cap, else onto all cells."""
    p = np.clip(pressure, 0.0, hardness)
    support = np.flatnonzero(p)
    if hardness * support.size >= total * (1.0 + 1e-12):
        p[support] = project(p[support], total, hardness)
        return p
    return project(p, total, hardness)


def _classes(p, hardness):
    """0 at zero pressure, 2 at the cap, 1 between (int8, flat)."""
    classes = np.ones(p.size, dtype=np.int8)
    classes[p <= 0.0] = 0
    classes[p >= hardness] = 2
    return classes


def _restore_total(p, total, hardness):
    """``p`` with its difference of ``Σ p`` from *total* spread over the free cells (in place)."""
    free = (p > 0.0) & (p < hardness)
    if free.any():
        p[free] += (total - p.sum()) / np.count_nonzero(free)
        np.clip(p, 0.0, hardness, out=p)
    return p


def _gradient_step(p, residual, alpha, total, hardness, apply, counts):
    """One projected-gradient step with the Armijo condition along the projected arc.

    Returns ``(p⁺, K(p⁺ − p), α_BB)`` or ``None`` when no halving of ``α`` yields a decrease
    that floating point can tell (``rᵀs ≥ 0`` for a nonzero projected step ``s``).
    """
    for _ in range(_BACKTRACKS):
        candidate = project(p - alpha * residual, total, hardness)
        step = candidate - p
        slope = float(residual @ step)
        if not slope < 0.0:
            return None
        response = apply(step)
        curvature = float(step @ response)
        if slope + 0.5 * curvature <= _ARMIJO * slope:
            counts.gradient += 1
            bb = float(step @ step) / curvature if curvature > 0.0 else alpha
            return candidate, response, bb
        counts.backtracks += 1
        alpha *= 0.5
    return None
