"""Claims (a)-(h) of Pohrt & Popov (2013) on the rough sphere and ζ(H).

(a) eq. 16 describes the BEM ensemble; (b) the crossover force of eq. 17; (c) ζ(H) ≈ 1.7/(H+1)
(eq. 13); (d) the low-force slope 1/(H+1) and (e) the high-force slope 1/3 with the Hertz
prefactor; (f) below F_tr roughness lowers k against the smooth sphere (Conclusions); (g) the
scaling of F_tr with R and h_rms implied by eq. 17; (h) eq. 18's λ for H → 0. Beyond the
paraboloid (Conclusions): (a), (b), (d)-(f) per body of revolution and for 1 < H < 2. Rows
(a)-(f) of a combination off the paper's setting keep their measured values but say
``untested`` (:func:`~roughcontact.study.claims.registry.off_theory`); claims (g) and (h) leave
those combinations out. Claims (a)-(f) are estimated per sphere combination
(:class:`~roughcontact.study.claims.registry.Combination`, the registry loops), (c) also from
``zeta.csv`` and (g), (h) from the whole study.
"""
from __future__ import annotations

import math

import numpy as np

from ..analysis.statistics import (NO_PREDICTION, NOT_SWEPT, UNRESOLVED, interval, judge, log_log_slope, untested,
                                   verdict_bound)
from ..config import axes
from .registry import Claim, all_of, at_theory, describe, off_theory, register, row, with_crossover

__all__ = ["EQ16_TOLERANCE", "LAMBDA_EQ17", "LAMBDA_GT"]

#: claim (a): eq. 16 describes the ensemble if no resolved load deviates by more than this (relative k)
EQ16_TOLERANCE = 0.10
#: eq. 18: λ from eq. 17 as H → 0 with ζ(0) = 1.7, √6 · 1.7^(−3/2); and Greenwood–Tripp's value
LAMBDA_EQ17, LAMBDA_GT = math.sqrt(6.0) * 1.7**-1.5, 1.41


def _context(c):
    """What every claim (a)-(f) states about the sphere combination *c*: its axes, sweep, body and
    resolved loads; its crossover row ``r``."""
    study, r = c.study, c.crossover
    body = f" (body m = {c.axes['exponent']:g})" if c.axes.get("exponent", 2.0) != 2.0 else ""
    body += " (1 < H < 2)" if c.axes["hurst"] > 1 else ""
    return r, {
        "where": c.axes,
        "sweep": describe(c.axes, study.grid.length, study.grid.n, len(study.seeds)),
        "body": body,
        "loads": (f"{int(r['n_loads_resolved'])} resolved loads, F/(E*L^2) = "
                  f"{r['force_min_resolved']:.2g}...{r['force_max']:.2g}"),
    }


def _a(combination):
    """Two rows: eq. 16 at every resolved load, and on the fractal branch alone (the resolved loads
    below the measured F_tr, ``n_loads_below_Ftr``), each against the same tolerance."""
    r, c = _context(combination)
    get = r.get
    every = row(
        "a", f"eq. 16 (fitted zeta) within {EQ16_TOLERANCE:.0%} of the BEM ensemble at every resolved load"
             f"{c['body']}",
        get("eq16_max_rel_dev", math.nan), get("eq16_max_rel_dev_ci_low", math.nan),
        get("eq16_max_rel_dev_ci_high", math.nan), EQ16_TOLERANCE,
        verdict_bound(EQ16_TOLERANCE, get("eq16_max_rel_dev_ci_low", math.nan),
                      get("eq16_max_rel_dev_ci_high", math.nan), side="below"),
        sweep=c["sweep"], loads=c["loads"], note="measured: max |k/k_eq16 - 1|", **c["where"])
    below = int(get("n_loads_below_Ftr", 0) or 0)
    low, high = get("eq16_fractal_max_rel_dev_ci_low", math.nan), get("eq16_fractal_max_rel_dev_ci_high", math.nan)
    fractal = row(
        "a", f"eq. 16 (fitted zeta) within {EQ16_TOLERANCE:.0%} of the BEM ensemble on the fractal branch alone"
             f" (resolved loads below F_tr){c['body']}",
        get("eq16_fractal_max_rel_dev", math.nan), low, high, EQ16_TOLERANCE,
        verdict_bound(EQ16_TOLERANCE, low, high, side="below") if below else
        untested(UNRESOLVED, "no resolved load below the crossover force"),
        sweep=c["sweep"], loads=f"{below} resolved loads below F_tr",
        note=(f"measured: max |k/k_eq16 - 1| below F_tr; its mean k/k_eq16 - 1 (systematic) "
              f"{get('eq16_fractal_mean_rel_dev', math.nan):+.3g} [{get('eq16_fractal_mean_rel_dev_ci_low', math.nan):+.3g}, "
              f"{get('eq16_fractal_mean_rel_dev_ci_high', math.nan):+.3g}]"),
        **c["where"])
    return [every, fractal]


def _crossover_verdict(r, column: str, predicted: float) -> str:
    """The verdict text of ``crossover.csv``'s *column* (``verdict_estimate``, ``verdict_fit``) with
    its untested reason named: ``unresolved`` crossovers (the note says why), no prediction (no
    fitted ζ), no interval."""
    word = r[column]
    if word == "unresolved":
        return untested(UNRESOLVED, r["note"].split("unresolved: ")[-1].split(";")[0])
    if word.startswith("untested"):
        if not math.isfinite(predicted):
            return untested(NO_PREDICTION, f"no fitted zeta at H = {r['hurst']:g}")
        return judge(predicted, r["Ftr_ci_low"], r["Ftr_ci_high"])
    return word


def _b(combination):
    """Two rows: eq. 17 with ζ of eq. 13 (the paper's prediction) and with the ζ fitted on the flat
    runs (``zeta.csv``), each with its own verdict."""
    r, c = _context(combination)
    note = "measured: eq. 16 with free prefactors, F/(E*L^2)"
    return [row("b", f"crossover force F_tr of eq. 17 (zeta = 1.7/(H+1); Fig. 3: 8e-5 E* L^2){c['body']}",
                r["Ftr_measured"], r["Ftr_ci_low"], r["Ftr_ci_high"], r["Ftr_pred_estimate"],
                _crossover_verdict(r, "verdict_estimate", r["Ftr_pred_estimate"]),
                sweep=c["sweep"], loads=c["loads"], note=note, **c["where"]),
            row("b", f"crossover force F_tr of eq. 17 with the fitted zeta (zeta.csv){c['body']}",
                r["Ftr_measured"], r["Ftr_ci_low"], r["Ftr_ci_high"], r["Ftr_pred_fit"],
                _crossover_verdict(r, "verdict_fit", r["Ftr_pred_fit"]), sweep=c["sweep"], loads=c["loads"],
                note=f"{note}; paper value: eq. 17 with zeta = {r['zeta_fit']:.3g}", **c["where"])]


def _c(inputs):
    """ζ(H) of ``zeta.csv`` against eq. 13; untested where the ζ fit's runs lack the paper's setting
    of an optional axis (:func:`roughcontact.study.analysis.zeta.fit.off_paper`), as (a)-(f) there."""
    from ..analysis.zeta.fit import off_paper

    n, length = inputs.study.grid.n, inputs.study.grid.length
    off = off_theory(off_paper(inputs.groups, length), length) if inputs.groups else ""
    out = []
    for _, z in inputs.zeta.iterrows():
        out.append(row(
            "c", "zeta(H) ~ 1.7/(H+1) (eq. 13)", z["zeta"], z["zeta_ci_low"], z["zeta_ci_high"], z["zeta_estimate"],
            off or judge(z["zeta_estimate"], z["zeta_ci_low"], z["zeta_ci_high"]), hurst=z["hurst"],
            sweep=f"{z['source'].split(' (')[0]}, {int(z['n_seeds'])} seeds, n = {n}",
            loads=f"{int(z['n_points'])} loads, F/(E*L^2) = {z['force_min']:.2g}...{z['force_max']:.2g}"))
    return out


def _c_sphere(combination):
    r, c = _context(combination)
    if not ("zeta_sphere" in r and math.isfinite(r["zeta_sphere"])):
        return []
    return row(
        "c", "zeta(H) ~ 1.7/(H+1) from the sphere's fractal branch (eq. 16's B)", r["zeta_sphere"],
        r["zeta_sphere_ci_low"], r["zeta_sphere_ci_high"], r["zeta_estimate"],
        judge(r["zeta_estimate"], r["zeta_sphere_ci_low"], r["zeta_sphere_ci_high"]),
        sweep=c["sweep"], loads=c["loads"], **c["where"])


def _slope_rows(r, c, slopes, claim, name, text):
    """Two rows of one slope window: against the asymptote (eq. 11 or eq. 9) and against the slope
    eq. 16 itself has over the same loads (the fair test where the window is not asymptotic)."""
    window = "low" if name == "slope_low" else "high"
    ratio = slopes.low_max_ratio if window == "low" else slopes.high_min_ratio
    low, high = r[f"{name}_ci_low"], r[f"{name}_ci_high"]
    asymptote = r[f"{name}_verdict"]
    if asymptote.startswith("untested"):    # crossover.csv: too few loads in the window, or no interval
        asymptote = untested(UNRESOLVED, asymptote.partition(": ")[2] or "no interval")
    shared = {"sweep": c["sweep"], **c["where"],
              "loads": (f"{int(r[f'n_loads_{window}'])} resolved loads with F {'<=' if window == 'low' else '>='} "
                        f"{ratio:g} F_tr")}
    return [row(claim, text, r[name], low, high, r[f"{name}_theory"], asymptote,
                note="paper value: the asymptote", **shared),
            row(claim, f"{window}-force slope equals that of eq. 16 itself over the same loads", r[name], low, high,
                r[f"{name}_eq16"],
                asymptote if asymptote.startswith("untested") else judge(r[f"{name}_eq16"], low, high),
                note="paper value: d ln k/d ln F of eq. 16 (the zeta of claim (a)) over the row's loads", **shared)]


def _d(combination):
    r, c = _context(combination)
    return _slope_rows(r, c, combination.study.fit.slopes, "d", "slope_low",
                       "low-force slope d ln k/d ln F = 1/(H+1) (eq. 11)")


def _e(combination):
    r, c = _context(combination)
    out = _slope_rows(r, c, combination.study.fit.slopes, "e", "slope_high",
                      "high-force slope = 1/(m+1) (1/3: Hertz, eq. 9)")
    if "hertz_coefficient" in r and math.isfinite(r["hertz_coefficient"]):
        out.append(row(
            "e", f"body prefactor A of F = A k^(m+1) + B k^(H+1) equals eq. 7 (L/(6R): Hertz, eq. 10){c['body']}",
            r["hertz_coefficient"], r["hertz_coefficient_ci_low"], r["hertz_coefficient_ci_high"],
            r["hertz_coefficient_theory"],
            judge(r["hertz_coefficient_theory"], r["hertz_coefficient_ci_low"], r["hertz_coefficient_ci_high"]),
            sweep=c["sweep"], loads=c["loads"], note="normalised units F/(E*L^2), k/(E*L)", **c["where"]))
    return out


def _f(combination):
    r, c = _context(combination)
    get = r.get
    softer = (verdict_bound(1.0, get("k_over_hertz_below_Ftr_ci_low", math.nan),
                            get("k_over_hertz_below_Ftr_ci_high", math.nan), side="below")
              if r["n_loads_below_Ftr"] else untested(UNRESOLVED, "no resolved load below F_tr"))
    return row(
        "f", f"below F_tr roughness lowers k against the smooth body (Conclusions){c['body']}",
        get("k_over_hertz_below_Ftr", math.nan), get("k_over_hertz_below_Ftr_ci_low", math.nan),
        get("k_over_hertz_below_Ftr_ci_high", math.nan), 1.0, softer,
        sweep=c["sweep"], loads=f"{int(r['n_loads_below_Ftr'])} resolved loads below F_tr",
        note="measured: max over those loads of k/k_body(F) (eq. 9 for m = 2)", **c["where"])


def _paper_spheres(inputs):
    """The rows of ``crossover.csv`` at the paper's setting (:func:`roughcontact.study.config.axes.paper_mask`);
    claims (g) and (h) leave the others out."""
    cross = inputs.cross
    return cross[axes.paper_mask(cross, inputs.study.grid.length)] if len(cross) else cross


def _g(inputs):
    """F_tr ∝ R^((H+1)/(2−H)) h^(3/(2−H)) (eq. 17), exponents fitted per H."""
    cross, reps, study = _paper_spheres(inputs), inputs.replicates, inputs.study
    out = []
    level = study.fit.confidence
    for hurst in study.hurst:
        sub = cross[(cross["hurst"] == hurst) & np.isfinite(cross["Ftr_ci_low"])] if len(cross) else cross
        for axis, theory_value in (("radius", (hurst + 1) / (2 - hurst)), ("h_rms", 3 / (2 - hurst))):
            statement = f"F_tr ~ {'R' if axis == 'radius' else 'h_rms'}^{theory_value:.3g} (eq. 17: " + \
                        ("(H+1)/(2-H))" if axis == "radius" else "3/(2-H))")
            values = sorted(set(sub[axis])) if len(sub) else []
            if len(values) < 2:
                swept = len([r for r in study.radius if math.isfinite(r)] if axis == "radius" else study.h_rms)
                why = (untested(UNRESOLVED, f"{len(values)} {axis} value(s) with a resolved crossover") if swept >= 2
                       else untested(NOT_SWEPT, f"one {axis} value only"))
                out.append(row("g", statement, math.nan, math.nan, math.nan, theory_value, why, hurst=hurst))
                continue
            others = [a for a in ("radius", "h_rms") if a != axis and len(set(sub[a])) >= 2]
            log_axis = np.log(sub[axis].to_numpy(float))
            covariates = [np.log(sub[a].to_numpy(float)) for a in others]      # the other axis, where swept
            point = log_log_slope(log_axis, np.log(sub["Ftr_measured"].to_numpy(float)), covariates=covariates)
            boot = np.array([reps["Ftr_replicates"].sel(
                {a: r[a] for a in reps["Ftr_replicates"].dims if a != "replicate"}).values
                for _, r in sub.iterrows()])                                     # (combos, replicates)
            exponents = log_log_slope(log_axis, np.log(boot).T, covariates=covariates)   # (replicates,)
            lo, hi = interval(exponents, level)
            out.append(row("g", statement, float(point), lo, hi, theory_value, judge(theory_value, lo, hi),
                           hurst=hurst, sweep=f"{len(sub)} sphere combinations at H = {hurst:g}",
                           loads=f"{axis} = {', '.join(f'{v:g}' for v in values)}"))
    return out


def _h(inputs):
    """Eq. 18, F_tr/E* = λ h^(3/2) R^(1/2) for H → 0, from the smallest H swept (≤ 0.2)."""
    cross, study = _paper_spheres(inputs), inputs.study
    small = [h for h in study.hurst if h <= 0.2]
    statement = f"eq. 18: F_tr = lambda E* h^1.5 R^0.5 as H -> 0, lambda = {LAMBDA_EQ17:.2f} (eq. 17; GT: {LAMBDA_GT})"
    if not small or not len(cross):
        return [row("h", statement, math.nan, math.nan, math.nan, LAMBDA_EQ17,
                    untested(NOT_SWEPT, f"the sweep's smallest H is {min(study.hurst):g} (needs H <= 0.2 with "
                                        "spheres)"))]
    from ...models.greenwood_tripp import self_affine_sphere_curve
    from ..analysis.crossover import fit_eq16

    out = []
    hurst = min(small)
    L, n = study.grid.length, study.grid.n
    for _, r in cross[cross["hurst"] == hurst].iterrows():
        scale = r["h_rms"] ** 1.5 * r["radius"] ** 0.5 / L**2
        low, high = r["Ftr_ci_low"] / scale, r["Ftr_ci_high"] / scale
        where = {"hurst": hurst, "radius": r["radius"], "h_rms": r["h_rms"]}
        predicted = r["Ftr_pred_estimate"] / scale
        unresolved = untested(UNRESOLVED,
                              "unresolved crossover, " + str(r["note"]).split("unresolved: ")[-1].split(";")[0])

        def judged(value):
            return judge(value, low, high) if math.isfinite(low) else unresolved

        out.append(row(
            "h", statement, r["Ftr_measured"] / scale, low, high, predicted, judged(predicted),
            note=f"paper value: eq. 17 at H = {hurst:g} (tends to {LAMBDA_EQ17:.2f} as H -> 0; GT {LAMBDA_GT})",
            **where))
        # Greenwood-Tripp on the same spectrum and grid, its crossover by the same fit with H -> 0 (F ~ k)
        gt = self_affine_sphere_curve(hurst=hurst, h_rms=r["h_rms"], n=n, length=L, radius=r["radius"], e_star=1.0)
        lam = float(fit_eq16(gt.force / L**2, gt.stiffness / L, 0.0).crossover_force) / scale
        out.append(row(
            "h", f"eq. 18 with Greenwood-Tripp's lambda ({LAMBDA_GT} in the paper; the same fit of GT's curve on "
                 "these surfaces gives the paper value column)", r["Ftr_measured"] / scale, low, high, lam,
            judged(lam), note=f"GT mu = {gt.mu:.3g} (grows with the grid: no cutoff)", **where))
    return out


#: claims (a)-(f) are tested on every sphere combination with a crossover row; off the paper's setting
#: (:func:`~roughcontact.study.claims.registry.off_theory`) their rows say untested
_PER_SPHERE = all_of(with_crossover, at_theory)

register(Claim("a", "eq. 16 (fitted zeta) describes the BEM ensemble within 10 % at every resolved load",
               estimate=_a, applies=_PER_SPHERE))
register(Claim("b", "the crossover force F_tr of eq. 17", estimate=_b, applies=_PER_SPHERE))
register(Claim("c", "zeta(H) ~ 1.7/(H+1) (eq. 13), from flat runs and from the sphere's fractal branch", _c,
               estimate=_c_sphere, applies=_PER_SPHERE))
register(Claim("d", "the low-force slope d ln k/d ln F = 1/(H+1) (eq. 11)", estimate=_d, applies=_PER_SPHERE))
register(Claim("e", "the high-force slope 1/(m+1) and the body prefactor of eq. 7 (Hertz: eqs. 9-10)", estimate=_e,
               applies=_PER_SPHERE))
register(Claim("f", "below F_tr roughness lowers k against the smooth body (Conclusions)", estimate=_f,
               applies=_PER_SPHERE))
register(Claim("g", "F_tr ~ R^((H+1)/(2-H)) h_rms^(3/(2-H)) (eq. 17)", _g))
register(Claim("h", "eq. 18: F_tr = lambda E* h^1.5 R^0.5 as H -> 0", _h))
