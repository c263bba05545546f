"""The rough sphere's fractal-branch prefactor ζ_s (issue 31, item 2): ``docs/results/fractal_prefactor.md``.

    PYTHONPATH=src nice -n 10 python docs/make_fractal_prefactor.py --measure RAW.csv   # ~1 h on 2 shared cores
    PYTHONPATH=src python docs/make_fractal_prefactor.py --raw RAW.csv [RAW2.csv ...]    # cache from raw rows
    PYTHONPATH=src python docs/make_fractal_prefactor.py                                 # page from the cache

``--measure`` presses every case of ``fractal_prefactor_run.CASES`` (12 seeds, the same surfaces on
512², 1024² and 2048²) and writes one row per (case, seed, grid, load) to RAW.csv (about 1.5 MB,
not kept). ``--raw`` reduces those rows to the two cached CSVs under ``docs/results/``:
``fractal_prefactor_loads.csv`` (per case and load: the ensemble means per grid, the contact's
descriptors on 2048²) and ``fractal_prefactor_seeds.csv`` (per case, seed and load: k on 2048², for
the bootstrap). The page, its table and its figure are computed from the cache alone.

Definitions (L = E* = 1). ζ_s(F) is eq. 16 solved for ζ at the measured ensemble stiffness k̄(F):
``ζ_16(F) = k̄ / ((F − k̄³/(6R))/h)^(1/(H+1))`` (the Hertz force at the same stiffness removed, so
that eq. 16's low-force limit is read at every load of the branch); ``ζ_raw(F) = k̄/fractal(F, ζ=1)``
is the brief's ratio without that correction. The fractal branch are the loads (i) at or below
F_tr (eq. 17, flat ζ law), (ii) grid-converged: |k̄_1024/k̄_2048 − 1| < 2 % and
|k̄_512/k̄_2048 − 1| < 6 % (a first-order sequence; a 2 % change that crosses a non-monotone one is not
convergence), (iii) out of the
single-asperity regime: one cluster of patches (patches closer than 0.004 L merged) carries less
than :data:`SINGLE` of the force on average. ζ_s of a case is the geometric mean of ζ_16 over its
branch; intervals: percentile bootstrap over the seeds (the branch's loads fixed).
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS))
RESULTS = DOCS / "results"
LOADS_CSV = RESULTS / "fractal_prefactor_loads.csv"
SEEDS_CSV = RESULTS / "fractal_prefactor_seeds.csv"
SUMMITS_CSV = RESULTS / "fractal_prefactor_summits.csv"
PAGE = RESULTS / "fractal_prefactor.md"
FIGURE = RESULTS / "fractal_prefactor.png"
#: a load belongs to the single-asperity regime when one cluster carries at least this share of the force
SINGLE = 0.9
#: largest |k̄_1024/k̄_2048 − 1| of a converged load
CONVERGED = 0.02
#: largest |k̄_512/k̄_2048 − 1| of a converged load: 3 × CONVERGED, first order from 512² on, so that
#: a small change between the two finest grids is not a crossing of a non-monotone sequence
COARSE = 0.06
BOOT = 2000
CASE_COLUMNS = ["case", "hurst", "radius", "h_rms", "period", "rolloff"]


def reduce_raw(paths, summit_paths=()) -> None:
    """Write the cached CSVs from raw measurement rows (:mod:`fractal_prefactor_run`).

    The grid ladder's means (``k512``, ``k1024``, ``k2048``) are over the seeds pressed on every
    grid; ``fractal_prefactor_seeds.csv`` keeps k on the finest grid for every seed (the ladder's
    and those pressed on the finest grid alone), and the contact's descriptors are means over them.
    """
    from fractal_prefactor_run import case_parameters

    raw = pd.concat([pd.read_csv(p) for p in paths], ignore_index=True)
    raw = raw.drop_duplicates(["case", "seed", "n", "force"])
    raw["i"] = raw.groupby(["case", "seed", "n"]).cumcount()
    finest = raw["n"].max()
    loads = []
    for case, sub in raw.groupby("case", sort=False):
        params = case_parameters(case)
        grids = sub.groupby("seed")["n"].nunique()
        ladder = sub[sub["seed"].isin(grids.index[grids == grids.max()])]
        means = ladder.groupby(["n", "i"])["k"].mean().unstack("n")
        fine = sub[sub["n"] == finest].groupby("i")
        frame = pd.DataFrame({"force": sub.groupby("i")["force"].mean()})
        for n in means.columns:
            frame[f"k{n}"] = means[n]
        frame["ladder_seeds"] = ladder["seed"].nunique()
        frame["seeds"] = sub[sub["n"] == finest]["seed"].nunique()
        for column in ("k", "cells", "patches", "clusters", "cluster_share", "share", "r2", "offset", "depth"):
            frame[column] = fine[column].mean()
        walls = ladder.groupby(["n", "i"])["wall_s"].sum().unstack("n")
        for n in walls.columns:
            frame[f"wall{n}"] = walls[n]         # the ladder seeds' solve + stiffness wall time on grid n
        for key in CASE_COLUMNS[1:]:
            frame[key] = params[key] if params[key] is not None else np.nan
        frame["case"] = case
        loads.append(frame.reset_index())
    loads = pd.concat(loads, ignore_index=True)
    loads = loads[CASE_COLUMNS + [c for c in loads.columns if c not in CASE_COLUMNS]]
    loads.to_csv(LOADS_CSV, index=False, float_format="%.5g")
    seeds = raw[raw["n"] == finest][["case", "seed", "i", "k"]]
    seeds.to_csv(SEEDS_CSV, index=False, float_format="%.5g")
    if summit_paths:
        summits = pd.concat([pd.read_csv(p) for p in summit_paths], ignore_index=True)
        summits.drop_duplicates(["case", "seed"]).to_csv(SUMMITS_CSV, index=False, float_format="%.4g")


# --- analysis -----------------------------------------------------------------------------------

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
    replicates: every case is resampled with the same seeds (the cases share their seeds' random
    phases), so that ratios of cases get paired intervals. Returns (DataFrame, {case: replicates})."""
    rows, replicates = [], {}
    n_seeds = seeds["seed"].nunique()
    pick = rng.integers(0, n_seeds, size=(BOOT, n_seeds))
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


def _figure(cases: pd.DataFrame, flagged: pd.DataFrame, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from roughcontact.models.paper import zeta_estimate
    from roughcontact.models.zeta_law import zeta_law

    fig, (ax, bx, cx) = plt.subplots(1, 3, figsize=(13, 3.9))
    hs = np.linspace(0.25, 0.95, 50)
    ax.plot(hs, zeta_law(hs), "k-", lw=1, label="flat ζ law (513², zeta_law)")
    ax.plot(hs, 0.8866 * zeta_law(hs), "k--", lw=1, label="0.887 × flat law (contact_scale)")
    ax.plot(hs, zeta_estimate(hs), "k:", lw=1, label="1.7/(H+1) (eq. 13)")
    for label, mask, marker, dx in (("flat, same surfaces", np.isinf(cases["radius"]), "s", 0.008),
                                    ("sphere ζ_s, R 0.5, h 9e-3", cases["case"].str.match(r"^(base|H\d)"), "o", -0.008)):
        sub = cases[mask & cases["zeta"].notna()]
        ax.errorbar(sub["hurst"] + dx, sub["zeta"], [sub["zeta"] - sub["lo"], sub["hi"] - sub["zeta"]], fmt=marker,
                    ms=4, capsize=2, label=label)
    ax.set(xlabel="H", ylabel="ζ", title="branch prefactor (2048², 95 % over seeds)")
    ax.legend(fontsize=7)
    family = ["flatH0.7", "R0.1", "base", "R2.0", "h0.003", "h0.027"]
    for case in family:
        sub = flagged[(flagged["case"] == case) & flagged["on_branch"]]
        if len(sub):
            bx.semilogx(sub["force"], sub["zeta16"], "o-" if case != "flatH0.7" else "s-k", ms=3, label=case)
    bx.set(xlabel="F/(E* L²)", ylabel="ζ_16(F) (branch loads)", title="H 0.7: ζ at each load")
    bx.legend(fontsize=7)
    spheres = cases[np.isfinite(cases["radius"]) & cases["flat_equal"].notna()]
    for label, pattern, marker in (("H sweep", r"^(base|H\d)", "o"), ("R sweep", r"^R", "^"), ("h sweep", r"^h", "v"),
                                   ("longest wave L/m", r"^P", "D"), ("roll-off", r"^r", "x")):
        sub = spheres[spheres["case"].str.match(pattern)]
        cx.errorbar(sub["sampled"], sub["flat_equal"], [sub["flat_equal"] - sub["flat_equal_lo"],
                                                        sub["flat_equal_hi"] - sub["flat_equal"]],
                    fmt=marker, ms=4, capsize=2, label=label)
    cx.axhline(1.0, color="0.5", lw=0.8)
    cx.set(xscale="log", xlabel="√(4 R h_rms)/λ_max (apex region / longest wave)",
           ylabel="ζ_s/ζ_flat at equal F", title="sphere against flat, same H")
    cx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def _fmt(x, digits=3):
    return "–" if x is None or (isinstance(x, float) and not np.isfinite(x)) else f"{x:.{digits}g}"


def _case_label(row) -> str:
    parts = [f"H {row.hurst:g}"]
    parts.append("flat" if np.isinf(row.radius) else f"R {row.radius:g}")
    parts.append(f"h {row.h_rms:.3g}")
    if row.period != 1.0:
        parts.append(f"longest wave {row.period:g} L")
    if np.isfinite(row.rolloff):
        parts.append(f"roll-off {row.rolloff:g} L")
    return ", ".join(parts)


def summarize(loads: pd.DataFrame, seeds: pd.DataFrame):
    """Flagged loads and per-case ζ_s with the flat reference and the hypotheses' numbers."""
    from roughcontact.models.zeta_law import zeta_law

    flagged = branch(loads)
    cases, replicates = case_zeta(flagged, seeds, np.random.default_rng(31))
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
    longest = cases["period"].where(cases["rolloff"].isna(), cases["rolloff"])
    cases["sampled"] = np.sqrt(4.0 * cases["radius"] * cases["h_rms"]) / longest
    cases["clusters_vs_flat"] = [_equal_force(flagged, c, flat_of.get(h, ""), "clusters")
                                 for c, h in zip(cases["case"], cases["hurst"])]
    cases["band_factor"] = [band_factor(h, 2.0 * a, rolloff=r) if np.isfinite(a) else np.nan
                            for h, a, r in zip(cases["hurst"], cases["a"], cases["rolloff"])]
    if SUMMITS_CSV.exists():
        summits = pd.read_csv(SUMMITS_CSV).groupby("case")[["summit", "touch_offset"]].mean()
        cases = cases.join(summits, on="case")
    return flagged, cases


def write_page(loads: pd.DataFrame, seeds: pd.DataFrame) -> Path:
    flagged, cases = summarize(loads, seeds)
    reading = (RESULTS / "fractal_prefactor_reading.txt")
    meta = (RESULTS / "fractal_prefactor_run.txt")
    _figure(cases, flagged, FIGURE)
    lines = ["# The sphere's fractal-branch prefactor", "",
             "Issue 31, item 2: what sets ζ_s, the prefactor of eq. 16's low-force limit on rough spheres. "
             "Generated by `python docs/make_fractal_prefactor.py` from the cached measurements "
             f"(`{LOADS_CSV.name}`, `{SEEDS_CSV.name}`); the method is in the script's docstring.", ""]
    if meta.exists():
        lines += [meta.read_text().strip(), ""]
    lines += ["## ζ_s per case", "",
              "ζ_s: geometric mean over the branch's loads of eq. 16 solved for ζ at the 2048² ensemble "
              "stiffness; [95 % bootstrap over 12 seeds]. ζ_raw: k̄/fractal_stiffness(F, ζ = 1) at the same "
              "loads (no Hertz correction). slope: d ln k̄/d ln F fitted over the branch (1/(H+1) in "
              "brackets). ζ_flat: the same measurement on nominally flat surfaces of the same spectra "
              "and grids (periodic, loads 10⁻⁶…10⁻⁴). Grid: the largest |k̄_1024/k̄_2048 − 1| on the branch.", "",
              "| case | branch F/(E*L²) | loads | cells (2048²) | clusters | ζ_s [95 %] | ζ_raw | slope [1/(H+1)] "
              "| grid | ζ_flat [95 %] | ζ_law | ζ_s/ζ_flat | ζ_s/ζ_law | ζ_s/(0.887 ζ_law) |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in cases.itertuples():
        if not np.isfinite(getattr(row, "zeta", np.nan)):
            lines.append(f"| {_case_label(row)} | none | 0 | | | | | | | | {_fmt(row.zeta_law)} | | | |")
            continue
        lines.append(
            f"| {_case_label(row)} | {row.f_lo:.2g}…{row.f_hi:.2g} | {row.loads} | {row.cells_lo:.0f}–{row.cells_hi:.0f} "
            f"| {row.clusters:.1f} | {row.zeta:.3f} [{row.lo:.3f}, {row.hi:.3f}] | {row.zeta_raw:.3f} "
            f"| {_fmt(row.slope)} [{1 / (row.hurst + 1):.3f}] | {100 * row.grid_change:.1f} % "
            f"| {_fmt(row.zeta_flat)} [{_fmt(row.flat_lo)}, {_fmt(row.flat_hi)}] | {row.zeta_law:.3f} "
            f"| {_fmt(row.zeta / row.zeta_flat)} | {row.zeta / row.zeta_law:.3f} | {row.zeta / (0.8866 * row.zeta_law):.3f} |")
    walls = loads.groupby("case", sort=False)[[c for c in loads.columns if c.startswith("wall")]].sum()
    lines += ["", "Wall time of the ladder's solves and stiffnesses (12 seeds, all loads; the seconds per grid "
              f"summed over every case): " + ", ".join(f"{c[4:]}²: {walls[c].sum():.0f} s" for c in walls.columns)
              + f"; the finest grid costs {walls.iloc[:, -1].sum() / walls.iloc[:, :-1].sum(axis=1).sum():.1f} times "
              "the two coarser together (one run, shared machine)."]
    lines += ["", f"![ζ_s against H, and ζ_s/ζ_flat against the apex region]({FIGURE.name})", ""]
    if reading.exists():
        lines += [reading.read_text().strip(), ""]
    lines += ["## Per load (2048² ensemble means)", "",
              "Branch: ✓ on the fractal branch; c: not converged (|Δ1024| ≥ 2 % or |Δ512| ≥ 6 %); "
              "s: single-asperity regime (one cluster ≥ 90 % of the force); x: above F_tr.", "",
              "| case | F/(E*L²) | F/F_tr | k̄ | Δ512 | Δ1024 | cells | clusters | top cluster's share | "
              "offset/L | ζ_16 | branch |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in flagged.itertuples():
        flag = "✓" if row.on_branch else "".join(c for c, bad in (("c", not row.converged), ("s", row.single),
                                                                     ("x", not row.below)) if bad)
        lines.append(f"| {row.case} | {row.force:.3g} | {row.force / row.f_tr:.3g} | {row.k:.4g} "
                     f"| {100 * (row.k512 / row.k2048 - 1):+.1f} % | {100 * row.grid_change:+.1f} % | {row.cells:.0f} "
                     f"| {row.clusters:.1f} | {row.cluster_share:.2f} | {row.offset:.3f} | {_fmt(row.zeta16)} | {flag} |")
    PAGE.write_text("\n".join(lines) + "\n")
    return PAGE


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--measure", metavar="RAW", help="run every case into RAW.csv first")
    parser.add_argument("--raw", nargs="+", metavar="RAW", help="rebuild the cache from raw rows")
    parser.add_argument("--summits", nargs="+", default=(), metavar="CSV", help="raw rows of --summits runs")
    args = parser.parse_args(argv)
    if args.measure:
        from fractal_prefactor_run import main as run

        start = time.time()
        run(args.measure, [])
        print(f"measured in {time.time() - start:.0f} s")
        args.raw = [args.measure]
    if args.raw:
        reduce_raw(args.raw, args.summits)
    print(write_page(pd.read_csv(LOADS_CSV), pd.read_csv(SEEDS_CSV)))


if __name__ == "__main__":
    main()
