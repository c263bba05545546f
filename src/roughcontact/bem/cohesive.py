"""Adhesive contact with a Maugis–Dugdale cohesive zone.

D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model", J. Colloid
Interface Sci. 150, 243-269 (1992), doi:10.1016/0021-9797(92)90285-T. The interaction is the
Dugdale law: a constant tensile stress ``σ₀`` acts on every cell whose gap ``g`` is
``0 < g ≤ δ_t = w/σ₀`` (the cohesive zone ``Z``; ``w`` the work of adhesion, the area under the
law), none where ``g > δ_t``; where the surfaces touch (``g = 0``, the contact ``C``) the pressure
is free, tensile too, down to ``−σ₀``: a contact cell that would need more tension opens (as in
Maugis' model, whose stress at the contact edge is ``−σ₀``; without the cap no cell would ever
leave the contact). No interpenetration: ``g ≥ 0`` everywhere. Pressures are compressive
positive, ``F = Σ p Δx²`` with the zone's tension; ``g = h − d + u``, ``h = z − min z``,
``u = K p`` (:mod:`roughcontact.bem.operators`).

The solve at an approach ``d`` (displacement control). With ``S = C ∪ Z`` (the cells within
range) fixed and the lift ``q = p + σ₀`` on ``S``, the law is the contact of a half-space loaded
by ``−σ₀`` on ``S``: ``q ≥ 0``, ``g ≥ 0``, ``q g = 0`` on ``S``, ``q = 0`` off it, a convex
problem (the shifted formulation of Rey, Anciaux & Molinari, Comput. Mech. 60, 69 (2017),
doi:10.1007/s00466-017-1392-5). It is solved by the constrained conjugate gradients of
Polonsky & Keer (Wear 231, 206 (1999)) with the approach given (no force constraint: the gap on
``q > 0`` is the residual; cells of ``S`` with ``q = 0`` and ``g < 0`` enter), to
``max |g| ≤ tol·s`` on ``q > 0`` and ``g ≥ −tol·s`` elsewhere on ``S``,
``s = max(δ_t, max_S |h − d|)``; on the bounding box of ``S`` (the periodic half-space too, by the
periodic kernel on the window's zero-padded FFT, exact for lifts inside the box, while the box is
at most half the grid a side; the whole grid otherwise). Then ``S``
is updated from the gaps of the whole grid — computed on a window around ``S``, widened to every
cell that a bound of the displacement elsewhere leaves possibly in range — and the solve repeats
until ``S`` is unchanged. Each
approach starts from the previous ``S`` and lifts (warm start), so that where several
equilibria exist (the jump-in and jump-out of the non-convex law) the path picks its branch.
Every state returned satisfies the law above.

The edge. A cell at the zone's outer edge opens its own gap by ``s_c = K_ii σ₀`` (``K_ii`` the
operator's self-coefficient) when its tension is taken off, so within ``s_c`` both of its
states are consistent (``g ≤ δ_t`` in ``S``, ``g > δ_t`` out of it). ``edge_rule="metastable"``
keeps the state the cell was in: the literal law, whose lattice trapping keeps cells in the zone
too long on unloading and makes the pull-off too tensile by about ``0.4 Δx/(c − a)`` (``c − a``
the zone's width; 0.30-0.46 measured at λ = 1-3). ``edge_rule="energy"`` (the default) counts a
cell in ``S`` when its gap midway between the two states is in range, ``g ± s_c/2 ≤ δ_t`` (``+``
in ``S``, ``−`` out): with the cell's own compliance, the state of lower energy (the energies of
the two states differ by ``σ₀ Δx² (g_out − s_c/2 − δ_t)``), i.e. Maxwell's rule for that cell;
its states are equilibria of the law too. Many cells switching at once can make these updates
cycle; an approach whose updates cycle is settled by the metastable rule from where the cycle
was found (``CohesivePath.fallback``).

Measured (2026-11-25; smooth sphere, pull-off against Maugis'
(:func:`roughcontact.models.adhesion.maugis_dugdale_pull_off`), ``ℓ = (πwR²/K)^{1/3}``,
``K = 4E*/3``, in cells; the unloading in steps of ``0.04 ℓ²/R``, whose sampling of the
cell-by-cell detachment moves the numbers by about ±1 %). Energy rule: λ = 0.5 +1.4 %, +1.1 % at
ℓ = 8, 12; λ = 1 +4.0 %, +2.9 %, +1.1 % at ℓ = 8, 12, 16; λ = 2 +4.0 % at ℓ = 20 (a zone of 3
cells); λ = 3 +3.3 %, +2.4 %, +1.9 % at ℓ = 16, 24, 32 (zones of 1.2-2.4 cells; 40-47 of the 60
approaches fall back); λ = 0.1 and 0.05 within 0.3 % at ℓ = 4. Metastable rule: λ = 1 +11.8 %,
+7.4 %, +4.4 %, +3.4 % at ℓ = 8, 12, 16, 24; λ = 2 +17.9 %, +11.5 % at ℓ = 16, 24; λ = 3 +18.3 %
at ℓ = 32.

The half-space is elastic: the adhesive paths take no ``hardness`` (passing one is a
``TypeError``); penetration-hardness plasticity (:mod:`roughcontact.bem.plastic`) is not combined
with adhesion.
"""
from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from .._validate import check_finite, check_finite_positive
from ..errors import ConvergenceError, DomainTooSmallError
from .active_sets import bounding_box
from .adhesion import CohesivePath
from .operators import operator_for, periodic_windows

__all__ = ["EDGE_RULES", "CohesivePath", "cohesive_path"]

#: Incremental displacement updates between two exact (FFT) recomputations in the contact solve.
_REFRESH = 50

#: How a cell at the zone's outer edge is counted (module docstring): the state of lower energy, or
#: the state it was in while that is consistent
EDGE_RULES = ("energy", "metastable")


def _full_contact(d: float) -> str:
    """Why a periodic displacement-controlled solve fails in full contact."""
    return (f"the cohesive contact covers the periodic grid at d = {d:g}: in full contact the approach does not "
            "fix the mean pressure")


@dataclasses.dataclass(frozen=True)
class _Lift:
    """The lifts ``q`` held on a box of the grid (zero outside it): the state's only floats, so that
    a path keeps no grid-sized array but the heights."""

    box: tuple[slice, slice]
    values: np.ndarray

    def on(self, box: tuple[slice, slice]) -> np.ndarray:
        """The lifts on *box* (a new array, zero outside :attr:`box`)."""
        out = np.zeros((box[0].stop - box[0].start, box[1].stop - box[1].start))
        rows = slice(max(box[0].start, self.box[0].start), min(box[0].stop, self.box[0].stop))
        cols = slice(max(box[1].start, self.box[1].start), min(box[1].stop, self.box[1].stop))
        if rows.start < rows.stop and cols.start < cols.stop:
            out[rows.start - box[0].start:rows.stop - box[0].start, cols.start - box[1].start:cols.stop - box[1].start] = \
                self.values[rows.start - self.box[0].start:rows.stop - self.box[0].start,
                            cols.start - self.box[1].start:cols.stop - self.box[1].start]
        return out


_NO_LIFT = _Lift((slice(0, 0), slice(0, 0)), np.zeros((0, 0)))


class _CohesiveSolver:
    """The solve at one approach (module docstring) on one grid."""

    def __init__(self, z, *, length, e_star, work_of_adhesion, cohesive_stress, periodic, edge_rule, tol,
                 maxiter, max_updates):
        z = np.asarray(z, dtype=float)
        if z.ndim != 2 or z.shape[0] != z.shape[1]:
            raise ValueError(f"z must be a square n x n array, got shape {z.shape}")
        if not np.all(np.isfinite(z)):
            raise ValueError("z must be finite everywhere")
        check_finite_positive("length", length)
        check_finite_positive("e_star", e_star)
        check_finite_positive("work_of_adhesion", work_of_adhesion)
        check_finite_positive("cohesive_stress", cohesive_stress)
        check_finite_positive("tol", tol)
        n = z.shape[0]
        self.spacing = length / n
        self.sigma = float(cohesive_stress)
        self.range = work_of_adhesion / cohesive_stress
        self.operator = operator_for(n, length, e_star, periodic)
        self.windows = periodic_windows(self.operator) if periodic else self.operator
        self.periodic = periodic
        self.heights = z - z.min()
        self.tol, self.maxiter, self.max_updates = tol, maxiter, max_updates
        if edge_rule not in EDGE_RULES:
            raise ValueError(f"edge_rule must be one of {', '.join(EDGE_RULES)}, got {edge_rule!r}")
        self.edge_rule = edge_rule

    def empty(self):
        """The state before any interaction: ``(reach, lift)``, both zero."""
        return np.zeros(self.heights.shape, dtype=bool), _NO_LIFT

    def _contact(self, d, reach, lift):
        """The lifts ``q = p + σ₀ ≥ 0`` on *reach* (``S``) at the approach *d*: the convex contact
        problem of the module docstring, by displacement-controlled constrained conjugate
        gradients (Polonsky & Keer 1999 with the approach given: no force constraint, the gap
        itself the residual), on the bounding box of ``S`` (periodic: the grid when the box is
        more than half of it a side). Stops when ``max_(q>0) |g| ≤ tol·s`` and
        ``min_(S, q=0) g ≥ −tol·s``, ``s = max(δ_t, max_S |h − d|)``."""
        n = self.heights.shape[0]
        box, operator = bounding_box(reach), self.windows
        if self.periodic and max(side.stop - side.start for side in box) > n // 2:
            box, operator = (slice(0, n), slice(0, n)), self.operator
        inside = reach[box]
        q = np.where(inside, lift.on(box), 0.0)
        base = self.heights[box] - d
        scale = max(self.range, float(np.abs(base[inside]).max()))
        base = base - self.sigma * operator(inside.astype(float))     # h − d + K(−σ₀ 1_S)
        limit = self.tol * scale
        direction = np.zeros_like(q)
        displacement, exact, since_exact = operator(q), True, 0
        column_limit = operator.column_limit(q.shape)
        norm_old, conjugate = 1.0, False
        for iteration in range(self.maxiter + 1):
            gap = base + displacement
            support = q > 0.0
            free = inside & ~support
            error = max(float(np.abs(gap[support]).max()) if support.any() else 0.0,
                        float(-gap[free].min()) if free.any() else 0.0)
            if error <= limit and not exact:        # accepted on an exact displacement only
                displacement, exact, since_exact = operator(q), True, 0
                continue
            if error <= limit:
                return _Lift(box, q)
            if iteration == self.maxiter:
                break
            residual = np.where(support, gap, 0.0)
            norm = float((residual * residual).sum())
            if norm == 0.0:                     # no residual on the contact (first touch): the
                closed = free & (gap < 0.0)     # penetrating cells by the self-coefficient
                q[closed] = -gap[closed] / operator.self_coefficient
                displacement, exact, since_exact, conjugate = operator(q), True, 0, False
                continue
            direction = residual + (norm / norm_old) * np.where(support, direction, 0.0) if conjugate else residual
            norm_old = norm
            response = operator(direction)
            curvature = float((response * direction)[support].sum())
            if not curvature > 0.0:         # a uniform direction on the whole periodic grid
                raise ConvergenceError(_full_contact(d))
            step = float((gap * direction)[support].sum()) / curvature
            trial = q - step * direction
            q = np.maximum(trial, 0.0)
            closed = free & (gap < 0.0)         # P&K: free cells that penetrate enter the contact
            q[closed] = -step * gap[closed]
            conjugate = not closed.any()
            changed = np.flatnonzero(q != trial)
            if changed.size <= column_limit and since_exact < _REFRESH:   # u updated, not recomputed
                displacement -= step * response
                operator.add_columns(displacement, q.reshape(-1)[changed] - trial.reshape(-1)[changed], changed)
                exact, since_exact = False, since_exact + 1
            else:
                displacement, exact, since_exact = operator(q), True, 0
        if self.periodic and support.size == n * n and support.all():
            raise ConvergenceError(_full_contact(d))
        raise ConvergenceError(f"the cohesive contact did not reach tol = {self.tol:g} in {self.maxiter} "
                               f"iterations at d = {d:g} (error {error / scale:.2e})")

    def _tail(self, distance: int) -> float:
        """Largest ``|K_ij|`` (displacement under a unit cell pressure) at offsets of at least
        *distance* cells in one direction (the periodic distance on the periodic half-space);
        Love's coefficients fall monotonically with each offset, so the free half-space's is
        the one at ``(distance, 0)``."""
        n = self.heights.shape[0]
        if self.periodic:
            tails = self._periodic_tails
            return float(tails[distance]) if distance < tails.size else 0.0
        if distance >= n:
            return 0.0
        return float(self.windows._coefficients(distance + 1)[distance, 0])

    @functools.cached_property
    def _periodic_tails(self) -> np.ndarray:
        """``[m]``: largest ``|k|`` of the periodic kernel at periodic distance ≥ ``m`` in a direction."""
        kernel = self.operator._kernel
        n = kernel.shape[0]
        rows = np.maximum.reduce([kernel.max(axis=1), -kernel.min(axis=1), kernel.max(axis=0), -kernel.min(axis=0)])
        index = np.arange(n)
        tails = np.zeros(n // 2 + 1)
        np.maximum.at(tails, np.minimum(index, n - index), rows)
        return np.maximum.accumulate(tails[::-1])[::-1]

    def _in_range(self, d: float, reach, lift, shift: float):
        """``(new, force)``: the cells with ``g ± shift ≤ δ_t`` (``+`` in ``S``, ``−`` out) under
        the pressure ``p = q − σ₀`` on *reach*, and the force ``Σ p Δx²``.

        The gaps are computed on a window: the bounding box of ``S`` widened by a margin ``m``,
        and further to take every cell outside it that might be in range, ``h − d − B ≤ δ_t +
        shift`` with ``B = Σ|p| · max_(offset ≥ m+1) |K|`` a bound of ``|u|`` there (the free
        half-space's window clipped to the grid; the periodic one on the whole grid when it
        would wrap). Exact: the displacement on the window is that of all of ``p``, which lies
        inside it, and no cell outside is in range."""
        n = self.heights.shape[0]
        if not reach.any():
            return self.heights <= d + self.range + shift, 0.0
        rows, cols = bounding_box(reach)
        inside = reach[rows, cols]
        pressure = np.where(inside, lift.on((rows, cols)) - self.sigma, 0.0)
        force = float(pressure.sum() * self.spacing**2)
        margin = max(8, max(rows.stop - rows.start, cols.stop - cols.start) // 2)
        window = [max(rows.start - margin, 0), min(rows.stop + margin, n),
                  max(cols.start - margin, 0), min(cols.stop + margin, n)]
        whole = self.periodic and (rows.start < margin or cols.start < margin or rows.stop + margin > n
                                   or cols.stop + margin > n)
        if not whole:
            bound = float(np.abs(pressure).sum()) * self._tail(margin + 1)
            candidates = self.heights <= d + self.range + shift + bound
            c_rows, c_cols = bounding_box(candidates) if candidates.any() else (rows, cols)
            del candidates
            window = [min(window[0], c_rows.start), max(window[1], c_rows.stop),
                      min(window[2], c_cols.start), max(window[3], c_cols.stop)]
            whole = self.periodic and max(window[1] - window[0], window[3] - window[2]) > n // 2
        if whole:
            window, operator = [0, n, 0, n], self.operator
        else:
            operator = self.windows
        box = (slice(window[0], window[1]), slice(window[2], window[3]))
        loaded = np.zeros((window[1] - window[0], window[3] - window[2]))
        loaded[rows.start - window[0]:rows.stop - window[0], cols.start - window[2]:cols.stop - window[2]] = pressure
        gap = operator(loaded)
        gap += self.heights[box] - d
        gap += np.where(reach[box], shift, -shift)
        new = np.zeros(reach.shape, dtype=bool)
        new[box] = gap <= self.range
        return new, force

    def settle(self, d: float, reach, lift):
        """``(reach, lift, force, updates, fallback)`` at the approach *d* from the state
        ``(reach, lift)`` (not modified): ``S`` updated by the edge rule until unchanged
        (module docstring); *fallback* tells whether the energy rule cycled and the metastable
        rule settled the approach."""
        rules = ("energy", "metastable") if self.edge_rule == "energy" else ("metastable",)
        updates = 0
        for rule in rules:
            shift = 0.5 * self.sigma * self.operator.self_coefficient if rule == "energy" else 0.0
            seen = set()
            while updates < self.max_updates:
                updates += 1
                lift = self._contact(d, reach, lift) if reach.any() else _NO_LIFT
                new, force = self._in_range(d, reach, lift, shift)
                if not self.periodic and (new[0].any() or new[-1].any() or new[:, 0].any() or new[:, -1].any()):
                    raise DomainTooSmallError(f"the cohesive zone reached the edge of the free-space grid at "
                                              f"d = {d:g}: enlarge length (or use periodic=True)")
                if np.array_equal(new, reach):
                    return reach, lift, force, updates, rule != self.edge_rule
                key = np.packbits(new).tobytes()
                if key in seen:
                    break                                   # a cycle: the next rule from here
                seen.add(key)
                reach = new
            else:
                raise ConvergenceError(f"the cohesive zone did not settle in {self.max_updates} updates at d = {d:g}")
        raise ConvergenceError(f"the cohesive zone's updates cycle at d = {d:g} under every edge rule")


def cohesive_path(z, depths, *, length: float, e_star: float, work_of_adhesion: float, cohesive_stress: float,
                  periodic: bool = False, edge_rule: str = "energy", tol: float = 1e-10, maxiter: int = 2000,
                  max_updates: int = 500, on_state=None, until=None) -> CohesivePath:
    """Press the indenter *z* along the approaches *depths* into a half-space that sticks by the
    Maugis–Dugdale cohesive zone (module docstring).

    Parameters
    ----------
    z : array_like
        Indenter heights (length), ``n × n``.
    depths : array_like
        The approaches from first touch of the rigid bodies, in path order (length; rising for
        loading, falling for unloading, in any sequence; negative ones are apart, where the zone
        alone may pull).
    length, e_star, work_of_adhesion : float
        Side of the grid (length), effective modulus (pressure), work of adhesion ``w`` (energy
        per area).
    cohesive_stress : float
        ``σ₀`` (pressure); the range is ``δ_t = w/σ₀``. For a sphere of radius ``R``, Maugis'
        parameter is :func:`roughcontact.models.adhesion.maugis_parameter` of it and
        :func:`roughcontact.models.adhesion.maugis_cohesive_stress` its inverse.
    periodic : bool
        Periodic half-space instead of the free one (the approach then counted against the mean
        plane, :mod:`roughcontact.bem.contact`).
    edge_rule : {"energy", "metastable"}
        How a cell at the zone's outer edge is counted (module docstring, The edge).
    tol, maxiter : float, int
        Keyword-only: the constrained conjugate gradients' gap tolerance (relative to
        ``max(δ_t, max_S |h − d|)``) and iteration limit per solve.
    max_updates : int
        Most updates of the zone per approach.
    on_state : callable, optional
        Called as ``on_state(i, contact, zone)`` with the contact (``g = 0``) and the zone
        (in range, not in contact) as boolean ``n × n`` masks of each approach ``i``, e.g. for the
        stiffness of the contact (the masks are not kept).
    until : callable, optional
        Called as ``until(i, force, contact_cells)`` after each approach ``i``; the path ends after
        the first approach for which it returns true (the later *depths* are not solved), e.g.
        once the contact covers a given area.

    Returns
    -------
    CohesivePath
        Force, contact and zone per approach; the pull-off force is the most tensile force of the
        path (that of the unloading, after a loading).

    Raises
    ------
    ConvergenceError
        A solve does not reach *tol*, or the zone's updates cycle under every edge rule or do not
        settle within *max_updates*.
    ValueError
        Heights not square or not finite, a parameter not a finite number > 0, an unknown
        *edge_rule*.
    """
    solver = _CohesiveSolver(z, length=length, e_star=e_star, work_of_adhesion=work_of_adhesion,
                             cohesive_stress=cohesive_stress, periodic=periodic, edge_rule=edge_rule, tol=tol,
                             maxiter=maxiter, max_updates=max_updates)
    reach, lift = solver.empty()
    area = solver.spacing**2
    columns = {key: [] for key in ("depth", "force", "contact_cells", "contact_radius", "iterations",
                                   "zone_cells", "zone_radius", "fallback")}
    detach_depth, touched = math.nan, False
    for d in np.asarray(depths, dtype=float).reshape(-1):
        check_finite("depths", float(d))
        reach, lift, force, updates, fallback = solver.settle(float(d), reach, lift)
        cells = int(np.count_nonzero(lift.values > 0.0))
        zone_cells = int(np.count_nonzero(reach)) - cells
        if on_state is not None:
            contact = np.zeros(reach.shape, dtype=bool)
            contact[lift.box] = lift.values > 0.0
            on_state(len(columns["depth"]), contact, reach & ~contact)
        if cells and not touched:
            touched = True
        elif touched and not cells and math.isnan(detach_depth):
            detach_depth = float(d)
        for key, value in (("depth", float(d)), ("force", force), ("contact_cells", cells),
                           ("contact_radius", math.sqrt(cells * area / math.pi)), ("iterations", updates),
                           ("zone_cells", zone_cells),
                           ("zone_radius", math.sqrt((cells + zone_cells) * area / math.pi)),
                           ("fallback", fallback)):
            columns[key].append(value)
        if until is not None and until(len(columns["depth"]) - 1, force, cells):
            break
    arrays = {key: np.asarray(values) for key, values in columns.items()}
    pull_off = float(arrays["force"].min()) if arrays["force"].size else math.nan
    return CohesivePath(**arrays, pull_off_force=pull_off, detach_depth=detach_depth,
                        cohesive_stress=float(cohesive_stress), interaction_range=solver.range)
