"""Claims (u), (v) and (w) on the real contact area of the rough sphere, at the loads whose area is resolved.

(u) Between the one-asperity regime and the crossover to Hertz the area grows linearly with the force,
``A = κ F/(E* h′_rms)`` with κ ≈ 2 (Hyun, Pei, Molinari & Robbins, Phys. Rev. E 70, 026117 (2004),
doi:10.1103/PhysRevE.70.026117; Pastewka & Robbins, Appl. Phys. Lett. 108, 221601 (2016),
doi:10.1063/1.4950802), ``h′_rms = √⟨|∇h|²⟩`` of the grid's spectrum
(:func:`roughcontact.models.area.rms_slope`): two rows, κ within :data:`KAPPA_TOLERANCE` of 2 and the
exponent of ``A ∝ F^a`` equal to 1, over the loads ``F_1 ≤ F ≤`` :data:`LINEAR_MAX_RATIO` ``F_A``.
(v) Above the crossover ``A`` approaches Hertz's ``π a²``, ``a = (3FR/(4E*))^(1/3)``: ``A/(π a²)``
within :data:`HERTZ_TOLERANCE` of 1 at the loads ``F ≥`` :data:`HERTZ_MIN_RATIO` ``F_A``. (w) At the
smallest loads the contact is the first summit's (Pastewka & Robbins 2016): ``A ∝ F^(2/3)`` at the
loads ``F ≤`` :data:`SINGLE_MAX_RATIO` ``F_1``.

The crossover ``F_A`` is where the linear law (κ = 2) meets Hertz's area
(:func:`roughcontact.models.area.laws.area_crossover_force`). ``F_1``, the end of the one-asperity
regime, is where one summit's Hertz area ``π (3F R_s/(4E*))^(2/3)`` meets the linear law's (κ = 2):
``F_1 = (π/2)³ (3R_s/4)² E* h′_rms³ = F_A (R_s/R)²``
(:func:`roughcontact.models.area.laws.single_asperity_force`), with the summit radius ``R_s =
c_s/h″_rms`` of :mod:`roughcontact.models.area.three_regime` (``c_s`` = 1.34, fitted on its
calibration sweep before any cutoff study; ``h″_rms`` the grid spectrum's rms Laplacian). The bound
is that closed form with those constants as they are, not moved toward where the measured κ reaches 2.
Pastewka & Robbins' own words on the regime's end were not at hand offline (only their abstract):
the criterion is this package's (``docs/guide/area.md``).

Only area-resolved loads count (:func:`roughcontact.study.analysis.area.area_context`: the
ensemble-mean contact cells a load needs at the grid's cells per shortest wavelength, measured by
``benchmarks/area_grid_study.py``); with too few of them a row is ``untested: unresolved`` and says
how many cells the area needs, never a verdict from unresolved loads; an empty window (``F_1 ≥ 0.1
F_A``, a sphere too small for a linear regime) is ``untested: not swept``. Spheres only (paraboloid,
elastic, non-adhesive); an off-paper roll-off or cutoff is allowed: the laws are written for any
spectrum through ``h′_rms`` and ``h″_rms``.
"""
from __future__ import annotations

import math

import numpy as np

from ...models.area.laws import SIMULATION_KAPPA, hertz_area, persson_fraction_at
from ...models.area.three_regime import SUMMIT
from ..analysis.area import AREA_TOLERANCE, area_context
from ..analysis.statistics import (NOT_SWEPT, OFF_PAPER, UNRESOLVED, bootstrap_indices, interval, judge,
                                   log_log_slope, untested, verdict_bound)
from .registry import Claim, describe, register, row

__all__ = ["KAPPA_TOLERANCE", "LINEAR_MAX_RATIO", "HERTZ_MIN_RATIO", "HERTZ_TOLERANCE", "SINGLE_MAX_RATIO",
           "SINGLE_EXPONENT"]

#: claim (u): κ within this fraction of 2 (the grid study's tolerance on the area; Persson's √(8/π)
#: lies 20 % below 2, outside it)
KAPPA_TOLERANCE = AREA_TOLERANCE
#: claim (u) uses the loads F <= this × F_A: there Persson's area under Hertz's pressure is within
#: 5 % of its linear limit (persson_area_fraction at β = 1.06 × 0.1^(1/3): 0.954 of 4β/(3√π))
LINEAR_MAX_RATIO = 0.1
#: claim (v) uses the loads F >= this × F_A: there Persson's area is within 10 % of π a²
#: (persson_area_fraction(1.06 × 10^(1/3)) = 0.905)
HERTZ_MIN_RATIO = 10.0
#: claim (v): A/(π a²) within this of 1
HERTZ_TOLERANCE = AREA_TOLERANCE
#: claim (w) uses the loads F <= this × F_1: there one summit's Hertz area is 10^(1/3) = 2.15 times the
#: linear law's (the mirror of (u)'s 0.1 F_A below Hertz)
SINGLE_MAX_RATIO = 0.1
#: claim (w): the exponent of one summit's Hertz area, A ∝ F^(2/3)
SINGLE_EXPONENT = 2.0 / 3.0

U_STATEMENT = ("between the one-asperity regime and the crossover A = kappa F/(E* h'_rms) with kappa ~ 2 "
               "(Hyun et al. 2004; Pastewka & Robbins 2016)")
V_STATEMENT = "above the crossover A approaches Hertz's pi a^2 (Pastewka & Robbins 2016)"
W_STATEMENT = "at the smallest loads one summit carries the load, A ~ F^(2/3) (Pastewka & Robbins 2016)"


def _applies(combination):
    """Spheres only; off the paraboloid, plastic or adhesive combinations keep no row (the laws are for
    an elastic, adhesion-free paraboloid)."""
    if combination.kind != "sphere":
        return None
    a = combination.axes
    if a.get("exponent", 2.0) != 2.0:
        return untested(OFF_PAPER, f"the area laws are for the paraboloid; body m = {a['exponent']:g}")
    if math.isfinite(a.get("hardness", math.inf)) or a.get("work_of_adhesion", 0.0) > 0:
        return untested(OFF_PAPER, "the area laws are elastic and adhesion-free")
    return ""


def _window(combination, low, high):
    """The context, the window's resolved load mask, the sweep text and the window's loads in words;
    *low* and *high* map the :class:`~roughcontact.study.analysis.area.AreaContext` to the window's
    bounds (force units)."""
    c = combination
    context = area_context(c.axes, c.data, c.study)
    force = c.data["force"].values
    low, high = low(context), high(context)
    in_window = (force >= low) & (force <= high)
    use = in_window & context.resolved
    study = c.study
    sweep = describe(c.axes, study.grid.length, study.grid.n, len(study.seeds))
    norm = study.e_star * study.grid.length**2
    loads = (f"{int(use.sum())} of {int(in_window.sum())} loads in the window area-resolved (>= "
             f"{context.min_cells:g} contact cells at {context.wavelength_cells:g} cells per shortest wavelength); "
             f"F_A = {context.crossover_force / norm:.3g} E* L^2, F_1 = {context.summit_force / norm:.3g} E* L^2 "
             f"(R_s = {SUMMIT:g}/h''_rms = {context.summit_radius:.3g}), h'_rms = {context.rms_slope:.3g}")
    return context, in_window, use, sweep, loads


#: how F_1 is computed, for the rows' notes
_F1_TEXT = (f"F_1 = (pi/2)^3 (3 R_s/4)^2 E* h'_rms^3, where one summit's Hertz area pi (3 F R_s/(4E*))^(2/3) equals "
            f"2F/(E* h'_rms); R_s = {SUMMIT:g}/h''_rms (three_regime's summit radius)")


def _untested_rows(letter, statements, paper_values, in_window, use, context, sweep, loads, need, where,
                   empty=""):
    if empty:
        why = untested(NOT_SWEPT, empty)
    elif not in_window.any():
        why = untested(NOT_SWEPT, "no load of the sweep in the window")
    else:
        why = untested(UNRESOLVED, f"under-resolved: {int(use.sum())} area-resolved load(s), {need} needed; "
                                   + context.why_unresolved)
    return [row(letter, s, math.nan, math.nan, math.nan, p, why, sweep=sweep, loads=loads, **where)
            for s, p in zip(statements, paper_values)]


def _u(combination):
    """κ = A E* h′/F averaged over the window's area-resolved loads, and the log-log slope of A(F)."""
    context, in_window, use, sweep, loads = _window(combination, lambda c: c.summit_force,
                                                    lambda c: LINEAR_MAX_RATIO * c.crossover_force)
    statements = (f"kappa = A E* h'_rms/F within {KAPPA_TOLERANCE:.0%} of {SIMULATION_KAPPA:g} at F_1 <= F <= "
                  f"{LINEAR_MAX_RATIO:g} F_A", f"A ~ F^a with a = 1 at F_1 <= F <= {LINEAR_MAX_RATIO:g} F_A")
    empty = ""
    if not context.summit_force < LINEAR_MAX_RATIO * context.crossover_force:
        empty = (f"the window F_1 <= F <= {LINEAR_MAX_RATIO:g} F_A is empty: F_1 >= {LINEAR_MAX_RATIO:g} F_A "
                 f"(R/R_s <= {1 / math.sqrt(LINEAR_MAX_RATIO):.3g}: no linear regime); {_F1_TEXT}")
    if empty or use.sum() < 2:
        return _untested_rows("u", statements, (SIMULATION_KAPPA, 1.0), in_window, use, context, sweep, loads,
                              2, combination.axes, empty)
    data, study = combination.data, combination.study
    force = data["force"].values[use]
    area = data["contact_area"].values[:, use]                            # (seed, load), length²
    scale = study.e_star * context.rms_slope / force
    boot = area[bootstrap_indices(area.shape[0], study.fit.bootstrap)].mean(1)   # (resample, load)
    kappa = float((area.mean(0) * scale).mean())
    kappa_boot = (boot * scale).mean(-1)
    low, high = interval(kappa_boot, study.fit.confidence)
    dev_low, dev_high = interval(np.abs(kappa_boot / SIMULATION_KAPPA - 1), study.fit.confidence)
    slope = float(log_log_slope(np.log(force), np.log(area.mean(0))))
    s_low, s_high = interval(np.asarray(log_log_slope(np.log(force), np.log(boot))), study.fit.confidence)
    return [row("u", statements[0], kappa, low, high, SIMULATION_KAPPA,
                verdict_bound(KAPPA_TOLERANCE, dev_low, dev_high, side="below"), sweep=sweep, loads=loads,
                note=(f"measured: mean over the loads of A E* h'_rms/F (ensemble-mean A); verdict on |kappa/2 - 1| "
                      f"in [{dev_low:.3g}, {dev_high:.3g}] against {KAPPA_TOLERANCE:g}; Persson's theory: "
                      f"{math.sqrt(8 / math.pi):.3f}; {_F1_TEXT}"), **combination.axes),
            row("u", statements[1], slope, s_low, s_high, 1.0, judge(1.0, s_low, s_high), sweep=sweep, loads=loads,
                note=f"measured: least-squares slope of ln A against ln F over the loads; {_F1_TEXT}",
                **combination.axes)]


def _v(combination):
    """A/(π a²) at the window's area-resolved loads: the largest deviation from 1."""
    context, in_window, use, sweep, loads = _window(combination, lambda c: HERTZ_MIN_RATIO * c.crossover_force,
                                                    lambda c: math.inf)
    statement = f"A/(pi a^2) within {HERTZ_TOLERANCE:.0%} of 1 at F >= {HERTZ_MIN_RATIO:g} F_A"
    if use.sum() < 1:
        return _untested_rows("v", (statement,), (1.0,), in_window, use, context, sweep, loads, 1,
                              combination.axes)
    data, study, s = combination.data, combination.study, context.surface
    hertz = hertz_area(data["force"].values[use], radius=s.radius, e_star=s.e_star)
    area = data["contact_area"].values[:, use]
    boot = area[bootstrap_indices(area.shape[0], study.fit.bootstrap)].mean(1) / hertz
    ratio = area.mean(0) / hertz
    worst = int(np.argmax(np.abs(ratio - 1)))
    low, high = interval(boot[:, worst], study.fit.confidence)
    dev_low, dev_high = interval(np.abs(boot - 1).max(-1), study.fit.confidence)
    return row("v", statement, float(ratio[worst]), low, high, 1.0,
               verdict_bound(HERTZ_TOLERANCE, dev_low, dev_high, side="below"), sweep=sweep, loads=loads,
               note=(f"measured: A/(pi a^2) at the load farthest from 1; verdict on max |A/(pi a^2) - 1| in "
                     f"[{dev_low:.3g}, {dev_high:.3g}]; Persson's theory at {HERTZ_MIN_RATIO:g} F_A: "
                     f"{float(persson_fraction_at(HERTZ_MIN_RATIO)):.3f}"),
               **combination.axes)


def _w(combination):
    """The log-log slope of A(F) at the window's area-resolved loads, against 2/3."""
    context, in_window, use, sweep, loads = _window(combination, lambda c: 0.0,
                                                    lambda c: SINGLE_MAX_RATIO * c.summit_force)
    statement = f"A ~ F^a with a = 2/3 at F <= {SINGLE_MAX_RATIO:g} F_1"
    if use.sum() < 2:
        return _untested_rows("w", (statement,), (SINGLE_EXPONENT,), in_window, use, context, sweep, loads, 2,
                              combination.axes)
    data, study = combination.data, combination.study
    force = np.log(data["force"].values[use])
    area = data["contact_area"].values[:, use]
    boot = area[bootstrap_indices(area.shape[0], study.fit.bootstrap)].mean(1)
    slope = float(log_log_slope(force, np.log(area.mean(0))))
    low, high = interval(np.asarray(log_log_slope(force, np.log(boot))), study.fit.confidence)
    return row("w", statement, slope, low, high, SINGLE_EXPONENT, judge(SINGLE_EXPONENT, low, high), sweep=sweep,
               loads=loads, note=f"measured: least-squares slope of ln A against ln F over the loads; {_F1_TEXT}",
               **combination.axes)


register(Claim("u", U_STATEMENT, estimate=_u, applies=_applies))
register(Claim("v", V_STATEMENT, estimate=_v, applies=_applies))
register(Claim("w", W_STATEMENT, estimate=_w, applies=_applies))
