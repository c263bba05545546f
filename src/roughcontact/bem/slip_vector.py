"""The two-component partial-slip kernel: tangential traction vectors under isotropic Coulomb friction.

On the contact set ``C`` of a normal state (pressure ``p``) the tangential traction
``q = (q_x, q_y)`` at a tangential force ``(Q, 0) = Σ q Δ²`` solves the convex programme::

    minimise ½ qᵀK q   subject to   |q| ≤ μp on C,  Σ q_x = Q/Δ²,  Σ q_y = 0,

``K`` the full ``2 × 2`` block of Cerruti's kernel on ``C``
(:class:`~roughcontact.bem.cerruti.PeriodicCerrutiPair`, :class:`~roughcontact.bem.cerruti.FreeCerrutiPair`).
With the rigid tangential displacement ``δ = (δ_x, δ_y)`` (the multipliers of the two force
constraints) and ``u = K q``, its optimality conditions are Coulomb's law on the lattice with the
isotropic cone:

* ``|q| < μp`` ⇒ ``u = δ`` (stick),
* ``|q| = μp`` ⇒ ``u − δ = −λ q``, ``λ ≥ 0`` (slip: the surface slips against its traction, the
  indenter moves ahead of it, ``q`` along ``δ − u``).

``Σ q_y = 0`` (force control in ``y``, ``δ_y`` free) is the load of tamaas' frictional solvers
and of a tangential force along ``x``; for a body symmetric about ``y = 0`` it is ``δ_y = 0``.

:func:`vector_slip_kernel` extends the active set of :mod:`roughcontact.bem.slip` (Kalker 1990,
ch. 2; Polonsky & Keer 1999) to the cone by Newton steps: the unknowns are both components on the
stick cells and, on the slipping cells (``|q| = μp``), the turn of the traction along the cone
(``q = μp e``, ``e`` turned within the tangent ``e⊥``), with the cone's curvature ``−(s·e)/(μp)``
on the diagonal (``s = u − δ``). Each step solves this linear system by conjugate gradients on the
null space of the two force constraints, preconditioned by its diagonal, to a residual
``min(0.1, e)·e`` of the current violation ``e`` (an inexact Newton step), and puts the slipping
tractions back on the cone; stick cells past ``|q| = μp`` join the cone with ``e = q/|q|`` and
slipping cells whose slip points along ``e`` come back (released as in :mod:`roughcontact.bem.slip`),
until the conditions hold to ``tol``. A slipping cell's direction cannot be fixed-point iterated
(``e ← −s/|s|``): its own traction dominates its own slip, and the iteration oscillates (tried).
At ``ν = 0`` nothing turns and the steps are the one-component problem's.
"""

from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["VectorSlipSolution", "vector_slip_kernel", "projected_cg"]

#: Inner iterations between exact recomputations of the stick displacement.
_REFRESH = 50


@dataclasses.dataclass(frozen=True, eq=False)
class VectorSlipSolution:
    """One load of :func:`vector_slip_kernel` (arrays over the ``m`` contact cells).

    Attributes: ``traction`` ``(2, m)`` q (force/length²); ``slip`` bool, ``|q| = μp``;
    ``displacement`` ``(δ_x, δ_y)`` (length); ``iterations`` products spent; ``converged``;
    ``error`` the relative violation ``max(max_stick |u − δ|, max_slip (|s_⊥| + max(s·e, 0))) / |δ|``,
    ``s = u − δ``, ``e = q/|q|``.
    """

    traction: np.ndarray
    slip: np.ndarray
    displacement: tuple[float, float]
    iterations: int
    converged: bool
    error: float


def projected_cg(apply, b, x, constraints, tol, maxiter, scale=None, diagonal=None):
    """Minimise ``½xᵀHx + bᵀx`` keeping ``A x`` (``A`` = *constraints*, ``(c, k)``).

    Conjugate gradients (Hestenes & Stiefel 1952) on the null space of ``A``, preconditioned by the
    positive *diagonal* ``D`` (default 1) with the constraint projection in its metric (Gould,
    Hribar & Nocedal, SIAM J. Sci. Comput. 23, 1376 (2001)): ``z = D⁻¹(g − Aᵀλ)``,
    ``λ = (AD⁻¹Aᵀ)⁻¹AD⁻¹g``. Stops at ``max |g − Aᵀλ| ≤ tol · scale`` (default ``|λ|``),
    ``g = Hx + b``.
    Returns ``(x, λ, iterations)``.
    """
    inverse = np.ones(x.size) if diagonal is None else 1.0 / diagonal
    weighted = constraints * inverse
    normal = np.linalg.inv(weighted @ constraints.T)

    def reduce(g):
        multipliers = normal @ (weighted @ g)
        residual = g - constraints.T @ multipliers
        return residual, inverse * residual, multipliers

    g = apply(x) + b
    residual, preconditioned, multipliers = reduce(g)
    direction = -preconditioned
    norm = float(residual @ preconditioned)
    iterations = 0
    while iterations < maxiter and np.abs(residual).max() > tol * (
            np.linalg.norm(multipliers) if scale is None else scale):
        response = apply(direction)
        curvature = float(direction @ response)
        if curvature <= 0.0 or norm <= 0.0:
            break
        step = norm / curvature
        x += step * direction
        iterations += 1
        g = apply(x) + b if iterations % _REFRESH == 0 else g + step * response
        residual, preconditioned, multipliers = reduce(g)
        new_norm = float(residual @ preconditioned)
        direction = -preconditioned + (new_norm / norm) * direction
        norm = new_norm
    return x, multipliers, iterations


class _TangentSpace:
    """The Newton unknowns at tractions ``q`` on the cone at the *slip* cells: two per stick cell,
    one per slipping cell (the turn ``τ`` along ``e⊥``), with the cone's curvature
    ``−(s·e)/(μp) ≥ 0`` (``s = u − δ``) on the slipping diagonal."""

    def __init__(self, apply, q, u, bound, slip, delta):
        self.apply, self.m = apply, bound.size
        self.cells, self.sliding = np.flatnonzero(~slip), np.flatnonzero(slip)
        k = self.k = self.cells.size
        direction = q[:, self.sliding] / bound[self.sliding]
        self.turn = np.array([-direction[1], direction[0]])
        along = np.einsum("ij,ij->j", u[:, self.sliding] - delta[:, None], direction)
        self.curvature = np.maximum(-along, 0.0) / bound[self.sliding]
        self.constraints = np.zeros((2, 2 * k + self.sliding.size))
        self.constraints[0, :k] = 1.0
        self.constraints[1, k:2 * k] = 1.0
        self.constraints[:, 2 * k:] = self.turn
        self_coefficient = getattr(apply, "self_coefficient", None)
        self.diagonal = None if self_coefficient is None else np.concatenate(
            [np.full(2 * k, self_coefficient), self_coefficient + self.curvature])

    def expand(self, v):
        full = np.zeros((2, self.m))
        full[0, self.cells], full[1, self.cells] = v[:self.k], v[self.k:2 * self.k]
        full[:, self.sliding] = self.turn * v[2 * self.k:]
        return full

    def reduce(self, field):
        return np.concatenate([field[0, self.cells], field[1, self.cells],
                               np.einsum("ij,ij->j", field[:, self.sliding], self.turn)])

    def hessian(self, v):
        product = self.reduce(self.apply(self.expand(v).reshape(-1)).reshape(2, self.m))
        product[2 * self.k:] += self.curvature * v[2 * self.k:]
        return product


def vector_slip_kernel(apply, bound, total, start, *, tol, maxiter) -> VectorSlipSolution:
    """Two-component partial slip on ``m`` contact cells at ``Σ q = (total, 0)``.

    Parameters
    ----------
    apply : callable
        ``v ↦ K v`` on flat stacked vectors ``(v_x, v_y)`` of length ``2m`` (displacement in length
        units from tractions in force/length²); its attribute ``self_coefficient``, if any (a cell's
        displacement under its own unit traction), preconditions the steps.
    bound : numpy.ndarray
        ``μ p`` per cell, > 0 (force/length²).
    total : float
        ``Q/Δ²``, ``0 < total < Σ bound``.
    start : numpy.ndarray
        ``(2, m)`` warm start (projected on the cone; any sums: shifted onto the constraints).
    tol : float
        Relative violation of the conditions accepted, keyword-only.
    maxiter : int
        Products allowed, keyword-only.

    Returns
    -------
    VectorSlipSolution

    Notes
    -----
    Each step is a Newton step on the stick cells (two unknowns each) and the slipping cells (one
    each, the traction's turn along ``e⊥``, the cone's curvature on the diagonal), solved by
    :func:`projected_cg` under the two force constraints from a step that restores the forces;
    the slipping tractions are then put back on the cone (so the turn converges quadratically
    where the sets have settled). Stick cells past the cone join it, slipping cells with
    ``s·e > 0`` are released as in :mod:`roughcontact.bem.slip`.
    """
    m = bound.size
    q = np.array(start, dtype=float).reshape(2, m)
    size = np.hypot(*q)
    slip = size >= bound * (1.0 - 1e-12)
    q[:, slip] *= bound[slip] / size[slip]
    u = apply(q.reshape(-1)).reshape(2, m)
    spent = 1
    error, delta, along = _violation(q, u, bound, slip)
    released = np.zeros(m, dtype=bool)
    while spent < maxiter:
        if slip.all():  # every cell on the cone, yet Σ|q| < Σμp: start the active set afresh
            slip[:] = False
            delta = u.mean(axis=1)
        space = _TangentSpace(apply, q, u, bound, slip, delta)
        mismatch = np.array([total - q[0].sum(), -q[1].sum()])  # the cone's projection moves the sums
        step = space.constraints.T @ np.linalg.solve(space.constraints @ space.constraints.T, mismatch)
        # an inexact Newton step: the linear residual to min(0.1, e) e of the violation e (Dembo,
        # Eisenstat & Steihaug, SIAM J. Numer. Anal. 19, 400 (1982)), which keeps the convergence quadratic
        forcing = max(0.25 * tol, min(0.1, error) * error) if np.isfinite(error) else 0.25 * tol
        step, _, used = projected_cg(space.hessian, space.reduce(u), step, space.constraints, forcing,
                                     maxiter - spent, diagonal=space.diagonal)
        spent += used + 1
        q = q + space.expand(step)
        size = np.hypot(*q)
        q[:, slip] *= bound[slip] / size[slip]
        over = ~slip & (size > bound)
        slip |= over
        q[:, over] *= bound[over] / size[over]
        if not slip.all():  # the forces exactly, on the stick cells (the cone moved them by O(τ²))
            q[:, ~slip] += (np.array([total - q[0].sum(), -q[1].sum()]) / np.count_nonzero(~slip))[:, None]
        u = apply(q.reshape(-1)).reshape(2, m)
        spent += 1
        error, delta, along = _violation(q, u, bound, slip)
        if error <= tol:
            return VectorSlipSolution(q, slip.copy(), (float(delta[0]), float(delta[1])), spent, True, error)
        wrong = slip & (along > tol)
        if wrong.any() and not over.any():
            # release the worst violators; a cell released twice comes back one at a time
            if (wrong & released).any():
                wrong = np.arange(m) == np.argmax(np.where(wrong, along, -np.inf))
            released |= wrong
            slip &= ~wrong
    return VectorSlipSolution(q, slip.copy(), (float(delta[0]), float(delta[1])), spent, False, error)


def _violation(q, u, bound, slip):
    """``(error, δ, s·e/|δ|)`` of tractions *q* with displacements *u*: δ the mean ``u`` of the stick
    cells, the error as :class:`VectorSlipSolution`'s (``inf`` without stick cells)."""
    if slip.all():
        return np.inf, np.zeros(2), np.zeros(bound.size)
    delta = u[:, ~slip].mean(axis=1)
    scale = float(np.hypot(*delta))
    s = (u - delta[:, None]) / scale
    e = q / bound
    along = np.einsum("ij,ij->j", s, e)
    across = np.abs(s[0] * e[1] - s[1] * e[0])
    error = max(float(np.hypot(*s[:, ~slip]).max(initial=0.0)),
                float((across + np.maximum(along, 0.0))[slip].max(initial=0.0)))
    return error, delta, along


def vector_tangent_stiffness(apply, solution: VectorSlipSolution, bound, *, tol, maxiter) -> float:
    """``dQ_x/dδ_x`` at ``Q_y = 0`` of a converged load, divided by ``Δ²``: the Newton system of
    :func:`vector_slip_kernel` at the solution driven by a unit ``δ_x`` (stick cells move with the
    indenter, slipping tractions keep ``μp`` and may turn), ``δ_y`` free. Without slip, the
    two-component full-stick stiffness of the contact."""
    q = solution.traction
    u = apply(q.reshape(-1)).reshape(2, bound.size)
    space = _TangentSpace(apply, q, u, bound, solution.slip, np.asarray(solution.displacement))
    if space.k == 0:
        return 0.0
    unit = space.reduce(np.array([np.ones(bound.size), np.zeros(bound.size)]))
    x, _, used = projected_cg(space.hessian, -unit, np.zeros(unit.size), space.constraints[1:], tol, maxiter,
                              scale=1.0, diagonal=space.diagonal)
    return float(space.expand(x)[0].sum())
