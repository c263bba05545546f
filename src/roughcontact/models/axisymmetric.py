"""Axisymmetric nominal contact of a paraboloid on an elastic half-space through a compliant layer.

The rigid paraboloid ``f(r) = r²/(2R)``, pressed by ``d`` into an elastic
half-space (effective modulus ``E*``), is separated from it by an interface
whose thickness ``ū(p)`` depends only on the local nominal pressure ``p(r)``
(a nonlinear Winkler layer, as in Greenwood & Tripp, J. Appl. Mech. 34, 153
(1967)). On a radial grid of ``N`` rings ``[r_j, r_{j+1})`` with piecewise
constant pressure and collocation at the ring midpoints ``ρ_i``:

    f(ρ_i) − d + Σ_j A_ij p_j = ū(p_i),    Σ_j π(r_{j+1}² − r_j²) p_j = F,

``A_ij`` the displacement at ``ρ_i`` of a unit pressure on ring ``j``: the
difference of two uniformly loaded disks (K. L. Johnson, Contact Mechanics,
CUP 1985, eqs. 3.22a,b, doi:10.1017/CBO9781139171731):

    u(r; a) = (4a/(π E*)) E(r/a)                          for r ≤ a,
    u(r; a) = (4r/(π E*)) [E(a/r) − (1 − a²/r²) K(a/r)]    for r > a,

with ``K``, ``E`` the complete elliptic integrals of modulus ``k``. The
unknowns are ``x_j = ln p_j`` and ``d`` (``ū`` is finite only for ``p > 0``);
Newton's method with a backtracking line search solves the bordered system.
The stiffness ``dF/dd`` is the exact derivative of the discrete system by
implicit differentiation: ``J_x dx = 1 dd``, ``dF = Σ a_j p_j dx_j``.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk, logsumexp

from .paper import hertz_contact_radius

_MAX_LOG_STEP = 5.0


@dataclasses.dataclass(frozen=True)
class NominalContact:
    """Solution of the axisymmetric nominal contact at one force.

    Attributes
    ----------
    radii : numpy.ndarray
        Ring midpoints ``ρ_i`` (length).
    pressure : numpy.ndarray
        Nominal pressure on the rings (force/length²).
    approach : float
        ``d`` (length): rigid-body approach, 0 where the apex's mean plane
        touches the undeformed half-space.
    stiffness : float
        ``dF/dd`` (force/length).
    iterations : int
        Newton iterations used.
    """

    radii: np.ndarray
    pressure: np.ndarray
    approach: float
    stiffness: float
    iterations: int


def disk_displacement(r, a):
    """Normal displacement times ``E*`` at ``r`` of unit pressure on the disk ``ρ < a``.

    Johnson (1985) eqs. 3.22a,b; ``a = 0`` gives 0. Length unit.
    """
    r, a = np.broadcast_arrays(np.asarray(r, dtype=float), np.asarray(a, dtype=float))
    inside = r <= a
    out = np.zeros(r.shape)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio_in = np.where(inside & (a > 0), r / np.where(a > 0, a, 1.0), 0.0)
        out = np.where(inside & (a > 0), 4.0 * a / np.pi * ellipe(ratio_in**2), out)
        ratio_out = np.where(~inside, a / np.where(r > 0, r, 1.0), 0.0)
        m = ratio_out**2
        outer = 4.0 * r / np.pi * (ellipe(m) - (1.0 - m) * ellipk(m))
    return np.where(~inside, outer, out)


def influence_matrix(radii, edges):
    """``A_ij E*``: displacement at ``radii[i]`` of unit pressure on ring ``j``.

    Ring ``j`` is ``[edges[j], edges[j+1])``.
    """
    disks = disk_displacement(radii[:, None], edges[None, :])
    return np.diff(disks, axis=1)


def solve(force, *, radius, e_star, law, r_max, n_rings, tolerance=1e-10, max_iterations=200):
    """Newton solution of the nominal contact at ``force`` (module docstring).

    ``law`` provides ``separation(log_p)`` (``ū``), ``compliance(log_p)``
    (``−dū/d ln p ≥ 0``), ``inverse(u)`` (``ln p`` with ``ū = u``) and
    ``scale`` (a length typical of ``ū``).
    """
    edges = np.linspace(0.0, r_max, n_rings + 1)
    radii = 0.5 * (edges[1:] + edges[:-1])
    ring_area = np.pi * np.diff(edges**2)
    influence = influence_matrix(radii, edges) / e_star
    profile = radii**2 / (2.0 * radius)
    hertz_radius = hertz_contact_radius(force, radius=radius, e_star=e_star)
    hertz_approach = hertz_radius**2 / radius
    length_scale = hertz_approach + law.scale

    def residual(log_p, approach):
        pressure = np.exp(log_p)
        gap = profile - approach + influence @ pressure - law.separation(log_p)
        balance = ring_area @ pressure / force - 1.0
        return np.append(gap / length_scale, balance), pressure

    merit = np.inf
    for guess in (_hertz_guess(radii, profile, influence, hertz_radius, hertz_approach,
                               e_star, radius, law),
                  _layer_guess(force, profile, influence, ring_area, hertz_radius,
                               hertz_approach, radii, e_star, radius, law)):
        if guess is None:
            continue
        with np.errstate(over="ignore", invalid="ignore"):
            guess_values, guess_pressure = residual(*guess)
            guess_merit = guess_values @ guess_values
        if np.isfinite(guess_merit) and guess_merit < merit:
            (log_p, approach), values, pressure, merit = (guess, guess_values, guess_pressure,
                                                          guess_merit)
    if not np.isfinite(merit):
        raise RuntimeError("no finite starting point for the nominal contact")
    for iteration in range(1, max_iterations + 1):
        jacobian = np.empty((n_rings + 1, n_rings + 1))
        jacobian[:n_rings, :n_rings] = influence * pressure[None, :]
        jacobian[np.arange(n_rings), np.arange(n_rings)] += law.compliance(log_p)
        jacobian[:n_rings] /= length_scale
        jacobian[:n_rings, n_rings] = -1.0 / length_scale
        jacobian[n_rings, :n_rings] = ring_area * pressure / force
        jacobian[n_rings, n_rings] = 0.0
        step = -np.linalg.solve(jacobian, values)
        step = _limit(step, log_p)
        for _ in range(40):
            trial, trial_pressure = residual(log_p + step[:n_rings], approach + step[n_rings])
            if trial @ trial < merit or trial @ trial == 0.0:
                break
            step *= 0.5
        else:
            if np.max(np.abs(values)) < 1e3 * tolerance:       # round-off floor reached
                break
            raise RuntimeError(f"nominal contact: line search failed (max residual "
                               f"{np.max(np.abs(values)):.3g})")
        log_p, approach = log_p + step[:n_rings], approach + step[n_rings]
        values, pressure, merit = trial, trial_pressure, trial @ trial
        if np.max(np.abs(values)) < tolerance:
            break
    else:
        raise RuntimeError(f"nominal contact did not converge in {max_iterations} Newton "
                           f"iterations (max residual {np.max(np.abs(values)):.3g})")
    block = influence * pressure[None, :]
    block[np.arange(n_rings), np.arange(n_rings)] += law.compliance(log_p)
    sensitivity = np.linalg.solve(block, np.ones(n_rings))       # d ln p / dd
    return NominalContact(radii=radii, pressure=pressure, approach=float(approach),
                          stiffness=float(ring_area * pressure @ sensitivity),
                          iterations=iteration)


def _limit(step, log_p):
    """Scale the Newton step so that no ring carrying load changes ``ln p`` by more than 5.

    Rings whose pressure is below ``e^{−50}`` of the largest are in the interface's
    logarithmic tail, where the equation is linear in ``ln p`` and Newton is exact;
    they do not limit the step, but none may rise above the largest ``ln p`` + 5.
    """
    n_rings = log_p.size
    loaded = log_p > log_p.max() - 50.0
    largest = np.max(np.abs(step[:n_rings][loaded]))
    step = step * min(1.0, _MAX_LOG_STEP / max(largest, 1e-300))
    ceiling = log_p.max() + _MAX_LOG_STEP - log_p
    step[:n_rings] = np.minimum(step[:n_rings], ceiling)
    return step


def _hertz_pressure(radii, hertz_radius, e_star, radius):
    """Hertz's ``p(r) = (2E* a/(πR)) √(1 − r²/a²)`` (zero outside ``a``)."""
    return (2.0 * e_star * hertz_radius / (np.pi * radius)
            * np.sqrt(np.clip(1.0 - (radii / hertz_radius) ** 2, 0.0, None)))


def _hertz_guess(radii, profile, influence, hertz_radius, hertz_approach, e_star, radius, law):
    """Hertz's pressure inside ``a_H``, the interface law on Hertz's gap outside (no more than
    the edge's pressure), ``d = d_H``; ``None`` if no ring lies inside ``a_H``.

    The better start when the interface is thin next to the Hertz approach.
    """
    hertz_pressure = _hertz_pressure(radii, hertz_radius, e_star, radius)
    gap = profile - hertz_approach + influence @ hertz_pressure
    inside = hertz_pressure > 0
    if not inside.any():
        return None
    log_inside = np.log(hertz_pressure[inside])
    log_p = np.minimum(law.inverse(gap), log_inside.min())
    log_p[inside] = log_inside
    return log_p, hertz_approach


def _layer_guess(force, profile, influence, ring_area, hertz_radius, hertz_approach, radii,
                   e_star, radius, law):
    """``ln p`` and ``d`` with the Hertz displacement and the interface law, force balanced;
    ``None`` if no shift balances the force.

    ``ū(p_j) = f_j − d_H + u_H,j + c`` with ``u_H`` the displacement of the Hertz
    pressure and ``c`` chosen so that the force is ``F``; ``d = d_H − c``.
    """
    hertz_pressure = _hertz_pressure(radii, hertz_radius, e_star, radius)
    gap = profile - hertz_approach + influence @ hertz_pressure
    log_area = np.log(ring_area)

    def excess(shift):
        return logsumexp(log_area + law.inverse(gap + shift)) - np.log(force)

    low, high = -law.scale, law.scale
    for _ in range(60):
        if excess(low) > 0:
            break
        low = 2.0 * low - high
    for _ in range(60):
        if excess(high) < 0:
            break
        high = 2.0 * high - low
    if not excess(low) > 0 > excess(high):
        return None
    shift = brentq(excess, low, high, xtol=1e-14 * (abs(low) + abs(high)))
    return law.inverse(gap + shift), hertz_approach - shift
