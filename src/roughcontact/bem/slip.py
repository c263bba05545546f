"""The one-component partial-slip kernel: tangential tractions ``q_x`` on a contact set under Coulomb
friction (two components: :mod:`roughcontact.bem.slip_vector`).

On the contact set ``C`` of a normal state (pressure ``p``) the tangential traction ``q`` (one
component, along ``x``) at a tangential force ``Q = Σ q Δ²`` solves the convex quadratic
programme

    minimise ½ qᵀK q   subject to   −μp ≤ q ≤ μp on C,  Σ q = Q/Δ²,

``K`` the tangential influence matrix on ``C`` (:mod:`roughcontact.bem.cerruti`). With the
rigid tangential displacement ``δ`` (the multiplier of the force constraint) and ``u = K q``
its optimality conditions are Coulomb's law on the lattice:

* ``|q| < μp`` ⇒ ``u = δ`` (stick),
* ``q = μp``  ⇒ ``u ≤ δ`` (slip along +x: the body moves ahead of the surface),
* ``q = −μp`` ⇒ ``u ≥ δ`` (slip along −x).

Each load is solved as this total (holonomic) problem, which is the incremental one of a
monotone load path as long as no slipping cell reverses or re-sticks (Cattaneo–Mindlin's
setting; Johnson 1985, §7.2). :func:`slip_kernel` is a primal active-set method in the manner
of Kalker's (*Three-dimensional elastic bodies in rolling contact*, Kluwer 1990, ch. 2) and of
Polonsky & Keer's force-controlled iteration (Wear 231, 206 (1999)): on the stick cells,
conjugate gradients (Hestenes & Stiefel 1952) for ``u = δ`` under the force constraint (the
gradient projected on ``Σ Δq = 0``, as Polonsky & Keer subtract the mean gap); stick cells past
``±μp`` go to the bound, slipping cells whose ``u − δ`` has the wrong sign come back, until the
conditions hold to ``tol``.
"""

from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["SlipSolution", "slip_kernel"]

#: Inner iterations between exact recomputations of the stick displacement.
_REFRESH = 50


@dataclasses.dataclass(frozen=True, eq=False)
class SlipSolution:
    """One load of :func:`slip_kernel` (flat arrays over the contact cells).

    Attributes: ``traction`` q (force/length²); ``slip`` bool, at ``±μp``; ``displacement`` δ
    (length); ``iterations`` products spent; ``converged``; ``error`` the relative violation
    ``max(max_stick |u − δ|, max_(q=μp) (u − δ), max_(q=−μp) (δ − u)) / δ``.
    """

    traction: np.ndarray
    slip: np.ndarray
    displacement: float
    iterations: int
    converged: bool
    error: float


def _projected_cg(apply, b, x, tol, maxiter):
    """Minimise ``½xᵀKx + bᵀx`` keeping ``Σ x``; stop at ``max |g − ḡ| ≤ tol |ḡ|``, ``g = Kx + b``.

    Returns ``(x, g, iterations)`` with ``g`` recomputed exactly."""
    g = apply(x) + b
    residual = g - g.mean()
    direction = -residual
    norm = float(residual @ residual)
    iterations = 0
    while iterations < maxiter and np.abs(residual).max() > tol * abs(g.mean()):
        response = apply(direction)
        curvature = float(direction @ response)
        if curvature <= 0.0:
            break
        step = norm / curvature
        x += step * direction
        iterations += 1
        if iterations % _REFRESH == 0:
            g = apply(x) + b
        else:
            g += step * response
        residual = g - g.mean()
        new_norm = float(residual @ residual)
        direction = -residual + (new_norm / norm) * direction
        norm = new_norm
    return x, apply(x) + b, iterations + 1


def slip_kernel(apply, bound, total, start, *, tol, maxiter) -> SlipSolution:
    """Partial slip on ``m`` contact cells at ``Σ q = total``.

    Parameters
    ----------
    apply : callable
        ``v ↦ K v``, the tangential displacement on the cells under tractions ``v`` (both flat,
        length ``m``); if it has a method ``restrict(cells)``, that gives ``K`` restricted to
        the flat indices ``cells`` (e.g. a dense submatrix) as such a callable.
    bound : numpy.ndarray
        ``μ p`` per cell, > 0 (force/length²).
    total : float
        ``Q/Δ²``, ``0 < total < Σ bound``.
    start : numpy.ndarray
        Feasible warm start (``|start| ≤ bound``, any sum: it is shifted onto the constraint).
    tol : float
        Relative violation of the conditions accepted, keyword-only.
    maxiter : int
        Products allowed, keyword-only.

    Returns
    -------
    SlipSolution
    """
    m = bound.size
    q = np.clip(start, -bound, bound).astype(float)
    upper = q >= bound
    lower = q <= -bound
    spent, error, delta = 0, np.inf, 0.0
    zero = np.zeros(m)
    released = np.zeros(m, dtype=bool)
    while spent < maxiter:
        stick = ~(upper | lower)
        if not stick.any():  # every cell at a bound, yet Σq < Σμp: start the active set afresh
            upper[:], lower[:], stick[:] = False, False, True
        fixed = np.where(upper, bound, np.where(lower, -bound, 0.0))
        free = np.flatnonzero(stick)

        if hasattr(apply, "restrict"):
            apply_stick = apply.restrict(free)
        else:
            def apply_stick(values, free=free):
                full = zero.copy()
                full[free] = values
                return apply(full)[free]

        offset = apply(fixed)[free]
        x = q[free]
        x += (total - fixed.sum() - x.sum()) / free.size
        x, _, used = _projected_cg(apply_stick, offset, x, tol, maxiter - spent)
        spent += used + 1
        q = fixed.copy()
        q[free] = x
        over, under = q > bound, q < -bound
        if over.any() or under.any():
            upper |= over
            lower |= under
            q = np.clip(q, -bound, bound)
            continue
        u = apply(q)
        spent += 1
        delta = float(u[stick].mean())
        scale = abs(delta)
        wrong_upper = upper & (u - delta > tol * scale)
        wrong_lower = lower & (delta - u > tol * scale)
        error = max(float(np.abs(u[stick] - delta).max()),
                    float((u - delta)[upper].max(initial=0.0)),
                    float((delta - u)[lower].max(initial=0.0))) / scale
        if error <= tol:
            return SlipSolution(q, upper | lower, delta, spent, True, error)
        if wrong_upper.any() or wrong_lower.any():
            # release the worst violators; a cell released twice goes back one at a time
            again = (wrong_upper | wrong_lower) & released
            if again.any():
                worst = np.argmax(np.where(wrong_upper, u - delta, np.where(wrong_lower, delta - u, -np.inf)))
                wrong_upper = wrong_upper & (np.arange(m) == worst)
                wrong_lower = wrong_lower & (np.arange(m) == worst)
            released |= wrong_upper | wrong_lower
            upper &= ~wrong_upper
            lower &= ~wrong_lower
    return SlipSolution(q, upper | lower, delta, spent, False, error)
