"""The Ciavarella–Jäger construction: partial slip from a normal load path.

M. Ciavarella, "The generalized Cattaneo partial slip plane contact problem. I — Theory",
Int. J. Solids Struct. 35, 2349 (1998), doi:10.1016/S0020-7683(97)00154-6, and J. Jäger,
"A new principle in contact mechanics", J. Tribol. 120, 677 (1998), doi:10.1115/1.2833765:
under a tangential force ``Q`` at fixed normal force ``P`` the tractions are ``μ`` times the
difference of two normal solutions,

    q = μ [p(d) − p(d*)],   Q = μ [P(d) − P(d*)],

the stick zone being the contact set at the smaller approach ``d*``. On the stick zone the
tangential displacement is then uniform, ``u_x = μ (d − d*) · K_t/K_n``, exactly where the
tangential kernel is a multiple of the normal one: ``ν = 0`` on the lattice of
:mod:`roughcontact.bem.cerruti` (where ``K_t = K_n``), and the MDR. Otherwise it is an
approximation; for the displacement this module takes Mindlin's compliance ratio,

    δ_x = μ (d − d*) (2 − ν)/(2(1 − ν)),   k_t(Q) = k_n(d*) · 2(1 − ν)/(2 − ν),

which is exact for the Hertzian sphere (Cattaneo–Mindlin, Johnson 1985, §7.2) and for any
contact at ``ν = 0``.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

import numpy as np

from .contact import ContactState
from .punch import contact_stiffness
from .tangential import check_friction, check_poisson

__all__ = ["CiavarellaJagerPath", "ciavarella_jager"]


@dataclasses.dataclass(frozen=True, eq=False)
class CiavarellaJagerPath:
    """The Ciavarella–Jäger tangential path of a normal state.

    Attributes
    ----------
    normal : ContactState
        The loaded state (``d``, ``P``).
    friction, poisson : float
        ``μ`` and ``ν``.
    states : tuple of ContactState
        The states at ``d* ≤ d`` that give the stick zones, in order of increasing ``Q``
        (the first is ``normal`` itself, ``Q = 0``).
    forces : numpy.ndarray
        ``Q = μ (P − P*)`` (force unit).
    displacements : numpy.ndarray
        ``δ_x = μ (d − d*) (2 − ν)/(2(1 − ν))`` (length unit).
    stick_areas : numpy.ndarray
        Contact area at ``d*`` (length²).
    stiffnesses : numpy.ndarray
        ``k_t(Q) = k_n(d*) · 2(1 − ν)/(2 − ν)`` (force/length); ``nan`` when not asked for.
    """

    normal: ContactState
    friction: float
    poisson: float
    states: tuple[ContactState, ...]
    forces: np.ndarray
    displacements: np.ndarray
    stick_areas: np.ndarray
    stiffnesses: np.ndarray

    def traction(self, index: int) -> np.ndarray:
        """``q = μ [p(d) − p(d*)]`` of load *index* (``(n, n)``, force/length²)."""
        return self.friction * (self.normal.pressure - self.states[index].pressure)


def ciavarella_jager(states: Sequence[ContactState], *, friction: float, poisson: float,
                     stiffness: bool = True, tol: float | None = None) -> CiavarellaJagerPath:
    """Tangential path of the last of *states* by Ciavarella–Jäger superposition.

    Parameters
    ----------
    states : sequence of ContactState
        Elastic states of one indenter (same heights, grid, ``E*``, half-space) at increasing
        force, e.g. from :func:`roughcontact.bem.load_path`; the last is loaded tangentially,
        the others give the stick zones.
    friction : float
        ``μ > 0``, keyword-only.
    poisson : float
        ``ν``, ``−1 < ν ≤ 1/2``, keyword-only.
    stiffness : bool
        Compute ``k_t(Q)`` from the normal stiffness of every state, keyword-only.
    tol : float, optional
        Residual of those stiffness solves (default: each state's ``tol``), keyword-only.

    Returns
    -------
    CiavarellaJagerPath
    """
    friction = check_friction(friction)
    poisson = check_poisson(poisson)
    states = list(states)
    if not states:
        raise ValueError("states must hold at least one ContactState")
    normal = states[-1]
    for other in states:
        if not isinstance(other, ContactState) or other.hardness is not None:
            raise ValueError("states must be elastic ContactStates (hardness None)")
        if (other.heights.shape != normal.heights.shape or other.length != normal.length
                or other.e_star != normal.e_star or other.periodic != normal.periodic):
            raise ValueError("states must share the grid, length, e_star and half-space of the last")
    if any(b.force < a.force for a, b in zip(states, states[1:])):
        raise ValueError("states must be in order of increasing force")
    ordered = tuple(reversed(states))
    compliance = (2.0 - poisson) / (2.0 * (1.0 - poisson))
    forces = np.array([friction * (normal.force - s.force) for s in ordered])
    displacements = np.array([friction * (normal.depth - s.depth) * compliance for s in ordered])
    areas = np.array([s.contact_area for s in ordered])
    if stiffness:
        k = np.array([contact_stiffness(s.contact, length=s.length, e_star=s.e_star, periodic=s.periodic,
                                        tol=s.tol if tol is None else tol) for s in ordered]) / compliance
    else:
        k = np.full(len(ordered), np.nan)
    return CiavarellaJagerPath(normal=normal, friction=friction, poisson=poisson, states=ordered,
                               forces=forces, displacements=displacements, stick_areas=areas,
                               stiffnesses=k)
