"""Method of dimensionality reduction (MDR) for rough spheres and flat rough surfaces.

The three-dimensional contact of a rigid indenter with an elastic half-space is
mapped onto a one-dimensional Winkler foundation of independent springs of
stiffness ``Δk = E* Δx``: at depth ``d`` (counted from first touch) the force is
``F = E* Σ max(d − g(x_i), 0) Δx`` and the stiffness ``k = dF/dd = E* × (total
contact length)``. ``g`` is the MDR profile: a body of revolution ``f(r)`` becomes
``g(x) = |x| ∫_0^|x| f'(r)/√(x² − r²) dr`` (the sphere ``r²/(2R)`` becomes
``x²/R``, ``Q r^m`` becomes ``κ(m) Q |x|^m`` with κ of eq. 8), and a random
roughness of 2D spectrum ``C2D`` becomes a 1D profile of spectrum
``C1D(q) = π q C2D(q)`` (same H), superposed on the body's ``g``.

Sign convention (the package's): heights are the indenter's shape, measured from
the undeformed half-space towards the indenter, so a higher ``g`` is further
away; contact starts where ``g`` (body plus roughness) is lowest. Units are the
caller's: lengths in the length unit, ``E*`` in force/length², ``F`` in force
and ``k`` in force/length.

References
----------
T. Geike, V. L. Popov, Phys. Rev. E 76, 036710 (2007), doi 10.1103/PhysRevE.76.036710.
R. Pohrt, V. L. Popov, A. E. Filippov, Phys. Rev. E 86, 026710 (2012),
doi 10.1103/PhysRevE.86.026710.
V. L. Popov, M. Heß, Method of Dimensionality Reduction in Contact Mechanics and
Friction, Springer (2015), doi 10.1007/978-3-642-53876-6.
R. Pohrt, V. L. Popov, Adv. Tribol. 2013, 974178 (2013) (eq. 8: κ).
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from .._validate import check_finite_positive, check_radius
from ..surfaces.profiles import coordinates, iter_profile_blocks
from .paper import kappa

__all__ = ["Indentation1D", "StiffnessEnsemble", "body_profile", "flat_stiffness", "mdr_force",
           "mdr_indentation", "mdr_stiffness", "sphere_stiffness"]



def body_profile(x, *, radius: float, exponent: float = 2.0) -> np.ndarray:
    """MDR profile of the body of revolution ``f = (R/m)(r/R)^m = Q r^m``: ``g = κ(m) Q |x|^m``.

    ``Q = R^(1−m)/m`` as in ``surfaces.body_of_revolution``; κ of eq. 8 (:func:`roughcontact.models.paper.kappa`).
    The sphere (m = 2, κ = 2) gives ``g = x²/R``; the cone of slope 1 (m = 1) ``π|x|/2``.
    ``x`` and ``R`` in the length unit; returns ``g`` (length unit).
    """
    check_finite_positive("radius", radius)
    check_finite_positive("exponent", exponent)
    x = np.abs(np.asarray(x, dtype=float))
    if exponent == 2.0:
        return x**2 / radius
    return float(kappa(exponent)) * radius ** (1.0 - exponent) / exponent * x**exponent


def _gaps(profile, body):
    """Validated ``g = profile + body`` shifted to ``min g = 0`` (1-D, finite)."""
    g = np.asarray(profile, dtype=float)
    if g.ndim != 1 or g.size < 1 or not np.all(np.isfinite(g)):
        raise ValueError(f"profile must be a non-empty 1-D array of finite heights, "
                         f"got shape {g.shape}")
    if body is not None:
        b = np.asarray(body, dtype=float)
        if b.shape != g.shape or not np.all(np.isfinite(b)):
            raise ValueError(f"body must be finite with the profile's shape {g.shape}, "
                             f"got shape {b.shape}")
        g = g + b
    return g - g.min()


def _check_values(name, values):
    """``values`` as a float array, or ``ValueError`` unless finite, ≥ 0, scalar or 1-D."""
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        array = np.full(2, np.nan)
    if array.ndim > 1 or not np.all(np.isfinite(array)) or np.any(array < 0):
        raise ValueError(f"{name} must be a finite number >= 0 or a 1-D array of them, "
                         f"got {values!r}")
    return array


def _check_common(values, name, dx, e_star):
    """Check ``dx``, ``e_star`` and the depths or forces ``values``; return the latter."""
    check_finite_positive("dx", dx)
    check_finite_positive("e_star", e_star)
    return _check_values(name, values)


def mdr_force(depth, profile, *, dx: float, e_star: float, body=None) -> np.ndarray:
    """Force ``F = E* Σ max(d − g(x_i), 0) Δx`` of the Winkler foundation at depth(s) ``d``.

    Parameters
    ----------
    depth : array_like
        Depth(s) ``d ≥ 0`` from first touch (length unit), scalar or 1-D.
    profile : array_like
        1-D MDR profile (length unit), e.g. :func:`profile_1d`: the indenter's shape.
    dx, e_star : float
        Spring spacing Δx (length unit); effective modulus E* (force/length²).
    body : array_like, optional
        MDR profile of the body (e.g. ``body_profile(coordinates(n, L), radius=R)``),
        added to ``profile``: ``g = profile + body``, shifted so that ``min g = 0``.

    Returns
    -------
    numpy.ndarray
        F (force unit), the shape of ``depth``.
    """
    d = _check_common(depth, "depth", dx, e_star)
    g = _gaps(profile, body)
    return e_star * dx * np.maximum(d[..., None] - g, 0.0).sum(axis=-1)


def mdr_stiffness(depth, profile, *, dx: float, e_star: float, body=None) -> np.ndarray:
    """Stiffness ``k = E* × (contact length) = E* Δx #{i: g(x_i) ≤ d}`` (force/length).

    ``dF/dd`` of :func:`mdr_force` (its right derivative where a spring starts to touch);
    arguments as there.
    """
    d = _check_common(depth, "depth", dx, e_star)
    g = _gaps(profile, body)
    return e_star * dx * np.count_nonzero(g <= d[..., None], axis=-1).astype(float)


def _breakpoints(gaps):
    """Sorted gaps ``u`` (min 0) per row: ``(S_j, F_j/(E*Δx))`` at the breakpoints ``d = u_j``,

    ``S_j = Σ_(i≤j) u_i`` and ``F_j/(E*Δx) = j u_j − S_j``.
    """
    u = np.sort(gaps, axis=-1)
    partial = np.cumsum(u, axis=-1)
    return partial, np.arange(1, u.shape[-1] + 1) * u - partial


def _invert(partial, scaled_force, row_breaks):
    """Contacts ``j`` and depths ``d = (F/(E*Δx) + S_j)/j`` of each row at each scaled force.

    ``F(d)`` is piecewise linear with slope ``E*Δx j`` between the breakpoints; ``j`` is
    the number of breakpoints at or below the force (``searchsorted``, right side).
    """
    count = np.empty((partial.shape[0], scaled_force.size), dtype=np.intp)
    for row in range(partial.shape[0]):
        count[row] = np.searchsorted(row_breaks[row], scaled_force, side="right")
    depth = (scaled_force + np.take_along_axis(partial, count - 1, axis=-1)) / count
    return count, depth


@dataclass(frozen=True, eq=False)
class Indentation1D:
    """One MDR profile pressed to given forces.

    Attributes (1-D arrays): ``force`` F (force unit); ``depth`` from first touch (length
    unit); ``stiffness`` ``k = dF/dd = E* × contact length`` (force/length);
    ``contact_length`` total length of springs in contact (length unit).
    """

    force: np.ndarray
    depth: np.ndarray
    stiffness: np.ndarray
    contact_length: np.ndarray


def mdr_indentation(force, profile, *, dx: float, e_star: float, body=None) -> Indentation1D:
    """Depth and stiffness of one MDR profile at given force(s), ``F(d)`` inverted exactly.

    Arguments as in :func:`mdr_force`, with ``force`` (force unit, ≥ 0, scalar or 1-D)
    in place of ``depth``. Returns an :class:`Indentation1D` of 1-D arrays.
    """
    f = np.atleast_1d(_check_common(force, "force", dx, e_star))
    partial, breaks = _breakpoints(_gaps(profile, body)[None, :])
    count, depth = _invert(partial, f / (e_star * dx), breaks)
    length = dx * count[0].astype(float)
    return Indentation1D(force=f, depth=depth[0], stiffness=e_star * length,
                         contact_length=length)


@dataclass(frozen=True, eq=False)
class StiffnessEnsemble:
    """Ensemble of MDR indentations of seeded rough profiles at given forces.

    Attributes: ``force`` F (force unit, 1-D); ``stiffness`` the ensemble mean of ``k``
    at each force (force/length); ``stiffness_error`` the standard error of that mean,
    ``std(k, ddof=1)/√N`` (force/length); ``realizations`` N; ``depth`` the mean depth
    from first touch (length unit); ``contact_length`` the mean contact length (length
    unit), ``L`` once the whole period touches (then ``k = E* L``: the finite period,
    not the body, sets ``k``).
    """

    force: np.ndarray
    stiffness: np.ndarray
    stiffness_error: np.ndarray
    realizations: int
    depth: np.ndarray
    contact_length: np.ndarray


def sphere_stiffness(force, *, radius: float, hurst: float, h_rms: float, length: float,
                     n: int, e_star: float, rolloff: float | None = None,
                     cutoff: float | None = None, realizations: int = 1000,
                     seed: int | None = 0) -> StiffnessEnsemble:
    """Mean MDR stiffness of a rough sphere at given forces over seeded rough profiles.

    Realisation ``i`` is ``g = x²/R + h_i(x)`` on :func:`coordinates` (``x = 0`` at node
    ``n//2``), with ``h_i`` row ``i`` of :func:`profile_ensemble` (row 0 is
    :func:`profile_1d` with ``seed``). Each ``g`` is sorted once; ``F(d)`` and
    ``k(d)`` are then exact piecewise-linear and piecewise-constant functions, and
    ``F → d`` is inverted per force with ``searchsorted`` (:func:`mdr_indentation`).
    ``radius = inf`` is the nominally flat surface (:func:`flat_stiffness`).

    Parameters
    ----------
    force : array_like
        F ≥ 0 (force unit), scalar or 1-D.
    radius : float
        R (length unit), > 0, or ``inf`` (flat).
    hurst, h_rms, length, n, rolloff, cutoff, seed
        As in :func:`profile_ensemble`: ``h_rms`` is the rms of the 2D surface (length
        unit), ``length`` the period L, ``n`` the points per profile (Δx = L/n).
    e_star : float
        Effective modulus E* (force/length²).
    realizations : int
        Number N ≥ 2 of profiles.

    Returns
    -------
    StiffnessEnsemble
        Mean and standard error of ``k`` (force/length) at each force.
    """
    check_radius(radius)
    check_finite_positive("e_star", e_star)
    f = np.atleast_1d(_check_values("force", force))
    if isinstance(realizations, bool) or not isinstance(realizations, numbers.Integral) or realizations < 2:
        raise ValueError(f"realizations must be an integer >= 2, got {realizations!r}")
    blocks = iter_profile_blocks(n, realizations, hurst=hurst, h_rms=h_rms, length=length, seed=seed,
                                 rolloff=rolloff, cutoff=cutoff)
    dx = length / n
    body = 0.0 if math.isinf(radius) else body_profile(coordinates(n, length), radius=radius)
    scaled = f / (e_star * dx)
    counts, depths = [], []
    for block in blocks:
        g = block + body
        partial, breaks = _breakpoints(g - g.min(axis=1, keepdims=True))
        count, depth = _invert(partial, scaled, breaks)
        counts.append(count)
        depths.append(depth)
    k = e_star * dx * np.concatenate(counts).astype(float)
    return StiffnessEnsemble(force=f, stiffness=k.mean(axis=0),
                             stiffness_error=k.std(axis=0, ddof=1) / math.sqrt(realizations),
                             realizations=int(realizations),
                             depth=np.concatenate(depths).mean(axis=0),
                             contact_length=k.mean(axis=0) / e_star)


def flat_stiffness(force, *, hurst: float, h_rms: float, length: float, n: int,
                   e_star: float, rolloff: float | None = None, cutoff: float | None = None,
                   realizations: int = 1000, seed: int | None = 0) -> StiffnessEnsemble:
    """Mean MDR stiffness of a nominally flat rough surface: :func:`sphere_stiffness`, R = ∞.

    The stiffness of the period ``L`` (compare :func:`roughcontact.models.paper.fractal_stiffness`, eq. 11);
    arguments and units as in :func:`sphere_stiffness`.
    """
    return sphere_stiffness(force, radius=math.inf, hurst=hurst, h_rms=h_rms, length=length,
                            n=n, e_star=e_star, rolloff=rolloff, cutoff=cutoff,
                            realizations=realizations, seed=seed)
