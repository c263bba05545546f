"""The paper's claims as a table (``claims.csv``): one row per quantitative claim
and per combination it is tested on, with the measured value, its 95 %
interval, the paper's value, the verdict (:mod:`.verdicts`) and the sweep and
loads it rests on. Rows (a)–(f) of a combination with a cutoff, a roll-off or a
hardness keep their measured values but say ``untested``: the paper's
equations are for an elastic, purely self-affine surface, and claims (i)–(k)
test those axes against the same seeds without them.

Claims (Pohrt & Popov 2013): (a) eq. 16 describes the BEM ensemble; (b) the
crossover force of eq. 17; (c) ζ(H) ≈ 1.7/(H+1) (eq. 13); (d) the low-force
slope 1/(H+1) and (e) the high-force slope 1/3 (with the Hertz prefactor);
(f) below F_tr roughness lowers k against the smooth sphere (Conclusions);
(g) the scaling of F_tr with R and h_rms implied by eq. 17; (h) eq. 18's λ
for H → 0. Beyond the paraboloid (Conclusions): (a), (b), (d)–(f) per body of
revolution and for 1 < H < 2; (i) a short-wavelength cutoff leaves k unchanged
where the contact is larger than the cutoff; (j) a roll-off's effect on the
low-force slope; (k) elasticity on all scales is not crucial (a hardness cap
leaves the unloading and the loading stiffness unchanged).
"""
from __future__ import annotations

import itertools
import logging
import math
from pathlib import Path

import numpy as np

from . import runs
from .axes import AXES, optional_axes
from .statistics import interval, verdict, verdict_bound
from .tables import write_html_table

__all__ = ["claims_table", "run_claims", "prl2012_exponent", "EQ16_TOLERANCE", "CLAIMS_LEAD"]

log = logging.getLogger(__name__)


#: claim (a): eq. 16 describes the ensemble if no resolved load deviates by more than this (relative k)
EQ16_TOLERANCE = 0.10
#: eq. 18: λ from eq. 17 as H → 0 with ζ(0) = 1.7, √6 · 1.7^(−3/2); and Greenwood–Tripp's value
LAMBDA_EQ17, LAMBDA_GT = math.sqrt(6.0) * 1.7**-1.5, 1.41


#: columns naming the combination a row rests on: the sweep axes (:data:`roughcontact.study.axes.AXES`)
AXIS_COLUMNS = tuple(AXES)


def _claim(claim, statement, measured, low, high, paper, verdict_text, *, sweep="", loads="", note="", **where):
    return {"claim": claim, "statement": statement, **{k: where.get(k, math.nan) for k in AXIS_COLUMNS},
            "measured": measured, "ci_low": low, "ci_high": high, "paper_value": paper,
            "verdict": verdict_text.split(":")[0], "reason": verdict_text.partition(": ")[2],
            "sweep": sweep, "loads": loads, "note": note}


def _paper_values(length: float) -> dict:
    """The paper's setting of the optional axes as merged-file coordinates."""
    return {a.name: a.coordinate(a.paper, length) for a in optional_axes()}


def _describe(r, length: float, n: int, seeds: int) -> str:
    """The sweep a row rests on: the combination (optional axes off the paper's setting), seeds, grid."""
    text = f"sphere H = {r['hurst']:g}, R = {r['radius']:g}, h_rms = {r['h_rms']:g}"
    for axis, value in _paper_values(length).items():
        if axis in r and r[axis] != value:
            text += f", {axis} = {r[axis]:g}"
    return f"{text}, {seeds} seeds, n = {n}"


#: the claim that tests each optional axis off the paper's elastic, purely self-affine setting
EFFECT_CLAIM = {a.name: a.claim for a in optional_axes() if a.claim}


def _off_theory(r, length: float) -> str:
    """Why eqs. 11–17 do not apply to the combination *r* ('' where they do): a cutoff, a
    roll-off or a hardness makes the surface other than elastic and purely self-affine."""
    paper = _paper_values(length)
    off = [f"{axis} = {r[axis]:g} (claim {claim} tests it)" for axis, claim in EFFECT_CLAIM.items()
           if axis in r and r[axis] != paper[axis]]
    if not off:
        return ""
    return "untested: eqs. 11-17 are for an elastic, purely self-affine surface; here " + ", ".join(off)


def _is_paper_setting(frame, length):
    """Rows of *frame* at the paper's setting of the optional axes (or all rows if it has no such columns)."""
    keep = np.ones(len(frame), dtype=bool)
    for axis, value in _paper_values(length).items():
        if axis in frame:
            keep &= frame[axis].to_numpy(float) == value
    return frame[keep]


def claims_table(cross, reps, zeta_df, cfg: dict, groups: dict | None = None, exponents=None,
                 zeta_replicates=None):
    """``claims.csv``: one row per quantitative claim of the paper (and per
    combination it is tested on), with the measured value, its 95 % interval,
    the paper's value, the verdict and the sweep and loads it rests on."""
    import pandas as pd

    n, seeds = cfg["grid"]["n"], len(cfg["seeds"])
    L = cfg["grid"]["length"]
    rows = []
    for _, z in zeta_df.iterrows():
        rows.append(_claim(
            "c", "zeta(H) ~ 1.7/(H+1) (eq. 13)", z["zeta"], z["zeta_ci_low"], z["zeta_ci_high"], z["zeta_estimate"],
            verdict(z["zeta_estimate"], z["zeta_ci_low"], z["zeta_ci_high"]), hurst=z["hurst"],
            sweep=f"{z['source'].split(' (')[0]}, {int(z['n_seeds'])} seeds, n = {n}",
            loads=f"{int(z['n_points'])} loads, F/(E*L^2) = {z['force_min']:.2g}...{z['force_max']:.2g}"))
    for _, r in cross.iterrows():
        where = {k: r[k] for k in AXIS_COLUMNS if k in r}
        sweep = _describe(r, L, n, seeds)
        body = f" (body m = {r['exponent']:g})" if r.get("exponent", 2.0) != 2.0 else ""
        body += " (1 < H < 2)" if r["hurst"] > 1 else ""
        loads = (f"{int(r['n_loads_resolved'])} resolved loads, F/(E*L^2) = "
                 f"{r['force_min_resolved']:.2g}...{r['force_max']:.2g}")
        get = r.get
        off_theory = _off_theory(r, L)  # '' at the paper's setting: then the verdict stands
        rows.append(_claim(
            "a", f"eq. 16 (fitted zeta) within {EQ16_TOLERANCE:.0%} of the BEM ensemble at every resolved load{body}",
            get("eq16_max_rel_dev", math.nan), get("eq16_max_rel_dev_ci_low", math.nan),
            get("eq16_max_rel_dev_ci_high", math.nan), EQ16_TOLERANCE,
            off_theory or verdict_bound(EQ16_TOLERANCE, get("eq16_max_rel_dev_ci_low", math.nan),
                                        get("eq16_max_rel_dev_ci_high", math.nan), side="below"),
            sweep=sweep, loads=loads, note="measured: max |k/k_eq16 - 1|", **where))
        cross_verdict = r["verdict_estimate"]
        if cross_verdict == "unresolved":
            cross_verdict = "untested: " + r["note"].split("unresolved: ")[-1].split(";")[0]
        rows.append(_claim(
            "b", f"crossover force F_tr of eq. 17 (zeta = 1.7/(H+1); Fig. 3: 8e-5 E* L^2){body}",
            r["Ftr_measured"], r["Ftr_ci_low"], r["Ftr_ci_high"], r["Ftr_pred_estimate"], off_theory or cross_verdict,
            sweep=sweep, loads=loads, note=(f"measured: eq. 16 with free prefactors, F/(E*L^2); eq. 17 with the "
                                            f"fitted zeta = {r['Ftr_pred_fit']:.3g}: {r['verdict_fit']}"), **where))
        if "zeta_sphere" in r and math.isfinite(r["zeta_sphere"]):
            rows.append(_claim(
                "c", "zeta(H) ~ 1.7/(H+1) from the sphere's fractal branch (eq. 16's B)", r["zeta_sphere"],
                r["zeta_sphere_ci_low"], r["zeta_sphere_ci_high"], r["zeta_estimate"],
                off_theory or verdict(r["zeta_estimate"], r["zeta_sphere_ci_low"], r["zeta_sphere_ci_high"]),
                sweep=sweep, loads=loads, **where))
        for claim, name, text in (("d", "slope_low", "low-force slope d ln k/d ln F = 1/(H+1) (eq. 11)"),
                                  ("e", "slope_high", "high-force slope = 1/(m+1) (1/3: Hertz, eq. 9)")):
            window = "low" if name == "slope_low" else "high"
            ratio = cfg["fit"]["slopes"][f"{window}_max_ratio" if window == "low" else "high_min_ratio"]
            rows.append(_claim(
                claim, text, r[name], r[f"{name}_ci_low"], r[f"{name}_ci_high"], r[f"{name}_theory"],
                off_theory or r[f"{name}_verdict"], sweep=sweep,
                loads=(f"{int(r[f'n_loads_{window}'])} resolved loads with F {'<=' if window == 'low' else '>='} "
                       f"{ratio:g} F_tr"),
                note=(f"eq. 16 itself gives {r[f'{name}_eq16']:.3f} over the same loads: "
                      f"{verdict(r[f'{name}_eq16'], r[f'{name}_ci_low'], r[f'{name}_ci_high'])}"), **where))
        if "hertz_coefficient" in r and math.isfinite(r["hertz_coefficient"]):
            rows.append(_claim(
                "e", f"body prefactor A of F = A k^(m+1) + B k^(H+1) equals eq. 7 (L/(6R): Hertz, eq. 10){body}",
                r["hertz_coefficient"],
                r["hertz_coefficient_ci_low"], r["hertz_coefficient_ci_high"], r["hertz_coefficient_theory"],
                off_theory or verdict(r["hertz_coefficient_theory"], r["hertz_coefficient_ci_low"],
                                      r["hertz_coefficient_ci_high"]),
                sweep=sweep, loads=loads, note="normalised units F/(E*L^2), k/(E*L)", **where))
        softer = (verdict_bound(1.0, get("k_over_hertz_below_Ftr_ci_low", math.nan),
                                get("k_over_hertz_below_Ftr_ci_high", math.nan), side="below")
                  if r["n_loads_below_Ftr"] else "untested: no resolved load below F_tr")
        rows.append(_claim(
            "f", f"below F_tr roughness lowers k against the smooth body (Conclusions){body}",
            get("k_over_hertz_below_Ftr", math.nan), get("k_over_hertz_below_Ftr_ci_low", math.nan),
            get("k_over_hertz_below_Ftr_ci_high", math.nan), 1.0, off_theory or softer,
            sweep=sweep, loads=f"{int(r['n_loads_below_Ftr'])} resolved loads below F_tr",
            note="measured: max over those loads of k/k_body(F) (eq. 9 for m = 2)", **where))
    if zeta_replicates is not None:
        rows += _zeta_law_claims(zeta_df, zeta_replicates, cfg)
    paper = _is_paper_setting(cross, L) if len(cross) else cross
    rows += _scaling_claims(paper, reps, cfg)
    rows += _lambda_claims(paper, cfg)
    if groups is not None and "sphere" in groups:
        from .effects import effect_claims

        rows += [_claim(**row) for row in effect_claims(groups["sphere"], cross, cfg)]
    if exponents is not None:
        rows += _exponent_claims(exponents, zeta_df, cfg)
    return pd.DataFrame(rows).sort_values("claim", kind="stable", ignore_index=True)


def _flat_rows(zeta_df):
    """Rows of zeta.csv fitted on flat runs at the paper's setting (not on a substituted roll-off,
    cutoff or hardness: :func:`roughcontact.study.zeta.paper_setting` says so in the source)."""
    if not len(zeta_df):
        return zeta_df
    return zeta_df[zeta_df["source"].astype(str) == "flat"]


#: the paper's values of the parameters of the candidate ζ(H) laws, where eq. 13 is of that form
EQ13_PARAMETERS = {"a/(H+1)": {"a": 1.7}, "a/(H+b)": {"a": 1.7, "b": 1.0}, "a*(H+1)^-b": {"a": 1.7, "b": 1.0},
                   "a/(H+1)+b/H": {"a": 1.7, "b": 0.0}}


def _zeta_law_claims(zeta_df, replicates, cfg) -> list[dict]:
    """Claim (c'): a ζ(H) law whose form the data choose (:mod:`.zeta_law`) beside eq. 13,
    from the flat runs: one row per parameter of the chosen law against eq. 13's value where
    eq. 13 has that form, and one row for the law's largest deviation from the measured ζ(H)
    against eq. 13's."""
    from ..models.zeta_law import LAWS
    from .zeta_law import MIN_HURST, fit_zeta_law

    n = cfg["grid"]["n"]
    flat = _flat_rows(zeta_df)
    flat = flat[np.isfinite(flat["zeta_ci_low"].to_numpy(float))] if len(flat) else flat
    statement = "zeta(H) follows a law whose form the data choose (eq. 13: 1.7/(H+1))"
    if len(flat) < MIN_HURST:
        return [_claim("c'", statement, math.nan, math.nan, math.nan, math.nan,
                       f"untested: {len(flat)} H value(s) with flat runs and a zeta interval "
                       f"(a law needs {MIN_HURST})")]
    hurst = flat["hurst"].to_numpy(float)
    law = fit_zeta_law(hurst, flat["zeta"], flat["zeta_ci_low"], flat["zeta_ci_high"],
                       replicates.sel(hurst=hurst).values, level=float(cfg["fit"]["zeta"]["confidence"]))
    aic = ", ".join(f"{form} {value:.1f}" for form, value in sorted(law.aic.items(), key=lambda kv: kv[1]))
    sweep = (f"flat H = {hurst.min():g}...{hurst.max():g} ({hurst.size} values), "
             f"{int(flat['n_seeds'].iloc[0])} seeds, n = {n}")
    note = f"AIC of the {len(LAWS)} candidate forms (lower is better): {aic}"
    rows = []
    for name, value in law.parameters.items():
        paper = EQ13_PARAMETERS.get(law.form, {}).get(name, math.nan)
        text = (verdict(paper, law.ci_low[name], law.ci_high[name]) if math.isfinite(paper)
                else "untested: eq. 13 is not of this form")
        rows.append(_claim("c'", f"zeta(H) = {law.form} chosen by the data: parameter {name}", value,
                           law.ci_low[name], law.ci_high[name], paper, text, sweep=sweep, note=note))
    rows.append(_claim(
        "c'", f"the law zeta = {law.form} deviates less from the measured zeta(H) than eq. 13",
        law.max_rel_dev, law.max_rel_dev_ci_low, law.max_rel_dev_ci_high, law.eq13_max_rel_dev,
        verdict_bound(0.0, law.difference_ci_low, law.difference_ci_high, side="below"), sweep=sweep,
        note=(f"measured: max over H of |law/zeta - 1|; paper value: the same for 1.7/(H+1); verdict on the "
              f"paired difference law - eq. 13, interval {law.difference_ci_low:.3g}...{law.difference_ci_high:.3g}")))
    return rows


def _scaling_claims(cross, reps, cfg):
    """Claim (g): F_tr ∝ R^((H+1)/(2−H)) h^(3/(2−H)) (eq. 17), exponents fitted per H."""
    rows = []
    level = float(cfg["fit"]["zeta"]["confidence"])
    for hurst in cfg["hurst"]:
        sub = cross[(cross["hurst"] == hurst) & np.isfinite(cross["Ftr_ci_low"])] if len(cross) else cross
        for axis, theory_value in (("radius", (hurst + 1) / (2 - hurst)), ("h_rms", 3 / (2 - hurst))):
            statement = f"F_tr ~ {'R' if axis == 'radius' else 'h_rms'}^{theory_value:.3g} (eq. 17: " + \
                        ("(H+1)/(2-H))" if axis == "radius" else "3/(2-H))")
            values = sorted(set(sub[axis])) if len(sub) else []
            if len(values) < 2:
                swept = len([r for r in cfg["radius"] if math.isfinite(r)] if axis == "radius" else cfg["h_rms"])
                why = (f"untested: {len(values)} {axis} value(s) with a resolved crossover" if swept >= 2
                       else f"untested: one {axis} value only")
                rows.append(_claim("g", statement, math.nan, math.nan, math.nan, theory_value, why, hurst=hurst))
                continue
            others = [a for a in ("radius", "h_rms") if a != axis and len(set(sub[a])) >= 2]
            design = np.column_stack([np.ones(len(sub)), np.log(sub[axis].to_numpy(float)),
                                      *[np.log(sub[a].to_numpy(float)) for a in others]])
            point = np.linalg.lstsq(design, np.log(sub["Ftr_measured"].to_numpy(float)), rcond=None)[0][1]
            boot = np.array([reps["Ftr_replicates"].sel(
                {a: row[a] for a in reps["Ftr_replicates"].dims if a != "replicate"}).values
                for _, row in sub.iterrows()])                                     # (combos, replicates)
            exponents = np.linalg.pinv(design)[1] @ np.log(boot)
            lo, hi = interval(exponents, level)
            rows.append(_claim("g", statement, float(point), lo, hi, theory_value, verdict(theory_value, lo, hi),
                               hurst=hurst, sweep=f"{len(sub)} sphere combinations at H = {hurst:g}",
                               loads=f"{axis} = {', '.join(f'{v:g}' for v in values)}"))
    return rows


def _lambda_claims(cross, cfg):
    """Claim (h): eq. 18, F_tr/E* = λ h^(3/2) R^(1/2) for H → 0, from the smallest H swept (≤ 0.2)."""
    small = [h for h in cfg["hurst"] if h <= 0.2]
    statement = f"eq. 18: F_tr = lambda E* h^1.5 R^0.5 as H -> 0, lambda = {LAMBDA_EQ17:.2f} (eq. 17; GT: {LAMBDA_GT})"
    if not small or not len(cross):
        return [_claim("h", statement, math.nan, math.nan, math.nan, LAMBDA_EQ17,
                       f"untested: the sweep's smallest H is {min(cfg['hurst']):g} (needs H <= 0.2 with spheres)")]
    from ..models.greenwood_tripp import self_affine_sphere_curve
    from .verdicts import fit_eq16

    rows = []
    hurst = min(small)
    L, n = cfg["grid"]["length"], cfg["grid"]["n"]
    for _, r in cross[cross["hurst"] == hurst].iterrows():
        scale = r["h_rms"] ** 1.5 * r["radius"] ** 0.5 / L**2
        low, high = r["Ftr_ci_low"] / scale, r["Ftr_ci_high"] / scale
        where = {"hurst": hurst, "radius": r["radius"], "h_rms": r["h_rms"]}
        predicted = r["Ftr_pred_estimate"] / scale
        unresolved = "untested: unresolved crossover, " + str(r["note"]).split("unresolved: ")[-1].split(";")[0]

        def judge(value):
            return verdict(value, low, high) if math.isfinite(low) else unresolved

        rows.append(_claim(
            "h", statement, r["Ftr_measured"] / scale, low, high, predicted, judge(predicted),
            note=f"paper value: eq. 17 at H = {hurst:g} (tends to {LAMBDA_EQ17:.2f} as H -> 0; GT {LAMBDA_GT})",
            **where))
        # Greenwood-Tripp on the same spectrum and grid, its crossover by the same fit with H -> 0 (F ~ k)
        gt = self_affine_sphere_curve(hurst=hurst, h_rms=r["h_rms"], n=n, length=L, radius=r["radius"], e_star=1.0)
        lam = float(fit_eq16(gt.force / L**2, gt.stiffness / L, 0.0).crossover_force) / scale
        rows.append(_claim(
            "h", f"eq. 18 with Greenwood-Tripp's lambda ({LAMBDA_GT} in the paper; the same fit of GT's curve on "
                 "these surfaces gives the paper value column)", r["Ftr_measured"] / scale, low, high, lam,
            judge(lam), note=f"GT mu = {gt.mu:.3g} (grows with the grid: no cutoff)", **where))
    return rows


def prl2012_exponent(hurst: float) -> float:
    """The free stiffness exponent of nominally flat fractal surfaces of Pohrt & Popov, Phys. Rev.
    Lett. 108, 104301 (2012), doi 10.1103/PhysRevLett.108.104301: 0.77 at fractal dimension
    D = 3 (H → 0) and 0.51 at D = 2 (H = 1), interpolated linearly in H = 3 − D."""
    return 0.77 - 0.26 * hurst


def _exponent_claims(exponents, zeta_df, cfg) -> list[dict]:
    """Claims (l) and (m) from the local exponents (:mod:`.exponents`) and the ζ fit.

    (l) With a roll-off below the system size, ``K ∝ p`` over a range of pressures (Pastewka et
    al., Phys. Rev. E 87, 062809 (2013)): per H and roll-off ``λ_r < L``, the largest local
    exponent of the flat runs with its interval; consistent when the interval of some load
    contains 1 (the number of such loads is the reason). (m) The free exponent of the flat runs
    at the paper's setting (``zeta.csv``) against :func:`prl2012_exponent`.
    """
    L = cfg["grid"]["length"]
    n, seeds = cfg["grid"]["n"], len(cfg["seeds"])
    flat_swept = any(not math.isfinite(r) for r in cfg["radius"])
    rolled = sorted(r for r in cfg["rolloff"] if r is not None and r < L)
    statement = "with a roll-off lambda_r < L, K ~ p (local exponent 1) over a range of loads (Pastewka et al. 2013)"
    rows = []
    if not (flat_swept and rolled):
        why = "no flat runs" if not flat_swept else "no roll-off below L swept"
        rows.append(_claim("l", statement, math.nan, math.nan, math.nan, 1.0, f"untested: {why}"))
    for hurst, rolloff in itertools.product(cfg["hurst"], rolled if flat_swept else []):
        sub = exponents[(exponents["kind"] == "flat") & (exponents["hurst"] == hurst)
                        & (exponents["rolloff"] == rolloff)] if len(exponents) else exponents
        for axis in ("cutoff", "hardness"):  # the other optional axes at the paper's setting
            if len(sub) and axis in sub:
                sub = sub[sub[axis].to_numpy(float) == runs.coordinate(axis, runs.DEFAULTS[axis], L)]
        sweep = f"flat H = {hurst:g}, rolloff = {rolloff:g} (length unit), {seeds} seeds, n = {n}"
        if not len(sub):
            rows.append(_claim("l", statement, math.nan, math.nan, math.nan, 1.0,
                               "untested: no load with a resolved window", sweep=sweep, hurst=hurst, rolloff=rolloff))
            continue
        covers = (sub["ci_low"] <= 1.0) & (sub["ci_high"] >= 1.0)
        covered = int(covers.sum())
        # the row shows the load the verdict rests on: the largest exponent whose interval holds 1, else the largest
        top = sub[covers].loc[sub[covers]["local_exponent"].idxmax()] if covered else \
            sub.loc[sub["local_exponent"].idxmax()]
        text = (f"consistent: the interval contains 1 at {covered} of {len(sub)} loads (no correction for "
                f"testing several loads)" if covered else verdict(1.0, top["ci_low"], top["ci_high"]))
        rows.append(_claim("l", statement, float(top["local_exponent"]), float(top["ci_low"]), float(top["ci_high"]), 1.0,
                           text, sweep=sweep, hurst=hurst, rolloff=rolloff,
                           loads=f"{len(sub)} loads with a resolved window, F/(E*L^2) = {sub['force'].min():.3g}..."
                                 f"{sub['force'].max():.3g}; the row's load {top['force']:.3g}",
                           note=("measured: the largest local exponent d ln k/d ln F (exponents.csv) whose interval "
                                 "holds 1, else the largest")))
    statement = ("free stiffness exponent of flat surfaces 0.77 (H -> 0) to 0.51 (H = 1), linear in H "
                 "(Pohrt & Popov, PRL 2012)")
    flat = _flat_rows(zeta_df)
    if not len(flat):
        rows.append(_claim("m", statement, math.nan, math.nan, math.nan, math.nan,
                           "untested: no flat runs at the paper's setting"))
    for _, z in flat.iterrows():
        value = prl2012_exponent(z["hurst"])
        rows.append(_claim("m", statement, z["exponent"], z["exponent_ci_low"], z["exponent_ci_high"], value,
                           verdict(value, z["exponent_ci_low"], z["exponent_ci_high"]), hurst=z["hurst"],
                           sweep=f"flat H = {z['hurst']:g}, {int(z['n_seeds'])} seeds, n = {n}", loads=z["window"],
                           note="measured: the free exponent of the zeta fit (zeta.csv)"))
    return rows


#: the lead paragraph of the claims page of the report
CLAIMS_LEAD = ("One row per quantitative claim of Pohrt & Popov (2013) and per sweep combination it is tested "
               "on: the measured value with its 95 % bootstrap-over-seeds interval (ci_low, ci_high), the "
               "paper's value and the verdict: consistent (the paper's value lies inside the interval, or for a "
               "bound the interval lies on the claimed side), differs (it is excluded) or untested (the sweep "
               "cannot decide it; the reason says why). claims.csv holds every digit.")


def run_claims(cfg, crossover_csv, crossover_nc, zeta_csv, zeta_nc, stiffness_nc, exponents_csv, out_csv, out_html):
    """``claims`` rule: crossover.csv, its replicates, zeta.csv and zeta.nc (its replicates), the
    runs and the local exponents -> claims.csv and the same table as an HTML page for the report
    (:mod:`roughcontact.study.tables`)."""
    import pandas as pd
    import xarray as xr

    from .merge import read_groups, write_csv

    cross = pd.read_csv(crossover_csv) if Path(crossover_csv).stat().st_size > 1 else pd.DataFrame()
    with xr.open_dataset(crossover_nc, engine="netcdf4") as reps, xr.open_dataset(zeta_nc, engine="netcdf4") as zds:
        exponents = pd.read_csv(exponents_csv) if Path(exponents_csv).stat().st_size > 1 else pd.DataFrame()
        table = claims_table(cross, reps.load(), pd.read_csv(zeta_csv), cfg, read_groups(stiffness_nc), exponents,
                             zds["zeta_replicates"].load())
    write_csv(table, out_csv)
    write_html_table(table, out_html, title="Claims of the paper", lead=CLAIMS_LEAD,
                     first=("claim", "statement", "verdict", "measured", "ci_low", "ci_high", "paper_value", "reason"))
    log.info("claims:\n%s", table.to_string())
