"""Tangential contact of a rigid indenter on an elastic half-space: full stick and partial slip.

A normal state (:class:`~roughcontact.bem.ContactState`, pressure ``p`` on the contact set ``C``)
is loaded by a tangential force ``Q`` along ``x`` (the grid's first axis) at fixed normal pressure.
Traction components (``components``): two, ``(q_x, q_y)`` with Cerruti's full ``2 × 2`` kernel,
the isotropic Coulomb cone and ``Σ q_y = 0`` (the default of :func:`partial_slip`); or one,
``q_x`` with ``u_y`` left free, Cattaneo–Mindlin's approximation (the default of
:func:`tangential_stiffness`, whose two values differ by ≲ 0.1 % at ν = 0.3). Equal at ``ν = 0``.
Stated simplification (:mod:`roughcontact.bem.cerruti`): the normal–tangential coupling neglected
(the pressure does not change under ``Q``, ``u`` does not depend on ``p``): exact for elastically
similar bodies and ``ν = 1/2``, the assumption of Mindlin (1949), Cattaneo (1938), Ciavarella
(1998), Jäger (1998) and the MDR. The option of including the coupling is not offered (not built;
see the guide page on tangential contact).

* :func:`tangential_stiffness` — full stick: a uniform tangential displacement ``δ`` of ``C``,
  ``K_t q = δ`` solved exactly on ``C`` (as :func:`roughcontact.bem.stiffness` solves the
  flat punch with the normal kernel), ``k_t = Σ q Δ²/δ``; Mindlin's ``8Ga/(2 − ν)`` for a circle.
* :func:`partial_slip` — Coulomb friction ``|q| ≤ μ p`` along a tangential load path
  ``Q = f μP`` (``0 ≤ f < 1``), warm-started (:mod:`roughcontact.bem.slip_loads`; kernels
  :mod:`roughcontact.bem.slip_vector`, two components, and :mod:`roughcontact.bem.slip`, one), with
  the stick and slip zones, the tangential displacement ``δ_x(Q)`` and the tangent stiffness
  ``k_t(Q) = dQ/dδ_x`` (one component: the full-stick stiffness of the stick zone, the slip zone's
  tractions staying at ``μp`` under a small increment; two: the slipping tractions may also turn),
  Cattaneo–Mindlin's ``k_t(0)(1 − Q/μP)^(1/3)``.

The Ciavarella–Jäger construction from a normal load path is
:func:`roughcontact.bem.cj_superposition.ciavarella_jager`.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence

import numpy as np

from .._validate import check_finite_positive, is_finite_number
from .active_sets import _window_box
from .cerruti import cerruti_pair_for, tangential_operator_for
from .contact import DEFAULT_MAXITER, ContactState
from .punch import punch_stiffness
from .slip_loads import one_component_loads, two_component_full_stick, two_component_loads

__all__ = ["SlipState", "SlipPath", "check_poisson", "check_friction", "check_components",
           "contact_tangential_stiffness", "tangential_stiffness", "partial_slip"]


def check_poisson(poisson) -> float:
    """``ν`` as a float; ``ValueError`` unless a finite number with ``−1 < ν ≤ 1/2``."""
    if not is_finite_number(poisson) or not -1.0 < poisson <= 0.5:
        raise ValueError(f"poisson must be a Poisson ratio with -1 < poisson <= 0.5, got {poisson!r}")
    return float(poisson)


def check_friction(friction) -> float:
    """``μ`` as a float; ``ValueError`` unless a finite number > 0."""
    check_finite_positive("friction", friction)
    return float(friction)


def _elastic(state: ContactState) -> None:
    if not isinstance(state, ContactState):
        raise TypeError(f"state must be a ContactState, got {type(state).__name__}")
    if state.hardness is not None:
        raise ValueError("tangential contact needs an elastic state (hardness None)")


def _window(contact: np.ndarray, operator, periodic: bool) -> tuple[slice, slice]:
    if periodic:
        return (slice(None), slice(None))
    return _window_box(contact, operator)


def check_components(components) -> int:
    """``1`` or ``2`` (traction components); ``ValueError`` otherwise."""
    if isinstance(components, bool) or components not in (1, 2):
        raise ValueError(f"components must be 1 (q_x) or 2 (q_x, q_y), got {components!r}")
    return int(components)


def contact_tangential_stiffness(contact: np.ndarray, *, length: float, e_star: float, poisson: float,
                                 periodic: bool, tol: float, components: int = 1) -> float:
    """Full-stick ``k_t = Q/δ_x`` of the contact set *contact* (bool, ``n × n``; force/length).

    ``components = 1``: the rigid flat punch of :func:`roughcontact.bem.punch.punch_stiffness` with
    the tangential kernel (:mod:`roughcontact.bem.cerruti`): ``K_xx q = 1`` on the set,
    ``k_t = Δ² Σ q``. ``components = 2``: ``(q_x, q_y)`` with the full ``2 × 2`` kernel, ``u = (1, δ_y)``
    on the set and ``Σ q_y = 0`` (:func:`roughcontact.bem.slip_loads.two_component_full_stick`).
    0 without contact; ``inf`` for a periodic grid in full contact. *tol*: the relative residual,
    keyword.
    """
    poisson = check_poisson(poisson)
    components = check_components(components)
    n = contact.shape[0]
    if not contact.any():
        return 0.0
    if periodic and contact.all():
        return math.inf
    operator = tangential_operator_for(n, float(length), float(e_star), poisson, bool(periodic))
    footprint = contact[_window(contact, operator, periodic)]
    if components == 1:
        return punch_stiffness(operator, footprint, tol) * (length / n) ** 2
    pair = cerruti_pair_for(n, float(length), float(e_star), poisson, bool(periodic))
    cells = np.flatnonzero(footprint)
    return two_component_full_stick(pair, footprint, cells, tol=tol, maxiter=DEFAULT_MAXITER) * (length / n) ** 2


def tangential_stiffness(state: ContactState, *, poisson: float, tol: float | None = None,
                         components: int = 1) -> float:
    """Full-stick tangential stiffness ``k_t`` of a solved normal state (force/length).

    Parameters
    ----------
    state : ContactState
        Elastic normal state; its contact set sticks.
    poisson : float
        Poisson ratio ``ν`` of the half-space (``E*`` is ``state.e_star``), keyword-only.
    tol : float, optional
        Relative residual of the solve (default ``state.tol``), keyword-only.
    components : {1, 2}
        Traction components, keyword-only: ``q_x`` alone (``u_y`` free; the default) or
        ``(q_x, q_y)`` at ``Q_y = 0``. Equal at ``ν = 0`` and for Mindlin's circle; on rough
        contacts at ``ν = 0.3`` they differ by ≲ 0.1 % (measured, guide page on tangential contact).

    Returns
    -------
    float
        ``k_t`` (force/length): Mindlin's ``8Ga/(2 − ν) = 2E*a · 2(1 − ν)/(2 − ν)`` for a circle.
    """
    _elastic(state)
    tol = state.tol if tol is None else tol
    check_finite_positive("tol", tol)
    return contact_tangential_stiffness(state.contact, length=state.length, e_star=state.e_star,
                                        poisson=poisson, periodic=state.periodic, tol=tol,
                                        components=components)


@dataclasses.dataclass(frozen=True, eq=False)
class SlipState:
    """Partial slip at one tangential force.

    Attributes
    ----------
    force : float
        Tangential force ``Q = Σ q Δ²`` (force unit).
    fraction : float
        ``Q/(μP)``.
    displacement : float
        Rigid tangential displacement ``δ_x`` of the indenter (length unit; for a periodic
        half-space relative to the mean surface displacement).
    traction : numpy.ndarray
        ``(n, n)`` tangential traction ``q_x``, ``|q| ≤ μp`` (force/length²).
    stick, slip : numpy.ndarray
        ``(n, n)`` bool: contact cells with ``|q| < μp`` and with ``|q| = μp``.
    stiffness : float
        Tangent ``k_t(Q) = dQ/dδ_x`` (force/length): one component, the full-stick stiffness of
        ``stick``; two, the tangent at ``Q_y = 0`` with the slipping tractions free to turn on the
        cone; ``nan`` when not asked for.
    iterations : int
        Influence products spent on this load.
    converged : bool
    error : float
        Relative violation of the stick–slip conditions (:mod:`roughcontact.bem.slip`,
        :mod:`roughcontact.bem.slip_vector`).
    cell_area : float
        ``Δ²`` (length²).
    traction_y : numpy.ndarray
        ``(n, n)`` traction ``q_y`` across the load (0 with one component; ``|(q_x, q_y)| ≤ μp``).
    displacement_y : float
        ``δ_y`` of the indenter at ``Q_y = 0`` (0 with one component, and by symmetry for a body
        symmetric about ``y = 0``).
    """

    force: float
    fraction: float
    displacement: float
    traction: np.ndarray
    stick: np.ndarray
    slip: np.ndarray
    stiffness: float
    iterations: int
    converged: bool
    error: float
    cell_area: float
    traction_y: np.ndarray | None = None
    displacement_y: float = 0.0

    @property
    def stick_area(self) -> float:
        """Area of the stick zone (length²)."""
        return float(np.count_nonzero(self.stick)) * self.cell_area

    @property
    def slip_area(self) -> float:
        """Area of the slip zone (length²)."""
        return float(np.count_nonzero(self.slip)) * self.cell_area


@dataclasses.dataclass(frozen=True, eq=False)
class SlipPath:
    """A tangential load path at fixed normal pressure (:func:`partial_slip`).

    Attributes
    ----------
    normal : ContactState
        The normal state (normal force ``P = normal.force``).
    friction, poisson : float
        ``μ`` and ``ν``.
    full_stick_stiffness : float
        ``k_t(0)`` (force/length), with the path's components.
    states : tuple of SlipState
        One per requested fraction, in the order given.
    components : int
        Traction components solved for (1: ``q_x``; 2: ``q_x, q_y``).
    """

    normal: ContactState
    friction: float
    poisson: float
    full_stick_stiffness: float
    states: tuple[SlipState, ...]
    components: int = 2

    @property
    def forces(self) -> np.ndarray:
        """``Q`` per load (force unit)."""
        return np.array([s.force for s in self.states])

    @property
    def displacements(self) -> np.ndarray:
        """``δ_x`` per load (length unit)."""
        return np.array([s.displacement for s in self.states])

    @property
    def stiffnesses(self) -> np.ndarray:
        """``k_t(Q)`` per load (force/length)."""
        return np.array([s.stiffness for s in self.states])

    @property
    def stick_areas(self) -> np.ndarray:
        """Stick area per load (length²)."""
        return np.array([s.stick_area for s in self.states])


def partial_slip(state: ContactState, fractions: Sequence[float], *, friction: float, poisson: float,
                 tol: float | None = None, maxiter: int = DEFAULT_MAXITER,
                 stiffness: bool = True, components: int = 2) -> SlipPath:
    """Cattaneo–Mindlin partial slip of a normal state along ``Q = f μP``.

    Parameters
    ----------
    state : ContactState
        Elastic normal state (pressure ``p``, force ``P``), held fixed.
    fractions : sequence of float
        ``f = Q/(μP)``, each ``0 ≤ f < 1``, nondecreasing (a monotone loading path; each load
        warm-starts from the previous one).
    friction : float
        Coulomb coefficient ``μ > 0``, keyword-only.
    poisson : float
        ``ν`` of the half-space, ``−1 < ν ≤ 1/2``, keyword-only.
    tol : float, optional
        Relative violation of the stick–slip conditions accepted (default ``state.tol``), and the
        residual of the stiffness solves; keyword-only.
    maxiter : int
        Influence products allowed per load, keyword-only.
    stiffness : bool
        Compute ``k_t(Q)`` of every load (one linear solve each), keyword-only.
    components : {1, 2}
        Traction components, keyword-only. 2 (default): ``(q_x, q_y)`` with the full ``2 × 2``
        Cerruti kernel and the isotropic cone ``|q| ≤ μp``, ``Σ q_y = 0``
        (:mod:`roughcontact.bem.slip_vector`): the frictional problem itself (tamaas' converged
        tractions to < 1e-3 of ``μ max p``). 1: ``q_x`` alone, ``u_y`` free
        (:mod:`roughcontact.bem.slip`): Cattaneo–Mindlin's approximation, 0.5–11 % of ``μ max p``
        off in ``q_x`` at ``ν = 1/2`` (64² sphere; 513² rough spheres), at 1/5–1/8 of the time.
        Equal at ``ν = 0``. Measured: the guide page on tangential contact.

    Returns
    -------
    SlipPath

    Raises
    ------
    ConvergenceError
        A load whose conditions are not met within ``maxiter`` products.
    """
    _elastic(state)
    friction = check_friction(friction)
    poisson = check_poisson(poisson)
    components = check_components(components)
    tol = state.tol if tol is None else tol
    check_finite_positive("tol", tol)
    fractions = np.asarray(fractions, dtype=float).reshape(-1)
    if not np.all(np.isfinite(fractions)) or np.any(fractions < 0) or np.any(fractions >= 1):
        raise ValueError(f"fractions must be finite with 0 <= f < 1, got {fractions.tolist()!r}")
    if np.any(np.diff(fractions) < 0):
        raise ValueError("fractions must be nondecreasing (a monotone tangential load path)")
    n = state.heights.shape[0]
    operator = tangential_operator_for(n, state.length, state.e_star, poisson, state.periodic)
    window = _window(state.contact, operator, state.periodic)
    footprint = state.contact[window]
    cells = np.flatnonzero(footprint)
    bound = friction * state.pressure[window].reshape(-1)[cells]
    k0 = contact_tangential_stiffness(state.contact, length=state.length, e_star=state.e_star,
                                      poisson=poisson, periodic=state.periodic, tol=tol, components=components)
    options = dict(tol=tol, maxiter=maxiter, stiffness=stiffness, k0=k0 / state.cell_area)
    if components == 1:
        loads = one_component_loads(operator, footprint, cells, bound, fractions, **options)
    else:
        pair = cerruti_pair_for(n, state.length, state.e_star, poisson, state.periodic)
        loads = two_component_loads(pair, footprint, cells, bound, fractions, **options)
    states = tuple(_state(state, window, cells, fraction, load) for fraction, load in zip(fractions, loads))
    return SlipPath(normal=state, friction=friction, poisson=poisson, full_stick_stiffness=k0, states=states,
                    components=components)


def _state(normal, window, cells, fraction, load) -> SlipState:
    q_cells, slip, (delta_x, delta_y), k, spent, error = load
    n = normal.heights.shape[0]
    fields = np.zeros((2, n, n))
    stick = np.zeros((n, n), dtype=bool)
    slipping = np.zeros((n, n), dtype=bool)
    rows, cols = np.unravel_index(cells, fields[0][window].shape)
    for target, values in ((fields[0], q_cells[0]), (fields[1], q_cells[1]), (stick, ~slip), (slipping, slip)):
        target[window][rows, cols] = values  # target[window] is a view: the window is a basic slice
    force = float(q_cells[0].sum()) * normal.cell_area
    return SlipState(force=force, fraction=float(fraction), displacement=float(delta_x), traction=fields[0],
                     stick=stick, slip=slipping, stiffness=k * normal.cell_area, iterations=spent, converged=True,
                     error=error, cell_area=normal.cell_area, traction_y=fields[1], displacement_y=float(delta_y))
