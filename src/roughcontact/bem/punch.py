"""Unloading stiffness: the force of a rigid flat punch pressed on a contact footprint.

:func:`punch_stiffness` solves ``K_cc p = 1`` on the footprint ``c`` (the
contact set of a solved state): the exact tangent stiffness of the discrete
problem (Barber, Proc. R. Soc. A 459, 53 (2003)). The system is symmetric
positive definite; it is solved by conjugate gradients (Hestenes & Stiefel 1952,
``scipy.sparse.linalg.cg``) with a dense matrix on small footprints and FFT
products otherwise. With FFT products the conjugate gradients use single-precision
products inside a mixed-precision iterative refinement (Wilkinson 1963;
Higham, *Accuracy and Stability of Numerical Algorithms*, 2nd ed., ch. 12): the
residual is recomputed in double precision after each inner solve, so the
stopping test is met in double precision at about half the cost per product. The conjugate gradients
of the FFT path are preconditioned with the FFT approximate inverse ``E*|q|/2`` of the half-space on the
footprint's window (:mod:`roughcontact.bem.preconditioner`, without deflation of the mean): on the
footprints of the largest loads of the default sphere at 1025² and 2049², 43 and 61 products instead of
77 and 97.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.sparse.linalg import LinearOperator, cg

from ..errors import ConvergenceError
from .active_sets import _window_box, bounding_box, dense_limit
from .operators import operator_for
from .preconditioner import fourier_inverse

__all__ = ["INNER_RTOL", "punch_stiffness", "contact_stiffness"]

#: Relative residual reduction of each single-precision inner solve of the refinement
#: (products accurate to ≈ 1e-6): two steps reach ``tol = 1e-8``. On the 1025² flat load
#: path at H = 0.7 (13 loads, up to 17000 cells) 0.69–0.80× the time of double-precision
#: conjugate gradients (benchmarks/RESULTS.md, section 6).
INNER_RTOL = 1e-5
#: Refinement steps before the solve falls back to double-precision products.
_REFINEMENTS = 8
#: Iterations of one inner solve before the solve falls back to double-precision products
#: (an inner solve to INNER_RTOL takes 15–40 on the 1025² flat path).
_INNER_MAXITER = 500


def _system(operator, footprint, convolve):
    """``K_cc`` as a :class:`~scipy.sparse.linalg.LinearOperator` of FFT products."""
    cells = np.flatnonzero(footprint)
    field = np.zeros(footprint.shape)
    flat_field = field.reshape(-1)

    def matvec(values):
        flat_field[cells] = values.ravel()
        return convolve(field).reshape(-1)[cells]

    return LinearOperator((cells.size, cells.size), matvec=matvec, dtype=float)


def _preconditioner(operator, footprint):
    """The FFT approximate inverse ``E*|q|/2`` of the half-space on the footprint's window
    (:class:`~roughcontact.bem.preconditioner.FourierInverse`, the mean not deflated) as a
    :class:`~scipy.sparse.linalg.LinearOperator`."""
    cells = np.flatnonzero(footprint)
    inverse = fourier_inverse(operator)
    return LinearOperator((cells.size, cells.size), dtype=float,
                          matvec=lambda values: inverse(footprint.shape, cells, values.ravel(), deflate=False))


def _cg(system, rhs, start, rtol, maxiter, preconditioner=None):
    solution, info = cg(system, rhs, x0=start, rtol=rtol, atol=0.0, maxiter=maxiter, M=preconditioner)
    if info != 0:
        raise ConvergenceError(f"the flat-punch stiffness solve did not converge in {info} iterations")
    return solution


def punch_stiffness(operator, footprint: np.ndarray, tol: float) -> float:
    """``Σ p`` of a rigid flat punch of unit depth on ``footprint`` (multiply by ``Δ²``).

    Parameters
    ----------
    operator : FreeSpaceOperator or PeriodicOperator
        Elastic half-space on the grid (or window) of ``footprint``.
    footprint : numpy.ndarray
        Bool array, the cells ``c`` in contact with the punch.
    tol : float
        Bound of the relative residual, keyword of the stopping test
        ``‖K_cc p − 1‖ ≤ tol ‖1‖`` (evaluated in double precision).

    Returns
    -------
    float
        ``Σ_c p`` (force per ``E*``-scaled unit depth divided by the cell area
        ``Δ²``; the caller multiplies by ``Δ²``).

    Notes
    -----
    On at most :func:`~roughcontact.bem.active_sets.dense_limit` cells the system is a
    dense matrix. Otherwise products are FFT convolutions, for the free
    half-space on the bounding box of the footprint (about half the window a
    load's solve needs). When the operator offers single-precision products
    and ``tol <`` :data:`INNER_RTOL`, each refinement step solves
    ``K_cc e = r`` with single-precision products to ``INNER_RTOL`` (or less
    when that suffices), adds ``e`` to ``p`` and recomputes ``r = 1 − K_cc p``
    in double precision. After :data:`_REFINEMENTS` steps without meeting the
    test, when a step does not reduce ``‖r‖``, or when an inner solve does not
    converge in :data:`_INNER_MAXITER` iterations, the solve finishes with
    double-precision products from the ``p`` of the smallest ``‖r‖``.
    """
    if not operator.periodic and footprint.any():  # the convolution on the box is the same
        footprint = footprint[bounding_box(footprint)]
    count = int(np.count_nonzero(footprint))
    unit_depth = np.ones(count)
    punch = unit_depth / operator.self_coefficient
    maxiter = 10 * count + 100
    if count <= dense_limit(operator):
        system = operator.influence_matrix(*np.nonzero(footprint))
        return float(_cg(system, unit_depth, punch, tol, maxiter).sum())
    exact = _system(operator, footprint, operator)
    preconditioner = _preconditioner(operator, footprint)
    if hasattr(operator, "single") and tol < INNER_RTOL:
        approximate = _system(operator, footprint, operator.single)
        target = tol * np.linalg.norm(unit_depth)
        best_norm = math.inf
        for _ in range(_REFINEMENTS):
            residual = unit_depth - exact.matvec(punch)
            norm = np.linalg.norm(residual)
            if norm <= target:
                return float(punch.sum())
            if norm >= best_norm:  # no progress: finish in double precision from the best p
                break
            best_norm, best = norm, punch
            rtol = max(INNER_RTOL, 0.5 * target / norm)
            correction, info = cg(approximate, residual, x0=np.zeros(count), rtol=rtol, atol=0.0,
                                  maxiter=_INNER_MAXITER, M=preconditioner)
            if info != 0:  # the single-precision system misbehaves
                break
            punch = best + correction
        punch = best
    return float(_cg(exact, unit_depth, punch, tol, maxiter, preconditioner).sum())


def contact_stiffness(contact: np.ndarray, *, length: float, e_star: float, periodic: bool, tol: float) -> float:
    """``k = dF/dd`` of the contact set *contact* (bool, ``n × n``) held fixed: the rigid flat punch
    on it (:func:`punch_stiffness`, times the cell area), on the window around the contact that a
    load solve would use (free half-space) or on the whole grid (periodic). 0 without contact;
    ``inf`` for a periodic grid in full contact. *tol*: keyword of :func:`punch_stiffness`."""
    n = contact.shape[0]
    if not contact.any():
        return 0.0
    if periodic and contact.all():
        return math.inf
    operator = operator_for(n, length, e_star, periodic)
    footprint = contact if periodic else contact[_window_box(contact, operator)]
    return punch_stiffness(operator, footprint, tol) * (length / n) ** 2
