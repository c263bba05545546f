"""Claims (n)–(q) on the adhesive runs (``work_of_adhesion`` > 0), from the pull-off table
``adhesion/pull_off.csv`` (:mod:`roughcontact.study.analysis.adhesion`).

(n) The smooth sphere's pull-off equals JKR's ``−(3/2)πwR`` (Johnson, Kendall & Roberts, Proc. R.
Soc. A 324 (1971) 301): rows with Johnson's parameter ``h_rms/δ_c ≤`` :data:`SMOOTH`. The detachment
criterion converges to JKR as the contact grows in cells, from above (+0.9 % at 80 cells); at the
row's resolution its pull-off is ``1 + e`` times JKR's, ``e`` its discretisation error there
(:func:`~roughcontact.study.analysis.adhesion.method_error`). Consistent when the ratio and its
interval lie within :data:`SAMPLING_ALLOWANCE` of ``1 + e`` (a two-sided test: a ratio below JKR's
differs too); untested (not swept) where the preload's contact is not wider than JKR's pull-off
radius (:data:`PRELOAD`), and untested (unresolved) where the run is below resolution:
``pull_off.csv``'s ``resolved`` is false, ``e`` above
:data:`~roughcontact.study.analysis.adhesion.RESOLVED_ERROR` (3 %, JKR's pull-off radius below
about 46 cells), where the method's own error is as large as the effects tested (the reason still
says how far the pull-off lies from ``1 + e``).

Claims (o) and (p) leave out the rows below resolution and say so in ``sweep`` (as they leave out
the preload-capped ones); where too few rows remain because of them they are untested
(unresolved).

(o) The rough pull-off collapses on Johnson's parameter ``h_rms/δ_c`` (his sphere form of Fuller &
Tabor's θ, Proc. R. Soc. A 345 (1975) 327): per H, the curves of the (R, w) pairs against
``h_rms/δ_c``, each pull-off ratio taken over that of the pair's own smooth sphere (which removes
the detachment criterion's discretisation error, different at each w), without the combinations
whose preload is below :data:`PRELOAD` JKR pull-off radii (as in (n)), compared where their
ranges overlap with no form assumed (:func:`_collapse_residual`); measured: the difference of two
curves where they lie farthest apart in units of the sum of their half-intervals, its interval
that difference plus and minus the sum (conservative: it holds 0 exactly where the intervals
overlap); consistent when it holds 0 (one curve within the intervals everywhere). Needs two or
more (R, w) pairs at one H.

(p) Li, Pohrt & Popov (Front. Mech. Eng. 5:7 (2019), doi:10.3389/fmech.2019.00007) find that
Johnson's parameter governs the adhesion of regular waviness, but that the adhesive strength of
random roughness needs a new parameter, which they identify numerically. Their parameter's
definition is not in any source this project has (only the abstract), so it is not implemented;
what is tested is the half of their finding that needs none: Johnson's ``h_rms/δ_c`` alone does
*not* collapse the random-roughness pull-off: the comparison of (o) between the curves of
different H; consistent with Li et al. when the interval of the difference excludes 0 (no one
curve of ``h_rms/δ_c`` for all H), differs when it holds 0. Needs two or more H with four
combinations each.

(q) Pastewka & Robbins' stickiness (PNAS 111 (2014) 3298) on the stickiness runs
(:mod:`roughcontact.study.runs.stickiness`): nominally flat surfaces pressed by displacement into a
half-space with a Maugis–Dugdale interaction of range ``Δr`` and work ``w`` are sticky — the
loading slope ``F/A`` at the contact area ``A*`` is negative — when
``N = (h′E*Δr/(2w))(h′²/(h″Δr))^(2/3) < 1``. One row per (H, N): the mean slope over seeds with its
interval; consistent when the interval lies wholly on the predicted side of 0 (below for
``N < 1``), differs when wholly on the other, untested when it contains 0, at ``N = 1`` itself (no
prediction) or outside the criterion's range ``Δr/g₀ <``
:data:`~roughcontact.models.rough_adhesion.STICKINESS_RANGE_LIMIT`. And one row per H: the
measured threshold, the ``N`` where the mean slope changes sign (``stickiness.csv``'s
``threshold``), consistent when its interval holds 1.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ...models.rough_adhesion import STICKINESS_RANGE_LIMIT
from ..analysis.adhesion import ERROR_CELLS, METHOD_ERRORS, RESOLVED_CELLS, RESOLVED_ERROR, method_error, resolved
from ..analysis.statistics import (NO_PREDICTION, NOT_SWEPT, OUT_OF_RANGE, UNRESOLVED, judge, split_verdict, untested,
                                   verdict_bound)
from .registry import Claim, register, row

__all__ = ["SMOOTH", "SAMPLING_ALLOWANCE", "PRELOAD", "method_error"]

#: a sphere counts as smooth when its roughness is this small against JKR's pull-off approach δ_c
SMOOTH = 0.05
#: claim (n)'s tolerance around the method's own pull-off: the pull-off's sampling along the retract
#: path (±1 %) and the residual scatter of nearly smooth seeds
SAMPLING_ALLOWANCE = 0.03
#: the preload's contact radius over JKR's pull-off radius that claim (n) needs (the retract path
#: must start from a contact wider than the one at pull-off)
PRELOAD = 1.1
def _spheres(table):
    return table[table["kind"] == "sphere"] if len(table) else table


def _unresolved(r) -> str:
    """The reason of an adhesive row below resolution (``resolved`` false,
    :mod:`roughcontact.study.analysis.adhesion`)."""
    error = method_error(r["jkr_radius_cells"])
    size = (f"where the method's own pull-off error is {error:+.1%}, more than {RESOLVED_ERROR:.0%}"
            if math.isfinite(error) else
            f"below the {ERROR_CELLS[0]:g} cells where the method's own pull-off error was measured "
            f"({METHOD_ERRORS[0]:+.1%} there, more than {RESOLVED_ERROR:.0%})")
    return (f"JKR's pull-off radius is {r['jkr_radius_cells']:.1f} cells, {size} (resolved from "
            f"{RESOLVED_CELLS:.0f} cells: refine grid.n)")


def _n(inputs):
    statement = "the smooth sphere's pull-off equals JKR's -(3/2) pi w R"
    table = _spheres(inputs.adhesion)
    smooth = table[table["johnson_parameter"] <= SMOOTH] if len(table) else table
    if not len(smooth):
        return [row("n", statement, math.nan, math.nan, math.nan, 1.0,
                    untested(NOT_SWEPT, f"no adhesive sphere with h_rms/delta_c <= {SMOOTH:g}"))]
    out = []
    for (_, r), fine in zip(smooth.iterrows(), resolved(smooth)):
        where = {a: r[a] for a in ("hurst", "radius", "h_rms", "work_of_adhesion")}
        error = method_error(r["jkr_radius_cells"])
        sweep = f"h_rms/delta_c = {r['johnson_parameter']:.3g}, {int(r['n_seeds'])} seeds"
        measured = (r["pull_off_ratio"], r["pull_off_ratio_ci_low"], r["pull_off_ratio_ci_high"])
        if not r["preload_radius_ratio"] >= PRELOAD:
            out.append(row("n", statement, *measured, 1.0,
                           untested(NOT_SWEPT, f"the preload's contact radius is {r['preload_radius_ratio']:.2f} "
                                    f"of JKR's pull-off radius (needs >= {PRELOAD:g}: raise forces.sphere.to)"),
                           sweep=sweep, **where))
            continue
        expected = 1.0 + error
        worst = max((abs(v - expected) for v in measured if math.isfinite(v)), default=math.nan)
        if not fine:
            # below resolution the method's own error is as large as the effects: no verdict on JKR
            away = (f"; the pull-off is {worst:.1%} from the method's own {expected:.3f} x JKR there"
                    if math.isfinite(worst) else "")
            out.append(row("n", statement, *measured, 1.0, untested(UNRESOLVED, _unresolved(r) + away),
                           sweep=sweep, **where))
            continue
        verdict = "consistent" if worst <= SAMPLING_ALLOWANCE else "differs"
        out.append(row("n", statement, *measured,
                       1.0, f"{verdict}: {worst:.1%} from the method's own {expected:.3f} x JKR at "
                       f"{r['jkr_radius_cells']:.1f} cells ({'within' if verdict == 'consistent' else 'more than'} "
                       f"{SAMPLING_ALLOWANCE:.0%})", sweep=sweep, **where))
    return out


def _preloaded(rows):
    """*rows* whose preload contact is at least :data:`PRELOAD` times JKR's pull-off radius (a pull-off
    capped by the preload measures the preload, not the adhesion) and how many were left out."""
    keep = rows["preload_radius_ratio"].to_numpy(float) >= PRELOAD
    return rows[keep], int(np.count_nonzero(~keep))


def _usable(rows):
    """The rows of *rows* that (o) and (p) compare: a finite pull-off ratio, resolved (the method's
    own error at most :data:`~roughcontact.study.analysis.adhesion.RESOLVED_ERROR`, the rows below
    resolution are left out and counted) and preloaded (:func:`_preloaded`); with the text of what
    was left out and the number of rows below resolution."""
    rows = rows[np.isfinite(rows["pull_off_ratio"].to_numpy(float))] if len(rows) else rows
    fine = resolved(rows)
    coarse = int(np.count_nonzero(~fine))
    rows, capped = _preloaded(rows[fine]) if len(rows) else (rows, 0)
    left = (f"{capped} left out: preload below {PRELOAD:g} JKR radii; {coarse} left out: below resolution, the "
            f"method's own pull-off error above {RESOLVED_ERROR:.0%}")
    return rows, left, coarse


def _short(coarse: int, reason: str) -> str:
    """The untested verdict of a collapse without enough rows: :data:`UNRESOLVED` where rows below
    resolution were left out (*coarse*), else :data:`NOT_SWEPT`."""
    if coarse:
        return untested(UNRESOLVED, f"{reason}, after leaving out {coarse} combination(s) below resolution "
                                    f"(the method's own pull-off error above {RESOLVED_ERROR:.0%}: refine grid.n)")
    return untested(NOT_SWEPT, reason)


def _series(rows, by) -> list:
    """The rough rows of *rows* split by the columns *by*: per series the sorted ``ln(h_rms/δ_c)``,
    the pull-off ratios over the series' own smooth sphere's (the rows with ``h_rms/δ_c ≤``
    :data:`SMOOTH`; as they are without one), and their half-intervals (at least 2 % of the ratio),
    with the series' key."""
    out = []
    for key, group in rows.groupby(list(by)):
        smooth = group[group["johnson_parameter"] <= SMOOTH]
        scale = float(smooth["pull_off_ratio"].mean()) if len(smooth) else 1.0
        rough = group[group["johnson_parameter"] > SMOOTH].sort_values("johnson_parameter")
        y = rough["pull_off_ratio"].to_numpy(float) / scale
        half = 0.5 * (rough["pull_off_ratio_ci_high"] - rough["pull_off_ratio_ci_low"]).to_numpy(float) / scale
        half = np.maximum(np.nan_to_num(half, nan=0.0), 0.02 * np.maximum(np.abs(y), 0.05))
        out.append((key if isinstance(key, tuple) else (key,), np.log(rough["johnson_parameter"].to_numpy(float)),
                    y, half))
    return out


@dataclasses.dataclass(frozen=True)
class Collapse:
    """How far series of pull-off ratios lie from one curve of ``h_rms/δ_c`` (:func:`_collapse_residual`).

    Attributes
    ----------
    worst : float
        The largest distance between two series over the sum of their half-intervals there (at most
        1: the intervals overlap everywhere).
    difference, bound : float
        At that point: the signed difference of the two pull-off ratios and the sum of their
        half-intervals, so that ``difference ± bound`` is the (conservative) interval of the
        difference; it holds 0 exactly when ``worst ≤ 1``.
    compared : int
        Points compared (0: the series' ranges do not overlap).
    """

    worst: float
    difference: float
    bound: float
    compared: int


def _collapse_residual(rows, by, *, across: str | None = None) -> Collapse:
    """Whether the series of *rows* (split by *by*, :func:`_series`) lie on one curve of
    ``h_rms/δ_c``, with no form assumed for it: each point of one series inside the parameter range
    of another is compared with that series interpolated linearly in ``ln(h_rms/δ_c)`` (ratio and
    half-interval alike); the residual is the distance over the sum of the two half-intervals.
    *across*: compare only series that differ in that column."""
    series = _series(rows, by)
    position = list(by).index(across) if across is not None else None
    out = Collapse(0.0, 0.0, math.nan, 0)
    for key_a, x_a, y_a, half_a in series:
        for key_b, x_b, y_b, half_b in series:
            if key_a == key_b or x_a.size < 2 or (position is not None and key_a[position] == key_b[position]):
                continue
            inside = (x_b >= x_a[0]) & (x_b <= x_a[-1])
            if not inside.any():
                continue
            difference = y_b[inside] - np.interp(x_b[inside], x_a, y_a)
            bound = half_b[inside] + np.interp(x_b[inside], x_a, half_a)
            k = int(np.argmax(np.abs(difference) / bound))
            worst = float(abs(difference[k]) / bound[k])
            if not out.compared or worst > out.worst:
                out = Collapse(worst, float(difference[k]), float(bound[k]), out.compared)
            out = dataclasses.replace(out, compared=out.compared + int(inside.sum()))
    return out


#: the loads column of claims (o) and (p)
_COLLAPSE_LOADS = ("the largest difference of two curves' pull-off ratios (each over its smooth sphere's), its "
                   "interval the sum of their half-intervals (it holds 0 where the intervals overlap)")


def _o(inputs):
    statement = "the rough pull-off / JKR's collapses on Johnson's h_rms/delta_c (Fuller & Tabor)"
    table = _spheres(inputs.adhesion)
    if not len(table):
        return [row("o", statement, math.nan, math.nan, math.nan, 1.0, untested(NOT_SWEPT, "no adhesive sphere"))]
    out = []
    for hurst, rows in table.groupby("hurst"):
        rows, left, coarse = _usable(rows)
        pairs = {(r["radius"], r["work_of_adhesion"]) for _, r in rows.iterrows()}
        sweep = f"H = {hurst:g}: {len(rows)} combinations ({left}), {len(pairs)} (R, w) pairs"
        if len(pairs) < 2 or len(rows) < 4:
            out.append(row("o", statement, math.nan, math.nan, math.nan, 1.0,
                           _short(coarse, f"{len(pairs)} (R, w) pair(s) and {len(rows)} combination(s) at "
                                  f"H = {hurst:g} (a collapse needs two pairs and four combinations)"),
                           hurst=hurst, sweep=sweep))
            continue
        collapse = _collapse_residual(rows, ("radius", "work_of_adhesion"))
        if not collapse.compared:
            out.append(row("o", statement, math.nan, math.nan, math.nan, 1.0,
                           _short(coarse, "the (R, w) pairs' ranges of h_rms/delta_c do not overlap"), hurst=hurst,
                           sweep=sweep))
            continue
        sweep += f", {collapse.compared} points compared"
        verdict = "consistent" if collapse.worst <= 1.0 else "differs"
        low, high = collapse.difference - collapse.bound, collapse.difference + collapse.bound
        out.append(row("o", statement, collapse.difference, low, high, 0.0,
                       f"{verdict}: the largest distance between the pairs' curves is {collapse.worst:.2f} times the "
                       "sum of their half-intervals",
                       hurst=hurst, sweep=sweep, loads=_COLLAPSE_LOADS))
    return out


def _p(inputs):
    statement = ("Li, Pohrt & Popov (2019): Johnson's h_rms/delta_c alone does not set the random-roughness "
                 "pull-off (their own parameter is not implemented)")
    table = _spheres(inputs.adhesion)
    rows, left, coarse = _usable(table)
    counts = rows.groupby("hurst").size() if len(rows) else {}
    enough = [h for h, count in dict(counts).items() if count >= 4]
    if len(enough) < 2:
        return [row("p", statement, math.nan, math.nan, math.nan, 1.0,
                    _short(coarse, f"{len(enough)} H with four or more combinations (one curve across H needs two)"),
                    sweep=f"{len(rows)} combinations ({left})" if len(table) else "")]
    rows = rows[rows["hurst"].isin(enough)]
    collapse = _collapse_residual(rows, ("hurst", "radius", "work_of_adhesion"), across="hurst")
    sweep = (f"H = {', '.join(f'{h:g}' for h in sorted(enough))}: {len(rows)} combinations ({left}), "
             f"{collapse.compared} points compared")
    if not collapse.compared:
        return [row("p", statement, math.nan, math.nan, math.nan, 1.0,
                    _short(coarse, "the H's ranges of h_rms/delta_c do not overlap"), sweep=sweep)]
    worst = collapse.worst
    verdict = (f"consistent: no one curve of h_rms/delta_c through every H (the H's curves {worst:.2f} times the "
               "sum of their half-intervals apart)" if worst > 1.0 else
               f"differs: the H's curves of h_rms/delta_c agree within their intervals ({worst:.2f})")
    return [row("p", statement, collapse.difference, collapse.difference - collapse.bound,
                collapse.difference + collapse.bound, 0.0, verdict, sweep=sweep, loads=_COLLAPSE_LOADS)]


def _q(inputs):
    statement = "flat surfaces are sticky (F < 0 at the area A*) when Pastewka & Robbins' number N < 1"
    table = inputs.stickiness
    if table is None or not len(table):
        return [row("q", statement, math.nan, math.nan, math.nan, 1.0,
                    untested(NOT_SWEPT, "no stickiness runs (the config's stickiness section)"))]
    out = []
    for hurst, rows in table.groupby("hurst"):
        first = rows.iloc[0]
        sweep = (f"flat, periodic, n = {int(first['n'])}, {int(first['n_seeds'])} seeds, h' = {first['rms_slope']:g}, "
                 f"dr/g0 = {first['range_ratio']:.3g}")
        valid = bool(first["range_ratio"] < STICKINESS_RANGE_LIMIT)
        outside = untested(OUT_OF_RANGE, f"dr/g0 = {first['range_ratio']:.2g} >= {STICKINESS_RANGE_LIMIT:g} (outside "
                                         "the criterion's range)")
        for _, r in rows.iterrows():
            low, high = r["loading_slope_ci_low"], r["loading_slope_ci_high"]
            measured = (f"F/A = {r['loading_slope']:.3g} h'E* [{low:.3g}, {high:.3g}], {r['sticky_fraction']:.0%} of "
                        "the seeds sticky")
            if not valid:
                verdict = outside
            elif r["number"] == 1.0:
                verdict = untested(NO_PREDICTION, f"N = 1 is the criterion's threshold itself ({measured})")
            else:
                predicted = r["number"] < 1.0
                side = "below" if predicted else "above"
                word, because, why = split_verdict(verdict_bound(0.0, low, high, side=side))
                text = f"predicted {'sticky' if predicted else 'not sticky'}; {measured}"
                verdict = untested(because, f"{text} ({why})") if because else f"{word}: {text}"
            out.append(row("q", statement, r["loading_slope"], low, high, 0.0, verdict, sweep=sweep,
                           loads="F/A at A* in units of h'E*; the paper's value: its sign changes at N = 1",
                           note=f"N = {r['number']:g}", hurst=hurst))
        low, high = first["threshold_ci_low"], first["threshold_ci_high"]
        if not valid:
            verdict = outside
        elif not math.isfinite(first["threshold"]):
            verdict = untested(NOT_SWEPT, "the mean slope does not change sign from negative to positive across the "
                                          "sweep's N")
        else:
            crossing = f"the slope changes sign at N = {first['threshold']:.3g} [{low:.3g}, {high:.3g}]"
            verdict = (f"{judge(1.0, low, high)}: {crossing}" if math.isfinite(low) and math.isfinite(high) else
                       untested(UNRESOLVED, f"{crossing} (no interval: the replicates' slopes rarely change sign)"))
        out.append(row("q", "Pastewka & Robbins: flat surfaces turn sticky at N = 1", first["threshold"], low, high,
                       1.0, verdict, sweep=sweep, loads="the number N where the mean F/A at A* changes sign",
                       note="threshold", hurst=hurst))
    return out


register(Claim("n", "the smooth sphere's pull-off equals JKR's", _n, needs=("adhesion",)))
register(Claim("o", "the rough pull-off collapses on Johnson's h_rms/delta_c", _o, needs=("adhesion",)))
register(Claim("p", "Li, Pohrt & Popov: Johnson's parameter alone does not collapse random roughness", _p,
               needs=("adhesion",)))
register(Claim("q", "Pastewka & Robbins' stickiness criterion on flat surfaces", _q, needs=("stickiness",)))
