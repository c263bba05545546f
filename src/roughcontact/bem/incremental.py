"""The incremental normal stiffness ``k = dF/dd`` of a solved state (:func:`stiffness`): the exact
unloading stiffness of the discrete problem as the force of a rigid flat punch whose footprint is the
contact set (the incremental analogy of Barber, Proc. R. Soc. A 459, 53 (2003);
:mod:`roughcontact.bem.punch`), or difference quotients of extra solves
(:mod:`roughcontact.bem.contact`). Conventions are those of :mod:`roughcontact.bem.contact`."""
from __future__ import annotations

import math

import numpy as np

from .._validate import check_finite_positive
from .contact import ContactState, _check_solver_args, _converged, _solve
from .operators import operator_for
from .punch import punch_stiffness

__all__ = ["stiffness"]


def stiffness(state: ContactState, *, method: str = "punch", tol: float | None = None,
              maxiter: int | None = None, rel_step: float = 1e-3) -> float:
    """Incremental normal stiffness ``k = dF/dd`` at ``state`` (force/length).

    Parameters
    ----------
    state : ContactState
    method : {"punch", "difference", "loading"}
        ``"punch"`` (default): the **unloading** stiffness, exact for the
        discrete problem: the force of a rigid flat punch whose footprint is
        the contact set, pressed by unit depth, i.e. ``k = Δ² Σ p`` with
        ``K_cc p = 1`` on the contact set ``c = {p > 0}`` (symmetric positive
        definite; conjugate gradients, stopped when
        ``‖K_cc p − 1‖ ≤ tol ‖1‖``). On unloading every contact cell, plastic
        ones included, unloads elastically (the flattened surface fits the
        indenter), so this is what an unloading experiment measures. For an
        elastic state it is also the loading tangent: between changes of the
        contact set ``F(d)`` is linear with exactly this slope.
        ``"difference"``: the central difference quotient
        ``(F₊ − F₋)/(d₊ − d₋)`` of two extra solves at ``F(1 ± rel_step)``,
        as in Pohrt & Popov (2013); elastic states only (with a hardness it
        would average loading and unloading).
        ``"loading"``: the **loading** tangent along the load history, the
        forward quotient ``(F₊ − F)/(d₊ − d)`` of one extra solve at
        ``F₊ = F(1 + rel_step)`` that starts from this state's plastic
        displacement (so cells keep flowing). Its bias is ``O(rel_step)``:
        for ``F ∝ d^(3/2)`` (Hertz) it is the tangent at ``F(1 + rel_step/2)``,
        ``rel_step/6`` above the tangent at ``F``. Near the fully plastic limit
        the discrete ``F(d)`` is a staircase (rings of cells reaching the cap
        at nearly one depth), so a small ``rel_step`` measures the lattice:
        take a step that adds many cells to the contact.
    tol : float, optional
        Tolerance of the punch solve or of the extra solves (default:
        ``state.tol``), keyword-only.
    maxiter : int, optional
        Iteration limit of the extra contact solves of ``"difference"`` and
        ``"loading"`` (default: ``state.maxiter``, the limit the state was solved
        with), keyword-only. The punch solve has its own limits
        (:mod:`roughcontact.bem.punch`).
    rel_step : float
        Relative force step of the difference quotients, keyword-only.

    Returns
    -------
    float
        Stiffness; ``inf`` for a periodic contact covering the whole grid
        (``"punch"``).

    Raises
    ------
    ConvergenceError
        If an extra solve of ``"difference"`` or ``"loading"`` does not meet its
        stopping test within ``maxiter``, or the punch solve does not converge.
    """
    if method in ("difference", "loading"):
        check_finite_positive("rel_step", rel_step)
        if rel_step >= 1:
            raise ValueError(f"rel_step must be < 1, got {rel_step!r}")
        tol = state.tol if tol is None else tol
        maxiter = state.maxiter if maxiter is None else maxiter
        _check_solver_args(state.length, state.e_star, tol, maxiter)
        if method == "loading":
            prior = None if state.hardness is None else state.plastic_displacement
            upper = _converged(_solve(state.heights, state.force * (1 + rel_step), state.length,
                                      state.e_star, state.periodic, tol, maxiter, state.pressure,
                                      state.depth * (1 + rel_step), state.edge_contact, state.hardness,
                                      prior), method)
            return (upper.force - state.force) / (upper.depth - state.depth)
        if state.hardness is not None:
            raise ValueError("method='difference' needs an elastic state; with a hardness use "
                             "'punch' (unloading) or 'loading'")
        # d(F) is increasing and concave: d(F(1 ± ε)) ≤ d(F)·(1 + ε) bounds both windows.
        upper, lower = (
            _converged(_solve(state.heights, state.force * (1 + sign * rel_step), state.length,
                              state.e_star, state.periodic, tol, maxiter, state.pressure,
                              state.depth * (1 + rel_step), state.edge_contact), method)
            for sign in (1, -1))
        return (upper.force - lower.force) / (upper.depth - lower.depth)
    if method != "punch":
        raise ValueError(f"method must be 'punch', 'difference' or 'loading', got {method!r}")
    tol = state.tol if tol is None else tol
    check_finite_positive("tol", tol)
    n = state.heights.shape[0]
    if state.periodic and np.all(state.contact):
        return math.inf
    operator = operator_for(n, state.length, state.e_star, state.periodic)
    return punch_stiffness(operator, state.contact[state.window], tol) * state.cell_area
