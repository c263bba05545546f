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

:func:`roughcontact.bem.bounded.bounded_cg` solves them: conjugate gradients on the cells
between the bounds and projected-gradient steps with the Armijo condition, a method that
converges by construction (its module states the argument). After a solve the plastic
displacement of a cell at the cap is its overlap ``−g`` (:func:`plastic_flow`); it is added to
the indenter's heights for the next load (the surface stays flattened).
"""

from __future__ import annotations

import numpy as np

__all__ = ["plastic_flow"]


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
