"""The analysis of ``docs/make_fractal_prefactor.py``: the branch's loads, ζ_s per case with its
bootstrap interval, the flat reference at equal force and the hypotheses' numbers (that script's
docstring has the definitions). Works on the cached CSVs (``docs/results/fractal_prefactor_*.csv``).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

SUMMITS_CSV = Path(__file__).resolve().parent / "results" / "fractal_prefactor_summits.csv"
#: a load belongs to the single-asperity regime when one cluster carries at least this share of the force
SINGLE = 0.9
#: largest |k̄_1024/k̄_2048 − 1| of a converged load
CONVERGED = 0.02
#: largest |k̄_512/k̄_2048 − 1| of a converged load: 3 × CONVERGED, first order from 512² on, so that
#: a small change between the two finest grids is not a crossing of a non-monotone sequence
COARSE = 0.06
BOOT = 2000

def crossover(row) -> float:
    from roughcontact.models import paper
    from roughcontact.models.zeta_law import zeta_law

    if np.isinf(row.radius):
        return np.inf
    h = row.h_rms if np.isnan(row.rolloff) else 9e-3
    return float(paper.crossover_force(row.radius, hurst=row.hurst, h_rms=h, length=1.0, e_star=1.0,
                                       zeta=float(zeta_law(row.hurst))))


def zeta16(k, force, hurst, radius, h_rms):
    """ζ of eq. 16 at stiffness k and force F (L = E* = 1): the Hertz force at k removed."""
    rough = force - (0.0 if np.isinf(radius) else k**3 / (6.0 * radius))
    with np.errstate(invalid="ignore"):
        return k / (np.where(rough > 0, rough, np.nan) / h_rms) ** (1.0 / (hurst + 1.0))


def branch(loads: pd.DataFrame) -> pd.DataFrame:
    """Flag each load: below F_tr, converged, single-asperity, and on the fractal branch."""
    out = []
    for case, sub in loads.groupby("case", sort=False):
        sub = sub.copy()
        f_tr = crossover(sub.iloc[0])
        sub["f_tr"] = f_tr
        sub["grid_change"] = sub["k1024"] / sub["k2048"] - 1.0
        sub["converged"] = (sub["grid_change"].abs() < CONVERGED) & ((sub["k512"] / sub["k2048"] - 1.0).abs() < COARSE)
        sub["single"] = sub["cluster_share"] >= SINGLE
        sub["below"] = sub["force"] <= f_tr * (1 + 1e-6)
        sub["on_branch"] = sub["converged"] & ~sub["single"] & sub["below"]
        row = sub.iloc[0]
        sub["zeta16"] = zeta16(sub["k"].to_numpy(), sub["force"].to_numpy(), row.hurst, row.radius, row.h_rms)
        sub["zeta_raw"] = sub["k"] / (sub["force"] / row.h_rms) ** (1.0 / (row.hurst + 1.0))
        sub["slope"] = np.gradient(np.log(sub["k"]), np.log(sub["force"]))
        out.append(sub)
    return pd.concat(out, ignore_index=True)


def case_zeta(flagged: pd.DataFrame, seeds: pd.DataFrame, rng):
    """ζ_s per case (geometric mean of ζ_16 over the branch) with its bootstrap interval, and the
    replicates: cases with the same seeds are resampled alike (they share their seeds' random
    phases), so that their ratios get paired intervals; *rng* is an integer seed. Returns (DataFrame, {case: replicates})."""
    rows, replicates, picks = [], {}, {}
    for case, sub in flagged.groupby("case", sort=False):
        row = sub.iloc[0]
        on = sub[sub["on_branch"]]
        table = seeds[seeds["case"] == case].pivot(index="seed", columns="i", values="k").sort_index()
        rec = dict(case=case, hurst=row.hurst, radius=row.radius, h_rms=row.h_rms, period=row.period,
                   rolloff=row.rolloff, f_tr=row.f_tr, loads=len(on))
        if len(on) == 0:
            rows.append(rec)
            continue
        idx = on["i"].to_numpy()
        ks = table[idx].to_numpy()
        # cases with the same number of seeds (the same seeds) share their resamples: paired ratios
        pick = picks.setdefault(ks.shape[0], np.random.default_rng(rng + ks.shape[0]).integers(
            0, ks.shape[0], size=(BOOT, ks.shape[0])))
        force = on["force"].to_numpy()

        def per_load(k_mean):
            return zeta16(k_mean, force, row.hurst, row.radius, row.h_rms)

        def stat(k_mean):
            return float(np.exp(np.nanmean(np.log(per_load(k_mean)))))

        loads_boot = np.array([per_load(ks[p].mean(axis=0)) for p in pick])
        boots = np.exp(np.nanmean(np.log(loads_boot), axis=1))
        replicates[case] = boots
        replicates[case, "loads"] = (force, loads_boot, per_load(ks.mean(axis=0)))
        raw = on["zeta_raw"].to_numpy()
        slope = np.polyfit(np.log(force), np.log(on["k"]), 1)[0] if len(on) > 1 else np.nan
        rec.update(zeta=stat(ks.mean(axis=0)), lo=np.percentile(boots, 2.5), hi=np.percentile(boots, 97.5),
                   zeta_raw=float(np.exp(np.mean(np.log(raw)))), f_lo=force.min(), f_hi=force.max(),
                   slope=slope, seeds=ks.shape[0], cells_lo=on["cells"].min(), cells_hi=on["cells"].max(),
                   clusters=on["clusters"].mean(), offset=on["offset"].mean(), r2=on["r2"].mean(),
                   a=(on["k"] / 2.0).mean(), grid_change=on["grid_change"].abs().max())
        rows.append(rec)
    return pd.DataFrame(rows), replicates


def ratio_at_equal_force(replicates, sphere: str, flat: str):
    """ζ_s/ζ_flat at the sphere's branch loads, ζ_flat(F) interpolated in ln F between the flat
    branch's loads (held constant beyond them): (ratio, low, high, share of loads inside the flat range)."""
    if (sphere, "loads") not in replicates or (flat, "loads") not in replicates:
        return np.nan, np.nan, np.nan, np.nan
    f_s, boot_s, mean_s = replicates[sphere, "loads"]
    f_f, boot_f, mean_f = replicates[flat, "loads"]
    x, xf = np.log(f_s), np.log(f_f)

    def ratio(z_s, z_f):
        return np.exp(np.nanmean(np.log(z_s) - np.interp(x, xf, np.log(z_f))))

    boots = np.array([ratio(a, b) for a, b in zip(boot_s, boot_f)])
    inside = np.mean((f_s >= f_f.min() * (1 - 1e-9)) & (f_s <= f_f.max() * (1 + 1e-9)))
    return (ratio(mean_s, mean_f), *np.percentile(boots, [2.5, 97.5]), inside)


def paired_ratio(replicates, num: str, den: str):
    """Ratio of two cases' ζ with its paired percentile interval (NaN if either is missing)."""
    if num not in replicates or den not in replicates:
        return np.nan, np.nan
    ratio = replicates[num] / replicates[den]
    return tuple(np.percentile(ratio, [2.5, 97.5]))


def pressure_factor(hurst):
    """Hypothesis (a): the flat law read locally, K(p) ∝ p^(1/(H+1)) per nominal area, under Hertz's
    nominal pressure p0 √(1 − r²/a²) (p0 = 3F/(2πa²)), integrated over the nominal contact, against
    the same force spread uniformly over it: ``(3/2)^s/(1 + s/2)``, s = 1/(H+1)."""
    s = 1.0 / (np.asarray(hurst, dtype=float) + 1.0)
    return 1.5**s / (1.0 + s / 2.0)


def band_factor(hurst, wavelength, *, n=2048, rolloff=None):
    """Hypothesis (c), the roughness seen within the contact: eq. 11 with (h, L) replaced by
    (h_λ, λ), h_λ the rms of the n-grid's modes of wavelength below λ (the same spectrum as
    :func:`roughcontact.surfaces.self_affine`), against eq. 11 itself: ``(λ/L)^(1−s) (h/h_λ)^s``,
    s = 1/(H+1). 1 for a continuous power law (eq. 11 is scale-free); the grid's discrete modes
    and a roll-off move it."""
    k = np.fft.fftfreq(n, 1.0 / n)
    q = np.hypot(k[:, None], k[None, :])
    q[0, 0] = np.inf
    c = q ** (-2.0 - 2.0 * hurst)
    if rolloff is not None and np.isfinite(rolloff):
        c = np.where(q < 1.0 / rolloff, (1.0 / rolloff) ** (-2.0 - 2.0 * hurst), c)
    ratio = np.sqrt(c[q > 1.0 / wavelength].sum() / c.sum())
    s = 1.0 / (hurst + 1.0)
    return wavelength ** (1.0 - s) * ratio ** (-s)


def _equal_force(flagged, sphere: str, flat: str, column: str) -> float:
    """Mean over the sphere's branch loads of its *column* over the flat surface's at the same F
    (ln-interpolated between the flat branch's loads)."""
    s_on = flagged[(flagged["case"] == sphere) & flagged["on_branch"]]
    f_on = flagged[(flagged["case"] == flat) & flagged["on_branch"]]
    if s_on.empty or f_on.empty:
        return np.nan
    ref = np.exp(np.interp(np.log(s_on["force"]), np.log(f_on["force"]), np.log(f_on[column])))
    return float(np.exp(np.mean(np.log(s_on[column].to_numpy() / ref))))


def _flat_reference(cases: pd.DataFrame) -> pd.DataFrame:
    flat = cases[np.isinf(cases["radius"])].set_index("hurst")[["zeta", "lo", "hi"]]
    return flat.rename(columns={"zeta": "zeta_flat", "lo": "flat_lo", "hi": "flat_hi"})


def summarize(loads: pd.DataFrame, seeds: pd.DataFrame):
    """Flagged loads and per-case ζ_s with the flat reference and the hypotheses' numbers."""
    from roughcontact.models.zeta_law import zeta_law

    flagged = branch(loads)
    cases, replicates = case_zeta(flagged, seeds, 31)
    cases = cases.join(_flat_reference(cases), on="hurst")
    base = {h: c for h, c in zip(cases["hurst"], cases["case"]) if c in ("base",) or c.startswith("H")}
    flat_of = {h: c for h, c in zip(cases["hurst"], cases["case"]) if c.startswith("flat")}
    ratio_flat = [paired_ratio(replicates, c, flat_of.get(h, "")) for c, h in zip(cases["case"], cases["hurst"])]
    cases["flat_ratio_lo"], cases["flat_ratio_hi"] = np.array(ratio_flat, dtype=float).reshape(-1, 2).T
    equal = np.array([ratio_at_equal_force(replicates, c, flat_of.get(h, ""))
                      for c, h in zip(cases["case"], cases["hurst"])], dtype=float).reshape(-1, 4)
    cases["flat_equal"], cases["flat_equal_lo"], cases["flat_equal_hi"], cases["flat_inside"] = equal.T
    ratio_base = [paired_ratio(replicates, c, base.get(h, "")) for c, h in zip(cases["case"], cases["hurst"])]
    sweep_zeta = cases.set_index("case")["zeta"]
    cases["base_ratio"] = cases["zeta"] / cases["hurst"].map(lambda h: sweep_zeta.get(base.get(h), np.nan))
    cases["base_ratio_lo"], cases["base_ratio_hi"] = np.array(ratio_base, dtype=float).reshape(-1, 2).T
    cases["zeta_law"] = zeta_law(cases["hurst"].to_numpy())
    cases["pressure_factor"] = pressure_factor(cases["hurst"])
    # the apex region, where the sphere has dropped by 2 h_rms (the roughness's own rms: a shorter
    # period keeps the power law's amplitude with h_rms·period^H), against the cell L
    actual = cases["h_rms"] * cases["period"] ** cases["hurst"]
    cases["sampled"] = np.sqrt(4.0 * cases["radius"] * actual)
    cases["clusters_vs_flat"] = [_equal_force(flagged, c, flat_of.get(h, ""), "clusters")
                                 for c, h in zip(cases["case"], cases["hurst"])]
    cases["band_factor"] = [band_factor(h, 2.0 * a, rolloff=r) if np.isfinite(a) else np.nan
                            for h, a, r in zip(cases["hurst"], cases["a"], cases["rolloff"])]
    if SUMMITS_CSV.exists():
        summits = pd.read_csv(SUMMITS_CSV).groupby("case")[["summit", "touch_offset"]].mean()
        cases = cases.join(summits, on="case")
    return flagged, cases


def calibration_cases(cases: pd.DataFrame) -> pd.Series:
    """The spheres the touch-height model is fitted on: self-affine from L to the grid (no roll-off,
    no shorter period) with a measured touch height."""
    return (np.isfinite(cases["radius"]) & cases["zeta"].notna() & (cases["period"] == 1.0)
            & cases["rolloff"].isna() & cases["summit"].notna())


def fit_touch_model(cases: pd.DataFrame):
    """β of ln(ζ_s/ζ_law) = −β u (intercept fixed to 0), and the free intercept's fit (c, β')."""
    sub = cases[calibration_cases(cases)]
    y = np.log(sub["zeta"] / sub["zeta_law"]).to_numpy()
    u = sub["summit"].to_numpy()
    beta = float(-np.sum(u * y) / np.sum(u * u))
    slope, intercept = np.polyfit(u, y, 1)
    return beta, float(np.exp(intercept)), float(-slope)
