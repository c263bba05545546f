"""One stickiness run: a flat rough surface loaded into a Maugis–Dugdale half-space, its slope dF/dA.

1. **The surface**: :func:`roughcontact.surfaces.self_affine` of the run's H and seed on the
   ``n × n`` periodic grid, cut off below ``cutoff`` cells (no roll-off), scaled to the rms
   gradient ``h′``; its own spectral moments give ``h″`` (the rms of ``∇²h/2``) and
   ``g₀ = (16/3)h′²/h″``.
2. **The interaction** of Pastewka & Robbins' number ``N`` (PNAS 111 (2014) 3298,
   doi:10.1073/pnas.1320846111): the range ``Δr = range_ratio · g₀`` and the work
   ``w = (h′E*Δr/(2N)) (h′²/(h″Δr))^(2/3)``, i.e. a Dugdale tension ``σ₀ = w/Δr`` wherever the gap
   is below ``Δr`` (:func:`roughcontact.bem.cohesive.cohesive_path`, periodic half-space).
3. **The loading**, displacement-controlled, in ``steps`` equal approaches from ``−Δr`` (the
   highest summit comes into range) to ``d_A + Δr``, ``d_A`` the approach at which the surface
   *without* adhesion covers the fraction ``area`` of the grid (adhesion only adds contact at an
   approach), ending at the first approach whose contact covers more than ``area``: force, contact
   and zone cells per approach. A sticky surface may jump into contact at once (a cell's own
   tension ``σ₀`` may close more than its gap) and end after a few approaches.
4. **The loading slope** ``F/A`` at ``A* = area · L²``: the load per contact area of ``F/(h′E*)``
   when the contact first covers the fraction ``area`` of the grid (:func:`loading_slope`;
   dimensionless). A rough surface's load grows in proportion to its contact at small areas, so
   this is the slope ``dF/dA`` of that linear regime, yet it is defined also where a sticky
   surface jumps into contact. Without adhesion it is ``1/κ``, ``κ ≈ 2`` (Hyun et al., Phys. Rev.
   E 70 (2004) 026117; Persson's ``√(8/π)``); with enough adhesion it changes sign: the contact
   holds an area ``A*`` under tension, the surface is sticky.

Forces in ``e_star * length**2``, lengths in the unit of ``grid.length``.
"""
from __future__ import annotations

import dataclasses
import logging
import math

import numpy as np

from ...bem import solve
from ...bem.cohesive import cohesive_path
from ...errors import ConvergenceError, IndentError
from .path import LoadPath
from ...models.rough_adhesion import (pastewka_robbins_gap, pastewka_robbins_stickiness,
                                      pastewka_robbins_work_of_adhesion)
from ...surfaces.moments import spectral_moments
from ...surfaces.roughness import self_affine

__all__ = ["StickinessSurface", "loading_slope", "stickiness_surface", "stickiness_run"]

logger = logging.getLogger(__name__)


def loading_slope(force, area, *, at: float) -> float:
    """The secant slope ``F(A*)/A*`` of a loading path at the contact area ``A* = at`` (module
    docstring, 4.): the force interpolated linearly in the area between the last state with
    ``A ≤ A*`` and the first beyond it, the path preceded by the surfaces apart (``A = 0``,
    ``F = 0``; the loading's area grows with the approach, and a sticky surface may jump over
    ``A*`` from there); NaN where the path does not reach ``A*``."""
    force, area = np.r_[0.0, np.asarray(force, float)], np.r_[0.0, np.asarray(area, float)]
    beyond = np.flatnonzero(area > at)
    if not beyond.size:
        return math.nan
    k = int(beyond[0])
    t = (at - area[k - 1]) / (area[k] - area[k - 1])
    return float((force[k - 1] + t * (force[k] - force[k - 1])) / at)


@dataclasses.dataclass(frozen=True)
class StickinessSurface:
    """The surface of a stickiness run and its interaction (module docstring, 1.–2.).

    Attributes
    ----------
    heights : numpy.ndarray
        ``n × n`` heights (length), rms gradient ``h′``.
    rms_curvature : float
        ``h″``, the rms of ``∇²h/2`` (1/length).
    interaction_range, work_of_adhesion : float
        ``Δr`` (length) and ``w`` (``e_star * length``).
    criterion : roughcontact.models.rough_adhesion.StickinessCriterion
        Pastewka & Robbins' number, prediction and ``g₀`` at that ``Δr`` and ``w``.
    """

    heights: np.ndarray
    rms_curvature: float
    interaction_range: float
    work_of_adhesion: float
    criterion: object


def stickiness_surface(s) -> StickinessSurface:
    """The surface of the run *s* (:class:`~.settings.StickinessRun`) and the interaction that
    gives it the run's number."""
    z = self_affine(s.n, hurst=s.hurst, h_rms=1.0, length=s.length, seed=s.seed, cutoff=s.cutoff * s.length / s.n)
    z *= s.rms_slope / math.sqrt(2.0 * spectral_moments(z, length=s.length).m2)
    moments = spectral_moments(z, length=s.length)
    slope, curvature = math.sqrt(2.0 * moments.m2), 0.5 * math.sqrt(8.0 * moments.m4 / 3.0)
    reach = s.range_ratio * pastewka_robbins_gap(rms_slope=slope, rms_curvature=curvature)
    work = pastewka_robbins_work_of_adhesion(s.number, rms_slope=slope, rms_curvature=curvature,
                                             interaction_range=reach, e_star=s.e_star)
    criterion = pastewka_robbins_stickiness(rms_slope=slope, rms_curvature=curvature, interaction_range=reach,
                                            e_star=s.e_star, work_of_adhesion=work)
    return StickinessSurface(z, curvature, reach, work, criterion)


def _area_approach(z, s) -> float:
    """``d_A``: the approach at which *z* without adhesion covers at least ``s.area`` of the grid
    (force-controlled solves from ``F = h′E*A/2``, raised until it does)."""
    force = s.rms_slope * s.e_star * s.length**2 * s.area / 2.0
    for _ in range(20):
        state = solve(z, force=force, length=s.length, e_star=s.e_star, periodic=True, tol=s.tol)
        covered = float(np.mean(state.contact))
        if covered >= s.area:
            return float(state.depth)
        force *= 1.5 * s.area / max(covered, 0.1 * s.area)
    raise IndentError(f"stickiness: no load brings the contact to stickiness.area = {s.area:g} of the grid")


def stickiness_run(s) -> dict:
    """The loading path of the stickiness run *s* (:class:`~.settings.StickinessRun`; module
    docstring): a dict of the arrays ``depth``,
    ``force``, ``contact_cells``, ``zone_cells`` (one per approach) and the scalars of
    :data:`roughcontact.study.files.runfile.STICKINESS_SCALARS`. Raises
    :class:`~roughcontact.errors.IndentError` naming the run when a solve does not converge; each
    approach is logged."""
    name = s.describe()
    surface = stickiness_surface(s)
    z, reach, work, criterion = (surface.heights, surface.interaction_range, surface.work_of_adhesion,
                                 surface.criterion)
    top = _area_approach(z, s) + reach
    depths = np.linspace(-reach, top, s.steps)
    cells = s.n * s.n
    scale = s.rms_slope * s.e_star * s.length**2
    logger.info("%s: h' = %.4g, h'' = %.4g, g0 = %.4g (%.3g cells), dr = %.4g, w = %.4g, sigma0/E* = %.4g, "
                "N = %.4g; %d approaches %.4g ... %.4g", name, s.rms_slope, surface.rms_curvature,
                criterion.g0, criterion.g0 * s.n / s.length, reach, work, work / reach / s.e_star, criterion.number,
                s.steps, depths[0], depths[-1])

    def record(i, contact, zone) -> str:   # an approach: its contact and zone, reported (the path keeps them)
        return f"contact {np.count_nonzero(contact) / cells:.4f}, zone {np.count_nonzero(zone) / cells:.4f} of the grid"

    follow = LoadPath(name, s.steps, record, what="approach")
    with follow.failing(ConvergenceError, lambda exc: f"{name}: the cohesive solve did not converge at {follow.where} "
                                                      f"({exc}); lower stickiness.area or use more cells (stickiness.n)"):
        path = cohesive_path(z, depths, length=s.length, e_star=s.e_star, work_of_adhesion=work,
                             cohesive_stress=work / reach, periodic=True, tol=s.tol, on_state=follow,
                             until=lambda i, force, contact: contact > s.area * cells)
    area = path.contact_cells / cells
    slope = loading_slope(path.force / scale, area, at=s.area)
    logger.info("%s: F/A = %.4g h'E* at A = %g L^2 (%d approaches with 0 < A <= %g L^2)", name, slope, s.area,
                int(np.count_nonzero((area > 0) & (area <= s.area))), s.area)
    return {
        "depth": path.depth, "force": path.force, "contact_cells": path.contact_cells.astype("i8"),
        "zone_cells": path.zone_cells.astype("i8"),
        "rms_slope": s.rms_slope, "rms_curvature": surface.rms_curvature, "interaction_range": reach,
        "work_of_adhesion": work, "pastewka_robbins_number": criterion.number, "range_ratio": criterion.range_ratio,
        "loading_slope": slope,
    }
