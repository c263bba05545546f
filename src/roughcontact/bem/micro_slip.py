"""The largest micro-slip of a tangential contact: the indenter's tangential displacement at the
onset of gross sliding, ``Q → μP`` (Grzemba, Pohrt, Teidelt & Popov, Wear 309, 40–47 (2014),
doi:10.1016/j.wear.2013.09.020).

At gross sliding every contact cell slips, ``q_x = μp``; under the one-component simplification of
:mod:`roughcontact.bem.tangential` (normal–tangential coupling neglected) the indenter's rigid
displacement ``δ_x`` is then the largest surface displacement of the contact, the last cell to
stick: ``δ_max = max_C u_x[μp]``, ``u_x`` from the Cerruti kernel (:mod:`roughcontact.bem.cerruti`).
For ``ν = 0`` (tangential and normal kernels proportional) ``u_x[μp] = μ u_z[p] = μ (d − h)`` on the
contact set, so ``δ_max = μ d`` exactly, ``d`` the approach from first touch; Grzemba et al.'s
rough-surface law ``δ_max = μ d E*/G*``, ``G*/E* = 2(1 − ν)/(2 − ν)`` (Mindlin's ratio), holds for
every body of revolution by the Ciavarella–Jäger construction.
"""
from __future__ import annotations

import numpy as np

from .cerruti import tangential_operator_for
from .contact import ContactState
from .tangential import check_friction, check_poisson

__all__ = ["gross_slip_displacement"]


def gross_slip_displacement(state: ContactState, *, friction: float, poisson: float) -> float:
    """``δ_max``: the tangential displacement of the indenter at the onset of gross sliding
    (length unit; module docstring).

    Parameters
    ----------
    state : ContactState
        Elastic normal state (pressure ``p`` on the contact set), held fixed.
    friction : float
        Coulomb coefficient ``μ > 0``, keyword-only.
    poisson : float
        ``ν`` of the half-space, ``−1 < ν ≤ 1/2``, keyword-only.

    Returns
    -------
    float
        ``max over the contact set of u_x[μp]``; 0 without contact. For a periodic half-space
        relative to the mean surface displacement (the periodic operator's zero mode is 0).
    """
    friction = check_friction(friction)
    poisson = check_poisson(poisson)
    if state.hardness is not None:
        raise ValueError("the largest micro-slip needs an elastic state (hardness None)")
    if not state.contact.any():
        return 0.0
    n = state.heights.shape[0]
    operator = tangential_operator_for(n, state.length, state.e_star, poisson, state.periodic)
    if state.periodic:
        field, contact = friction * state.pressure, state.contact
    else:   # the free operator acts on a window: the contact's bounding box
        rows, cols = np.nonzero(state.contact)
        box = (slice(rows.min(), rows.max() + 1), slice(cols.min(), cols.max() + 1))
        field, contact = friction * np.where(state.contact, state.pressure, 0.0)[box], state.contact[box]
    return float(operator(field)[contact].max())
