"""The rough sphere's fractal-branch prefactor ζ_s (issue 31, item 2): ``docs/results/fractal_prefactor.md``.

    PYTHONPATH=src nice -n 10 python docs/make_fractal_prefactor.py --measure RAW.csv   # ~1 h on 2 shared cores
    PYTHONPATH=src python docs/make_fractal_prefactor.py --raw RAW.csv [RAW2.csv ...]    # cache from raw rows
    PYTHONPATH=src python docs/make_fractal_prefactor.py                                 # page from the cache

``--measure`` presses every case of ``fractal_prefactor_run.CASES`` (12 seeds, the same surfaces on
512², 1024² and 2048²) and writes one row per (case, seed, grid, load) to RAW.csv (about 1.5 MB,
not kept). The page's run added 24 seeds on 2048² alone to 18 cases and the first-touch heights::

    python docs/fractal_prefactor_run.py EXTRA.csv base R2.0 R0.1 flatH0.7 h0.003 h0.027 P0.5 \
        H0.9 H0.5 H0.3 R1.0 R0.2 R4.0 h0.081 H0.8 H0.6 H0.4 P0.25 --grids 2048 --seeds 12:36
    python docs/fractal_prefactor_run.py SUMMITS.csv --summits --grids 2048 --seeds 0:12
    python docs/fractal_prefactor_run.py SUMMITS2.csv base R2.0 R0.1 h0.003 h0.027 flatH0.7 --summits \
        --grids 2048 --seeds 12:36
    python docs/make_fractal_prefactor.py --raw RAW.csv EXTRA.csv --summits SUMMITS.csv SUMMITS2.csv

``--raw`` reduces those rows to the cached CSVs under ``docs/results/``:
``fractal_prefactor_loads.csv`` (per case and load: the ensemble means per grid, the contact's
descriptors on 2048²) and ``fractal_prefactor_seeds.csv`` (per case, seed and load with at least
``SEED_CELLS`` mean contact cells: k on 2048², for the bootstrap), and ``fractal_prefactor_summits.csv`` (per case and seed: the first touch). The page, its
table and its figure are computed from the cache alone.

Definitions (L = E* = 1). ζ_s(F) is eq. 16 solved for ζ at the measured ensemble stiffness k̄(F):
``ζ_16(F) = k̄ / ((F − k̄³/(6R))/h)^(1/(H+1))`` (the Hertz force at the same stiffness removed, so
that eq. 16's low-force limit is read at every load of the branch); ``ζ_raw(F) = k̄/fractal(F, ζ=1)``
is the plain ratio, without that correction. The fractal branch are the loads (i) at or below
F_tr (eq. 17, flat ζ law), (ii) grid-converged: |k̄_1024/k̄_2048 − 1| < 2 % and
|k̄_512/k̄_2048 − 1| < 6 % (a first-order sequence; a 2 % change that crosses a non-monotone one is not
convergence), (iii) out of the
single-asperity regime: one cluster of patches (patches closer than 0.004 L merged) carries less
than ``fractal_prefactor_analysis.SINGLE`` of the force on average. ζ_s of a case is the geometric mean of ζ_16 over its
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

from fractal_prefactor_analysis import calibration_cases, fit_touch_model, summarize  # noqa: E402

CASE_COLUMNS = ["case", "hurst", "radius", "h_rms", "period", "rolloff"]
#: the per-seed cache keeps the loads with at least this many mean contact cells on 2048² (no branch
#: load has fewer than 30: below, the 1024² and 2048² ensembles differ by 19 % in the median)
SEED_CELLS = 10


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
    # per seed only where a branch can be (at least SEED_CELLS mean contact cells on the finest grid),
    # to keep the cache small; the loads' ensemble means above cover every load
    seeds = raw[raw["n"] == finest][["case", "seed", "i", "k"]]
    keep = loads.loc[loads["cells"] >= SEED_CELLS, ["case", "i"]]
    seeds = seeds.merge(keep, on=["case", "i"])
    seeds.to_csv(SEEDS_CSV, index=False, float_format="%.5g")
    # the first touch: from --summits runs, and from the raw rows that carry it (later runs)
    parts = [pd.read_csv(p) for p in summit_paths]
    if "summit" in raw:
        parts.append(raw[(raw["n"] == finest) & raw["summit"].notna()][["case", "seed", "summit", "touch_offset"]])
    if parts:
        summits = pd.concat(parts, ignore_index=True).drop_duplicates(["case", "seed"])
        summits.to_csv(SUMMITS_CSV, index=False, float_format="%.4g")


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
    family = ["flatH0.7", "R0.1", "base", "R2.0", "R4.0", "h0.003", "h0.081"]
    for case in family:
        sub = flagged[(flagged["case"] == case) & flagged["on_branch"]]
        if len(sub):
            bx.semilogx(sub["force"], sub["zeta16"], "o-" if case != "flatH0.7" else "s-k", ms=3, label=case)
    bx.set(xlabel="F/(E* L²)", ylabel="ζ_16(F) (branch loads)", title="H 0.7: ζ at each load")
    bx.legend(fontsize=7)
    spheres = cases[np.isfinite(cases["radius"]) & cases["zeta"].notna() & cases["rolloff"].isna()]
    for label, pattern, marker in (("H sweep (0.3-0.9)", r"^(base|H\d)", "o"), ("R sweep, H 0.7", r"^R", "^"),
                                   ("h sweep, H 0.7", r"^h", "v"), ("longest wave L/2, L/4", r"^P", "D")):
        sub = spheres[spheres["case"].str.match(pattern)]
        cx.errorbar(sub["sampled"], sub["zeta"] / sub["zeta_law"], [(sub["zeta"] - sub["lo"]) / sub["zeta_law"],
                                                                    (sub["hi"] - sub["zeta"]) / sub["zeta_law"]],
                    fmt=marker, ms=4, capsize=2, label=label)
    cx.axhline(0.8866, color="k", ls="--", lw=0.8, label="contact_scale's 0.887")
    cx.set(xlim=(0, 0.45), xlabel="√(4 R h_rms)/L (apex region against the cell)",
           ylabel="ζ_s / ζ_law(H)", title="sphere's ζ against the flat law")
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


def write_page(loads: pd.DataFrame, seeds: pd.DataFrame) -> Path:
    flagged, cases = summarize(loads, seeds)
    beta, c_free, beta_free = fit_touch_model(cases)
    cases["touch_model"] = cases["zeta_law"] * np.exp(-beta * cases["summit"])
    reading = (RESULTS / "fractal_prefactor_reading.txt")
    meta = (RESULTS / "fractal_prefactor_run.txt")
    _figure(cases, flagged, FIGURE)
    lines = ["# The sphere's fractal-branch prefactor", "",
             "Issue 31, item 2: what sets ζ_s, the prefactor of eq. 16's low-force limit on rough spheres. "
             "Generated by `python docs/make_fractal_prefactor.py` from the cached measurements "
             f"(`{LOADS_CSV.name}`, `{SEEDS_CSV.name}`); the method is in the script's docstring.", ""]
    if meta.exists():
        lines += [meta.read_text().strip(), ""]
    spheres = flagged[np.isfinite(flagged["radius"])].copy()
    bins = [0, 10, 30, 100, 300, 1000, np.inf]
    spheres["bin"] = pd.cut(spheres["cells"], bins, right=False)
    spheres["d1024"] = spheres["grid_change"].abs() * 100
    spheres["d512"] = (spheres["k512"] / spheres["k2048"] - 1).abs() * 100
    table = spheres.groupby("bin", observed=True).agg(loads=("d1024", "size"), d512=("d512", "median"),
                                                       d1024=("d1024", "median"), d1024_90=("d1024", lambda v: v.quantile(0.9)),
                                                       converged=("converged", "mean"), single=("single", "mean"))
    lines += ["## Convergence", "",
              "The same surfaces (generated on 2048², `realization_of`) on 512², 1024² and 2048², every sphere "
              "case, 12 seeds: the ensemble mean's change against 2048² by the 2048² grid's mean contact cells "
              "(median over the loads; Δ1024's 90 % quantile), the share of loads that pass the branch's "
              "convergence test and the share in the single-asperity regime.", "",
              "| contact cells (2048²) | loads | median \|Δ512\| | median \|Δ1024\| | 90 % \|Δ1024\| | converged | single-asperity |",
              "|---|---|---|---|---|---|---|"]
    for interval, r in table.iterrows():
        lines.append(f"| {interval.left:g}–{interval.right:g} | {r.loads:.0f} | {r.d512:.1f} % | {r.d1024:.1f} % "
                     f"| {r.d1024_90:.1f} % | {100 * r.converged:.0f} % | {100 * r.single:.0f} % |")
    lines += ["", "## ζ_s per case", "",
              "ζ_s: geometric mean over the branch's loads of eq. 16 solved for ζ at the 2048² ensemble "
              "stiffness; [95 % percentile bootstrap over the seeds, 2000 resamples]. ζ_raw: k̄/fractal_stiffness(F, ζ = 1) at the same "
              "loads (no Hertz correction). slope: d ln k̄/d ln F fitted over the branch (1/(H+1) in "
              "brackets). ζ_flat: the same measurement on nominally flat surfaces of the same spectra "
              "and grids (periodic, loads 10⁻⁶…10⁻⁴). Grid: the largest |k̄_1024/k̄_2048 − 1| on the branch.", "",
              "| case | seeds | branch F/(E*L²) | loads | cells (2048²) | clusters | ζ_s [95 %] | ζ_raw | slope [1/(H+1)] "
              "| grid | ζ_flat [95 %] | ζ_law | ζ_s/ζ_flat (each on its own branch) | ζ_s/ζ_law | ζ_s/(0.887 ζ_law) |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for row in cases.itertuples():
        if not np.isfinite(getattr(row, "zeta", np.nan)):
            lines.append(f"| {_case_label(row)} | | none | 0 | | | | | | | | {_fmt(row.zeta_law)} | | | |")
            continue
        lines.append(
            f"| {_case_label(row)} | {row.seeds:.0f} | {row.f_lo:.2g}…{row.f_hi:.2g} | {row.loads} | {row.cells_lo:.0f}–{row.cells_hi:.0f} "
            f"| {row.clusters:.1f} | {row.zeta:.3f} [{row.lo:.3f}, {row.hi:.3f}] | {row.zeta_raw:.3f} "
            f"| {_fmt(row.slope)} [{1 / (row.hurst + 1):.3f}] | {100 * row.grid_change:.1f} % "
            f"| {_fmt(row.zeta_flat)} [{_fmt(row.flat_lo)}, {_fmt(row.flat_hi)}] | {row.zeta_law:.3f} "
            f"| {_fmt(row.zeta / row.zeta_flat)} | {row.zeta / row.zeta_law:.3f} | {row.zeta / (0.8866 * row.zeta_law):.3f} |")
    walls = loads.groupby("case", sort=False)[[c for c in loads.columns if c.startswith("wall")]].sum()
    lines += ["", "Wall time of the ladder's solves and stiffnesses (12 seeds, all loads; the seconds per grid "
              "summed over every case): " + ", ".join(f"{c[4:]}²: {walls[c].sum():.0f} s" for c in walls.columns)
              + f"; the finest grid costs {walls.iloc[:, -1].sum() / walls.iloc[:, :-1].sum(axis=1).sum():.1f} times "
              "the two coarser together (one run, shared machine)."]
    lines += ["", f"![ζ_s against H (left); ζ_16 at each branch load, H 0.7 (middle); ζ_s/ζ_law against the apex region √(4Rh)/L (right)]({FIGURE.name})", ""]
    lines += ["## The hypotheses' numbers", "",
              "Per sphere: ζ_s/ζ_flat at equal F (the flat ζ_16(F) of the same H, surfaces and grids, "
              "ln-interpolated to the sphere's branch loads, held at its end values beyond them; [95 %]); "
              "clusters/flat: the sphere's clusters over the flat surface's at the same F; (a) the Hertz "
              "pressure factor (3/2)^s/(1+s/2), s = 1/(H+1); (c) eq. 11 with (h, L) → (h_λ, λ = 2a), a = k̄/(2E*), "
              "against eq. 11 (the 2048² grid's modes); √(4Rh)/L: the apex region (where the sphere "
              "has dropped by 2 h_rms, h_rms the roughness's own) against the cell; u: the roughness's height at the first "
              "touch in units of its rms (12 seeds; `fractal_prefactor_summits.csv`); offset: the first "
              "touch's distance from the apex; model: a candidate tested and not kept, ζ_law(H)·exp(−βu), β fitted here "
              f"(β = {beta:.4f}; with a free intercept c·exp(−β′u): c = {c_free:.3f}, β′ = {beta_free:.4f}), "
              "fitted on the spheres marked *.", "",
              "| case | ζ_s/ζ_flat at equal F [95 %] | clusters/flat | (a) | (c) | √(4Rh)/L | u | offset/L "
              "| ζ_s | model | ζ_s/model − 1 |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    fitted = calibration_cases(cases)
    for row, fit in zip(cases.itertuples(), fitted):
        if np.isinf(row.radius) or not np.isfinite(getattr(row, "zeta", np.nan)):
            continue
        lines.append(
            f"| {row.case}{' *' if fit else ''} | {_fmt(row.flat_equal)} [{_fmt(row.flat_equal_lo)}, {_fmt(row.flat_equal_hi)}] "
            f"| {_fmt(row.clusters_vs_flat)} | {row.pressure_factor:.3f} | {_fmt(row.band_factor)} | {row.sampled:.3f} "
            f"| {_fmt(row.summit)} | {_fmt(row.touch_offset)} | {row.zeta:.3f} | {_fmt(row.touch_model)} "
            f"| {_fmt(100 * (row.zeta / row.touch_model - 1), 2)} % |")
    flats = cases[np.isinf(cases["radius"])]
    if "summit" in cases and flats["summit"].notna().any():
        lines += ["", "Flat surfaces' first touch (their highest point): u = "
                  + ", ".join(f"{r.summit:.2f} (H {r.hurst:g})" for r in flats.itertuples() if np.isfinite(r.summit))
                  + "; the model's ζ_law·exp(−βu) there: "
                  + ", ".join(f"{r.zeta_law * np.exp(-beta * r.summit):.3f} (H {r.hurst:g})"
                              for r in flats.itertuples() if np.isfinite(r.summit)) + "."]
    lines.append("")
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
