"""Adhesive contact by the mesh-dependent detachment criterion of Pohrt & Popov.

R. Pohrt, V. L. Popov, "Adhesive contact simulation of elastic solids using local mesh-dependent
detachment criterion in boundary elements method", Facta Universitatis Mech. Eng. 13, 3-10
(2015). A cell of side ``Δx`` joins the contact when the deformed gap closes there, and leaves it
only when its tensile stress exceeds the critical stress

    σ_c = √(c · E* w / Δx),

so that the contact set, and with it the force, depends on the path: loading and unloading
differ (hysteresis), and the pull-off force is the most tensile force of the unloading path.

The constant. The edge of an adhesive contact is a crack tip: the normal stress ahead of it is
``σ(s) = −K/√(2πs)`` at the distance ``s``, with ``K = √(2E*w)`` for a rigid indenter on a
half-space of modulus ``E*`` (Griffith: ``G = K²/(2E*) = w``; JKR's edge stress
``√(wE*/(πs))`` is the same). If the element next to the tip carried the mean of that field over
its width, ``(1/Δx)∫₀^Δx K/√(2πs) ds = √(4E*w/(πΔx))``, the constant would be ``c = 4/π``.
The boundary elements carry a uniform pressure each, collocated at their centres, and the
contact's edge on a square grid is a staircase: the edge element's pressure is the continuum
stress nearer the tip than its mean. Calibrated on JKR (the smooth sphere's load-controlled
pull-off ``−(3/2)πwR``, contact radius at pull-off 10, 20 and 40 cells, measured 2026-11-24), the
pull-off scales as ``c`` and is ``0.527 c``, ``0.498 c`` and ``0.486 c`` times JKR's, converging
(geometrically, ratio 0.4) to ``0.478 c``: ``c = 2.1`` makes the method converge to JKR
(+10.9 %, +5.2 % and +1.4 % at 10, 20 and 40 cells); ``c = 4/π`` would converge to 61 % of it.
``tests/test_adhesion_bem.py`` checks it.

The solve at a given approach ``d`` (displacement control): on the contact set ``C`` the surface
follows the indenter, ``u_i = d − (z_i − min z)``, and the pressures solve ``K_CC p_C = u_C`` by
conjugate gradients (``‖K_CC p_C − u_C‖ ≤ tol ‖u_C‖``); cells of ``C`` with ``p < −σ_c``
leave it, cells outside with a closed gap (``z_i − min z − d + u_i < 0``) join it, and the
solve repeats until ``C`` is unchanged. Each approach starts from the previous contact set and
pressures (warm start). Pressures are compressive positive, forces ``F = Σ p Δx²``.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from .._validate import check_finite_positive
from ..errors import ConvergenceError
from .operators import operator_for

__all__ = ["DETACHMENT_CONSTANT", "critical_stress", "AdhesivePath", "adhesive_path"]

#: ``c`` of the detachment criterion ``σ_c = √(c E* w/Δx)``, calibrated on JKR (module docstring)
DETACHMENT_CONSTANT = 2.1


def critical_stress(*, e_star: float, work_of_adhesion: float, spacing: float,
                    constant: float = DETACHMENT_CONSTANT) -> float:
    """``σ_c = √(c E* w/Δx)``: the tensile stress at which a cell of side ``spacing`` detaches."""
    check_finite_positive("e_star", e_star)
    check_finite_positive("work_of_adhesion", work_of_adhesion)
    check_finite_positive("spacing", spacing)
    return math.sqrt(constant * e_star * work_of_adhesion / spacing)


@dataclasses.dataclass(frozen=True)
class AdhesivePath:
    """The states of a displacement-controlled adhesive path, one entry per approach.

    Attributes
    ----------
    depth : numpy.ndarray
        Approach ``d`` from first touch (length).
    force : numpy.ndarray
        ``F = Σ p Δx²`` (force; negative: tensile).
    contact_cells : numpy.ndarray
        Cells in contact.
    contact_radius : numpy.ndarray
        ``√(A/π)`` of the contact area ``A`` (length).
    iterations : numpy.ndarray
        Contact-set updates of each approach.
    pull_off_force : float
        The most tensile force of the path (force): the pull-off under load control.
    detach_depth : float
        The first approach of the path's unloading at which no cell is left in contact (NaN if
        the contact never comes off).
    """

    depth: np.ndarray
    force: np.ndarray
    contact_cells: np.ndarray
    contact_radius: np.ndarray
    iterations: np.ndarray
    pull_off_force: float
    detach_depth: float


def _cg(apply, rhs, x, *, tol, maxiter):
    """Conjugate gradients on the SPD ``apply`` from ``x``: ``‖apply(x) − rhs‖ ≤ tol ‖rhs‖``."""
    r = rhs - apply(x)
    p = r.copy()
    rr = float(r @ r)
    limit = (tol * float(np.linalg.norm(rhs))) ** 2
    for _ in range(maxiter):
        if rr <= limit:
            return x
        ap = apply(p)
        alpha = rr / float(p @ ap)
        x += alpha * p
        r -= alpha * ap
        rr_new = float(r @ r)
        p = r + (rr_new / rr) * p
        rr = rr_new
    if rr <= limit:
        return x
    raise ConvergenceError(f"conjugate gradients did not reach tol = {tol:g} in {maxiter} iterations")


def adhesive_path(z, depths, *, length: float, e_star: float, work_of_adhesion: float, periodic: bool = False,
                  constant: float = DETACHMENT_CONSTANT, tol: float = 1e-10, maxiter: int = 2000,
                  max_updates: int = 2000) -> AdhesivePath:
    """Press the indenter *z* (``n × n`` heights, lowest first) along the approaches *depths*
    (length, from first touch; rising for loading, falling for unloading, in any sequence) into
    a half-space that sticks by the detachment criterion (module docstring).

    Parameters
    ----------
    z : array_like
        Indenter heights (length), ``n × n``.
    depths : array_like
        The approaches, in path order (length).
    length, e_star, work_of_adhesion : float
        Side of the grid, effective modulus, work of adhesion ``w`` (energy per area).
    periodic : bool
        Periodic half-space instead of the free one.
    constant : float
        ``c`` of ``σ_c = √(c E* w/Δx)``.
    tol, maxiter : float, int
        Keyword-only: the conjugate gradients' relative residual and iteration limit per solve.
    max_updates : int
        Most contact-set updates per approach.

    Raises
    ------
    ConvergenceError
        A solve or the contact set does not settle within its limits.
    """
    z = np.asarray(z, dtype=float)
    if z.ndim != 2 or z.shape[0] != z.shape[1]:
        raise ValueError(f"z must be a square n x n array, got shape {z.shape}")
    check_finite_positive("length", length)
    n = z.shape[0]
    spacing = length / n
    sigma_c = critical_stress(e_star=e_star, work_of_adhesion=work_of_adhesion, spacing=spacing, constant=constant)
    operator = operator_for(n, length, e_star, periodic)
    heights = z - z.min()
    contact = np.zeros(z.shape, dtype=bool)
    pressure = np.zeros(z.shape)
    out = {key: [] for key in ("depth", "force", "contact_cells", "contact_radius", "iterations")}
    detach_depth = math.nan
    for d in np.asarray(depths, dtype=float):
        for update in range(max_updates):
            if not contact.any():
                contact = heights <= d        # first touch: every cell the rigid approach reaches
                pressure[:] = 0.0
                if not contact.any():
                    break
            target = (d - heights)[contact]

            def apply(values):
                field = np.zeros(z.shape)
                field[contact] = values
                return operator(field)[contact]

            pressure[~contact] = 0.0
            pressure[contact] = _cg(apply, target, pressure[contact].copy(), tol=tol, maxiter=maxiter)
            displacement = operator(pressure)
            gap = heights - d + displacement
            leave = contact & (pressure < -sigma_c)
            join = ~contact & (gap < 0.0)
            if not leave.any() and not join.any():
                break
            contact = (contact & ~leave) | join
            pressure[~contact] = 0.0
        else:
            raise ConvergenceError(f"the contact set did not settle in {max_updates} updates at d = {d:g}")
        cells = int(np.count_nonzero(contact))
        if cells == 0 and math.isnan(detach_depth) and out["contact_cells"] and out["contact_cells"][-1] > 0:
            detach_depth = float(d)
        out["depth"].append(float(d))
        out["force"].append(float(pressure.sum() * spacing**2))
        out["contact_cells"].append(cells)
        out["contact_radius"].append(math.sqrt(cells * spacing**2 / math.pi))
        out["iterations"].append(update + 1)
    arrays = {key: np.asarray(value) for key, value in out.items()}
    return AdhesivePath(**arrays, pull_off_force=float(arrays["force"].min()) if len(arrays["force"]) else math.nan,
                        detach_depth=detach_depth)
