"""Greenwood & Tripp (1967): the elastic contact of a rough sphere, solved in GT's units.

J. A. Greenwood, J. H. Tripp, "The elastic contact of rough spheres",
J. Appl. Mech. 34, 153 (1967) (GT). A smooth elastic sphere of radius ``B``
(GT's notation; ``B = R``, the radius of the paraboloid ``r²/(2R)`` of
:func:`roughcontact.surfaces.paraboloid`) touches a Greenwood–Williamson rough
surface: independent spherical summits of radius ``β``, areal density ``η`` and
Gaussian heights of standard deviation ``σ`` (Greenwood & Williamson, Proc. R.
Soc. A 295, 300 (1966)). The summits carry the local nominal pressure
``p = (4/3) η E* β^(1/2) σ^(3/2) F_{3/2}(s/σ)`` at a local separation ``s``
between the sphere and the mean summit plane, ``F_n(h) = ∫_h^∞ (x − h)^n φ(x) dx``
with ``φ`` the standard normal density, and the nominal pressure deforms the
half-space (modulus ``E*``) elastically.

Dimensionless variables (GT): ``ρ = r/√(2Bσ)``, separations and
displacements in units of ``σ``, pressure in units of ``E*√(σ/(8B))``, so
that ``p = μ F_{3/2}(d* + ρ² + w(ρ) − w(0))`` with
``μ = (8/3) η σ √(2Bβ)`` and ``d* = d/σ`` the separation at the centre
(sphere apex to the deformed mean summit plane). The displacement of the
half-space under an axisymmetric pressure is (Johnson, Contact Mechanics,
1985, ch. 3, the ring-load Green's function after Landen's transformation)

    w(ρ) = (2/π) [ ∫_0^ρ p(t) (t/ρ) K(t/ρ) dt + ∫_ρ^∞ p(t) K(ρ/t) dt ],

``K`` the complete elliptic integral of the first kind (modulus argument),
``w(0) = ∫ p dt``; forces are in units of ``E* σ^(3/2) √(B/2)``
(``F = 2π ∫ ρ p dρ`` in those units) and stiffnesses in units of
``E* √(σB/2)``.

Limits (tested in ``tests/test_greenwood_tripp.py``):

* Light load, ``d* → ∞``: the elastic displacement is negligible against the
  separation, ``p → μ F_{3/2}(d* + ρ²)`` (a rigid sphere on the summits) and,
  since ``∫_h^∞ F_n = F_{n+1}(h)/(n + 1)``, the force tends to
  ``2π μ ∫_0^∞ ρ F_{3/2}(d* + ρ²) dρ = (2π/5) μ F_{5/2}(d*)``.
* Hertz, large load (or ``σ → 0`` at fixed physical load): the summit layer
  is compressed by ``|d*| σ``, and ``μ F_{3/2}(d*) ≈ |d*|^(3/2) μ`` only has to
  match the central pressure ``∝ F^(1/3)``, so ``|d*|`` grows like ``F^(2/9)``
  while the elastic approach ``2ρ_a²`` grows like ``F^(2/3)``: the pressure
  tends to Hertz's ``p = (8/π)√(ρ_a² − ρ²)`` in these units and force and
  stiffness to ``F = (16/3) ρ_a³``, ``k = 4 ρ_a``, i.e. ``F = k³/12``
  (``k = 2E*a`` and ``F = 4E*a³/(3R)`` with ``a = ρ_a√(2Rσ)``).
* Far from the apex the load vanishes: ``p(ρ) ≤ μ F_{3/2}(d* + ρ² − w(0))``
  decays like ``exp(−ρ⁴/2)``, so the truncation at ``rho_max`` is checked
  (``edge_pressure_tol``).
* The force is a continuous, decreasing function of ``d*`` and an increasing
  one of ``μ``; its derivative along the load curve is computed exactly
  (``stiffness_star``).

Summit statistics (``η``, ``β``, ``σ``) from a surface's spectral moments:
:mod:`roughcontact.models.asperities` on the moments of :mod:`roughcontact.surfaces.moments`;
the load curve in physical units: :mod:`roughcontact.models.greenwood_tripp.sphere`.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np
from scipy.integrate import quad
from scipy.special import ellipk, gamma, pbdv

from ..._validate import check_finite_positive, check_grid_size
from ...errors import ConvergenceError

__all__ = [
    "GreenwoodTrippSolution",
    "greenwood_tripp",
    "gt_function",
    "influence_matrix",
]

#: Gauss–Legendre nodes per half of a hat function for the smooth influence integrals.
_GAUSS_NODES = 20
#: Below this separation (in σ) ``F_n`` is summed from its asymptotic series instead of
#: the parabolic cylinder function (which overflows near −53 and loses accuracy before).
_DEEP = -20.0


def gt_function(h, n: float):
    """``F_n(h) = ∫_h^∞ (x − h)^n φ(x) dx``, ``φ`` the standard normal density.

    Closed form ``F_n(h) = Γ(n + 1)/√(2π) · exp(−h²/4) · D_{−n−1}(h)`` with
    ``D_ν`` the parabolic cylinder function (from
    ``F_n = e^(−h²/2)/√(2π) ∫_0^∞ t^n e^(−t²/2 − ht) dt`` and the integral
    representation of ``U(a, h) = D_{−a−1/2}(h)``, DLMF §12.5;
    ``scipy.special.pbdv``), relative accuracy ~1e-13 for
    ``−20 ≤ h ≤ 10`` (beyond ``h = 10`` the value is below ``1e-22`` and only
    its absolute accuracy matters); below ``h = −20`` the expansion
    ``F_n = |h|^n Σ_m C(n, 2m) (2m − 1)!! |h|^(−2m)`` (moments of the normal
    distribution), seven terms, relative accuracy ~1e-15.
    """
    h = np.asarray(h, dtype=float)
    deep = h < _DEEP
    shallow = np.where(deep, 0.0, h)
    value = (gamma(n + 1.0) / math.sqrt(2.0 * math.pi) * np.exp(-shallow * shallow / 4.0)
             * pbdv(-n - 1.0, shallow)[0])
    if np.any(deep):
        # F_n(h) = E[(a + X)^n] with a = −h (the part X < h weighs ~exp(−h²/2)):
        # a^n Σ_m C(n, 2m) (2m − 1)!! a^(−2m), consecutive terms in the ratio
        # (n − 2m + 2)(n − 2m + 1)/(2m a²).
        a = np.where(deep, -h, 1.0)
        term = np.ones_like(a)
        series = np.ones_like(a)
        for m in range(1, 8):
            term = term * (n - 2 * m + 2) * (n - 2 * m + 1) / (2 * m * a * a)
            series = series + term
        value = np.where(deep, a**n * series, value)
    return value


def _kernel(xi):
    """``g(ξ)`` of ``w(ρ) = (2/π) ∫ p(t) g(t/ρ) dt``: ``ξ K(ξ)`` below 1, ``K(1/ξ)`` above."""
    xi = np.asarray(xi, dtype=float)
    inside = xi < 1.0
    safe = np.where(inside, xi, 1.0 / np.where(inside, 1.0, xi))
    value = ellipk(safe * safe)
    return np.where(inside, xi * value, value)


def _hat_integrand(s: float, row: int, column: int) -> float:
    """``(1 − |s|) g((column + s)/row)`` for ``quad`` (one number at a time)."""
    xi = (column + s) / row
    value = xi * float(ellipk(xi * xi)) if xi < 1.0 else float(ellipk(1.0 / (xi * xi)))
    return (1.0 - abs(s)) * value


def influence_matrix(rho_max: float, points: int) -> np.ndarray:
    """``M`` with ``w(ρ_i) = Σ_j M_ij p_j`` (units ``σ`` and ``E*√(σ/(8B))``).

    For a pressure piecewise linear between the nodes ``ρ_j = j·rho_max/(points − 1)``
    and 0 beyond ``rho_max``, the displacement of the module docstring's kernel
    at the nodes, integrated exactly over each hat function (read-only array).
    """
    check_finite_positive("rho_max", rho_max)
    check_grid_size(points)
    return (rho_max / (points - 1)) * _influence(points)


@functools.lru_cache(maxsize=4)
def _influence(points: int) -> np.ndarray:
    """Dimensionless ``A`` with ``w_i = h Σ_j A_ij p_j`` on ``ρ_i = i h``, ``p`` piecewise linear.

    ``A_ij = (2/π) ∫ (1 − |s|) g((j + s)/i) ds`` over the hat of node ``j``
    (half hats at both ends), ``A_0j`` its plain integral (``g → π/2``).
    Integrands with the logarithmic singularity of ``K`` (``|i − j| ≤ 1``, where
    it sits at an end of a half hat) are integrated adaptively
    (``scipy.integrate.quad``, relative accuracy 1e-11), the others by
    Gauss–Legendre quadrature with :data:`_GAUSS_NODES` nodes on each half of
    the hat (the nearest singularity lies a hat's width away: error far below 1e-12).
    """
    last = points - 1
    nodes, weights = np.polynomial.legendre.leggauss(_GAUSS_NODES)
    right = 0.5 * (nodes + 1.0)                       # on [0, 1]
    half = 0.5 * weights
    matrix = np.ones((points, points))
    matrix[0, [0, last]] = 0.5
    i = np.arange(1, points)[:, None, None]
    j = np.arange(points)[None, :, None]
    upper = half * (1.0 - right) * _kernel((j + right) / i)    # s in [0, 1]
    lower = half * (1.0 - right) * _kernel((j - right) / i)    # s in [−1, 0]
    upper_sum = upper.sum(axis=2)
    lower_sum = lower.sum(axis=2)
    upper_sum[:, last] = 0.0
    lower_sum[:, 0] = 0.0
    matrix[1:] = (2.0 / math.pi) * (upper_sum + lower_sum)
    for row in range(1, points):
        for column in range(max(0, row - 1), min(points, row + 2)):
            total = 0.0
            for low, high in ((-1.0, 0.0), (0.0, 1.0)):
                if (column == 0 and low < 0) or (column == last and high > 0):
                    continue
                value, _ = quad(_hat_integrand, low, high, args=(row, column), limit=200,
                                epsabs=0.0, epsrel=1e-11)
                total += value
            matrix[row, column] = (2.0 / math.pi) * total
    matrix.flags.writeable = False
    return matrix


@dataclasses.dataclass(frozen=True, eq=False)
class GreenwoodTrippSolution:
    """GT's rough-sphere contact at one central separation, in GT's units (module docstring).

    Attributes
    ----------
    depth_star, mu : float
        The input: ``d* = d/σ``, the separation of the sphere's apex from the
        deformed mean summit plane, and ``μ = (8/3) η σ √(2Bβ)``.
    rho : numpy.ndarray
        Radial nodes ``ρ = r/√(2Bσ)`` on ``[0, rho_max]``.
    pressure : numpy.ndarray
        Nominal pressure at the nodes, units ``E*√(σ/(8B))`` (piecewise linear
        between nodes, 0 beyond ``rho_max``).
    displacement : numpy.ndarray
        Elastic displacement ``w(ρ)`` of the half-space at the nodes, units
        ``σ``; the separation is ``d* + ρ² + w(ρ) − w(0)``.
    force_star : float
        Total force ``2π ∫ ρ p dρ``, units ``E* σ^(3/2) √(B/2)``.
    approach_star : float
        Rigid-body approach ``w(0) − d*`` of the sphere, units ``σ``, counted
        from the position where the apex touches the undeformed mean summit plane.
    stiffness_star : float
        ``dF/d(approach)`` along the load curve, units ``E* √(σB/2)``: the exact
        derivative of the discrete solution (implicit differentiation of its
        equations with respect to ``d*``).
    residual : float
        ``max_i |p_i − μ F_{3/2}(s_i)| / max_i p_i`` at the returned solution.
    """

    depth_star: float
    mu: float
    rho: np.ndarray
    pressure: np.ndarray
    displacement: np.ndarray
    force_star: float
    approach_star: float
    stiffness_star: float
    residual: float


def _force_weights(rho_max: float, points: int) -> np.ndarray:
    """``W`` with ``2π ∫ ρ p dρ = W · p`` exactly for piecewise linear ``p``."""
    h = rho_max / (points - 1)
    weights = np.arange(points) * h * h
    weights[0] = h * h / 6.0
    weights[-1] = rho_max * h / 2.0 - h * h / 6.0
    return 2.0 * math.pi * weights


def greenwood_tripp(depth_star: float, mu: float, *, rho_max: float = 5.0, points: int = 100,
                    pressure_tol: float = 1e-12, edge_pressure_tol: float = 1e-6,
                    max_newton: int = 100) -> GreenwoodTrippSolution:
    """Solve GT's integral equation ``p = μ F_{3/2}(d* + ρ² + w(ρ) − w(0))``.

    Parameters
    ----------
    depth_star : float
        ``d* = d/σ``, central separation (any finite number; negative when
        the apex is below the deformed mean summit plane).
    mu : float
        ``μ = (8/3) η σ √(2Bβ)`` (> 0), see :func:`mu_parameter`.
    rho_max : float
        Outer radius of the grid in units of ``√(2Bσ)``; the pressure is 0
        beyond it. Keyword-only.
    points : int
        Nodes on ``[0, rho_max]`` (≥ 8). Keyword-only.
    pressure_tol : float
        Newton's method stops when ``max_i |p_i − μ F_{3/2}(s_i)| ≤
        pressure_tol · max_i p_i`` (``s_i`` the separation at node ``i``).
        Keyword-only.
    edge_pressure_tol : float
        The solution is rejected when ``p(rho_max) > edge_pressure_tol · max p``:
        the load would not have vanished at the grid's edge. Keyword-only.
    max_newton : int
        Maximum Newton iterations. Keyword-only.

    Returns
    -------
    GreenwoodTrippSolution

    Raises
    ------
    ValueError
        For bad arguments, or a pressure at ``rho_max`` above
        ``edge_pressure_tol · max p`` (enlarge ``rho_max``).
    ConvergenceError
        If Newton's method does not meet ``pressure_tol`` in ``max_newton`` steps.

    Notes
    -----
    Collocation at the nodes with piecewise linear pressure: ``w = M p`` with
    the influence matrix of the module docstring's kernel integrated exactly
    over each hat (:func:`influence_matrix`), ``w(ρ) − w(0) = D p``,
    ``D = M − 1 M_0``. Newton's method on ``R(p) = p − μ F_{3/2}(d* + ρ² + D p)``
    with Jacobian ``J = I + (3/2) μ diag(F_{1/2}) D`` (``F'_n = −n F_{n−1}``),
    halving the step until ``max |R|`` decreases, from the rigid-sphere
    pressure ``μ F_{3/2}(d* + ρ²)``. Sensitivity: ``∂p/∂d* = −J⁻¹ (3/2) μ F_{1/2}``,
    whence ``stiffness_star = (W ∂p/∂d*)/(M_0 ∂p/∂d* − 1)`` with ``W`` the
    force weights.
    """
    if (isinstance(depth_star, bool) or not isinstance(depth_star, (int, float, np.floating))
            or not math.isfinite(depth_star)):
        raise ValueError(f"depth_star must be a finite number, got {depth_star!r}")
    check_finite_positive("mu", mu)
    check_finite_positive("rho_max", rho_max)
    check_grid_size(points)
    check_finite_positive("pressure_tol", pressure_tol)
    check_finite_positive("edge_pressure_tol", edge_pressure_tol)
    if isinstance(max_newton, bool) or not isinstance(max_newton, int) or max_newton < 1:
        raise ValueError(f"max_newton must be a positive integer, got {max_newton!r}")
    rho = np.linspace(0.0, rho_max, points)
    influence = influence_matrix(rho_max, points)
    relative = influence - influence[0]
    rigid = depth_star + rho * rho

    def residual_of(pressure):
        separation = rigid + relative @ pressure
        return pressure - mu * gt_function(separation, 1.5), separation

    pressure = mu * gt_function(rigid, 1.5)
    residual, separation = residual_of(pressure)
    for _ in range(max_newton):
        size = float(np.abs(residual).max())
        if size <= pressure_tol * float(pressure.max()):
            break
        jacobian = np.eye(points) + (1.5 * mu * gt_function(separation, 0.5))[:, None] * relative
        step = np.linalg.solve(jacobian, -residual)
        scale = 1.0
        while True:
            trial = pressure + scale * step
            trial_residual, trial_separation = residual_of(trial)
            if float(np.abs(trial_residual).max()) < size or scale < 1e-10:
                break
            scale *= 0.5
        pressure, residual, separation = trial, trial_residual, trial_separation
    size = float(np.abs(residual).max()) / float(pressure.max())
    if size > pressure_tol:
        raise ConvergenceError(f"Greenwood-Tripp Newton iteration did not converge "
                           f"(residual {size:.2e} > {pressure_tol:g})")
    if pressure[-1] > edge_pressure_tol * pressure.max():
        raise ValueError(f"pressure at rho_max = {rho_max:g} is {pressure[-1] / pressure.max():.2e} "
                         f"of its maximum (> edge_pressure_tol): enlarge rho_max")
    jacobian = np.eye(points) + (1.5 * mu * gt_function(separation, 0.5))[:, None] * relative
    sensitivity = np.linalg.solve(jacobian, -1.5 * mu * gt_function(separation, 0.5))
    weights = _force_weights(rho_max, points)
    displacement = influence @ pressure
    stiffness = float(weights @ sensitivity) / (float(influence[0] @ sensitivity) - 1.0)
    return GreenwoodTrippSolution(
        depth_star=float(depth_star), mu=float(mu), rho=rho, pressure=pressure,
        displacement=displacement, force_star=float(weights @ pressure),
        approach_star=float(displacement[0] - depth_star), stiffness_star=stiffness,
        residual=size)

