"""Figures of the parameter study (the paper's Figs. 1-4, ζ(H), a collapse plot).

:func:`figure_specs` (no heavy imports) tells the workflow which files the
``figures`` rule writes; :func:`make_figures` draws them (matplotlib, xarray
and pandas are imported there).
"""
from __future__ import annotations

import logging
import math
from pathlib import Path

from . import study

log = logging.getLogger(__name__)

FIG_DIR = "results/figures"
CAPTIONS = "../report"  # relative to workflow/rules/


def _tag(hurst, radius, h_rms) -> str:
    return f"H{study.format_value(hurst)}_R{study.format_value(radius)}_h{study.format_value(h_rms)}"


def figure_specs(cfg: dict) -> list[dict]:
    """One dict per figure: path, caption (relative to workflow/rules), category, labels."""
    specs = [
        {"key": "fig1", "path": f"{FIG_DIR}/fig1_surface.png", "caption": "fig1.rst",
         "category": "Surfaces", "labels": {"figure": "Fig. 1 self-affine surface"}},
        {"key": "fig2", "path": f"{FIG_DIR}/fig2_rough_sphere.png", "caption": "fig2.rst",
         "category": "Surfaces", "labels": {"figure": "Fig. 2 rough sphere"}},
    ]
    for hurst, radius, h in study.combinations(cfg):
        if math.isfinite(radius):
            specs.append({
                "key": ("fig3", hurst, radius, h),
                "path": f"{FIG_DIR}/fig3_{_tag(hurst, radius, h)}.png", "caption": "fig3.rst",
                "category": "Fig. 3 stiffness vs force",
                "labels": {"figure": "Fig. 3", "H": f"{hurst:g}", "R": f"{radius:g}", "h_rms": f"{h:g}"},
            })
    specs += [
        {"key": "fig4", "path": f"{FIG_DIR}/fig4_profiles.png", "caption": "fig4.rst",
         "category": "Surfaces", "labels": {"figure": "Fig. 4 equivalent profiles"}},
        {"key": "zeta", "path": f"{FIG_DIR}/zeta.png", "caption": "zeta.rst",
         "category": "zeta(H) and collapse", "labels": {"figure": "zeta(H)"}},
    ]
    if any(math.isfinite(r) for r in cfg["radius"]):
        specs.append({"key": "collapse", "path": f"{FIG_DIR}/collapse.png", "caption": "collapse.rst",
                      "category": "zeta(H) and collapse", "labels": {"figure": "collapse"}})
    for spec in specs:
        spec["caption"] = f"{CAPTIONS}/{spec['caption']}"
    return specs


def _pick(values, preferred):
    return preferred if preferred in values else values[len(values) // 2]


def make_figures(cfg, ensemble_nc, zeta_csv, crossover_csv, outputs=None):
    """Draw every figure of :func:`figure_specs` (to *outputs*, same order, if given)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    import pandas as pd

    from . import analysis, provenance, surfaces, theory

    specs = figure_specs(cfg)
    paths = list(outputs) if outputs is not None else [s["path"] for s in specs]
    L, E, n = cfg["grid"]["length"], cfg["e_star"], cfg["grid"]["n"]
    zeta_df = pd.read_csv(zeta_csv)
    cross = pd.read_csv(crossover_csv) if Path(crossover_csv).stat().st_size > 1 else pd.DataFrame()
    zeta_of = dict(zip(zeta_df["hurst"], zeta_df["zeta"]))
    ens = analysis.read_groups(ensemble_nc).get("sphere")
    min_cells = cfg["fit"]["zeta"]["min_cells"]
    H0 = _pick(cfg["hurst"], 0.7)
    h0 = _pick(cfg["h_rms"], 9e-3)
    finite = [r for r in cfg["radius"] if math.isfinite(r)]
    R0 = _pick(finite, 0.5) if finite else 0.5
    seed0 = cfg["seeds"][0]

    def save(fig, path):
        with provenance.atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=110, format="png")
        plt.close(fig)

    def zeta_used(hurst):
        z = zeta_of.get(hurst, math.nan)
        return z if math.isfinite(z) else float(theory.zeta_estimate(hurst))

    for spec, path in zip(specs, paths):
        key = spec["key"]
        if key == "fig1":
            z = surfaces.self_affine(n, hurst=H0, h_rms=h0, length=L, seed=seed0)
            fig, (a, b) = plt.subplots(1, 2, figsize=(9, 4), gridspec_kw={"width_ratios": [1, 1.4]})
            im = a.imshow(z.T, cmap="gray", origin="lower", extent=(0, L, 0, L))
            fig.colorbar(im, ax=a, label="z")
            a.set(title=f"(a) H = {H0:g}, h_rms = {h0:g}, seed {seed0}", xlabel="x", ylabel="y")
            x = (np.arange(n) + 0.5) * L / n
            b.plot(x, z[:, n // 2], lw=0.8)
            b.set(title="(b) cut at y = L/2", xlabel="x", ylabel="z")
            fig.tight_layout()
            save(fig, path)
        elif key == "fig2":
            z = surfaces.rough_sphere(n, radius=R0, hurst=H0, h_rms=h0, length=L, seed=seed0)
            x = (np.arange(n) - n // 2) * L / n
            c = slice(n // 4, n - n // 4)  # central half: the roughness stays visible
            X, Y = np.meshgrid(x[c], x[c], indexing="ij")
            zc = z[c, c]
            step = max(1, zc.shape[0] // 96)
            fig = plt.figure(figsize=(6, 5))
            ax = fig.add_subplot(projection="3d")
            ax.plot_surface(X[::step, ::step], Y[::step, ::step], zc[::step, ::step], cmap="viridis",
                            linewidth=0, antialiased=False)
            ax.set(title=f"rough sphere R = {R0:g}, H = {H0:g}, h_rms = {h0:g} (central half)",
                   xlabel="x", ylabel="y", zlabel="z")
            save(fig, path)
        elif key[0] == "fig3":
            _, hurst, radius, h = key
            sub = ens.sel(hurst=hurst, radius=radius, h_rms=h)
            F = sub["force"].values / (E * L**2)
            k = sub["k_mean"].values / (E * L)
            err = np.nan_to_num(sub["k_sem"].values / (E * L))
            cells = sub["contact_cells_mean"].values
            res = cells >= min_cells
            zf = zeta_used(hurst)
            fig, ax = plt.subplots(figsize=(6, 4.6))
            ax.errorbar(F[res], k[res], yerr=err[res], fmt="o", color="C3", ms=4, capsize=2,
                        label=f"BEM mean of {ens.attrs['n_seeds']} seeds")
            if (~res).any():
                ax.errorbar(F[~res], k[~res], yerr=err[~res], fmt="o", mfc="none", color="C3", ms=4, capsize=2,
                            label=f"< {min_cells} contact cells (unresolved)")
            Fg = np.geomspace(F.min() / 3, F.max() * 3, 200)
            ax.plot(Fg, theory.stiffness_from_force(Fg * E * L**2, radius, hurst, h, L, E, zf) / (E * L), "k-",
                    label=f"eq. 16, fitted zeta = {zf:.3g}")
            ze = float(theory.zeta_estimate(hurst))
            ax.plot(Fg, theory.stiffness_from_force(Fg * E * L**2, radius, hurst, h, L, E, ze) / (E * L), "k:",
                    lw=1, label=f"eq. 16, zeta = 1.7/(H+1) = {ze:.3g}")
            ax.plot(Fg, theory.hertz_stiffness(Fg * E * L**2, radius, E) / (E * L), "--", color="C0",
                    label="Hertz, eq. 9 (slope 1/3)")
            ax.plot(Fg, theory.fractal_stiffness(Fg * E * L**2, hurst, h, L, E, zf) / (E * L), "--", color="C2",
                    label=f"roughness, eq. 11 (slope {1 / (hurst + 1):.3f})")
            row = cross[(np.isclose(cross["hurst"], hurst)) & (np.isclose(cross["radius"], radius))
                        & (np.isclose(cross["h_rms"], h))] if len(cross) else cross
            if len(row):
                r = row.iloc[0]
                fp = float(r["Ftr_pred_fit"]) if math.isfinite(r["Ftr_pred_fit"]) else float(r["Ftr_pred_estimate"])
                ax.axvline(fp, color="0.4", ls="-.", lw=1, label=f"F_tr predicted (eq. 17) = {fp:.2g}")
                if math.isfinite(r["Ftr_ci_low"]):
                    ax.axvspan(r["Ftr_ci_low"], r["Ftr_ci_high"], color="C3", alpha=0.15, lw=0,
                               label=f"F_tr measured = {r['Ftr_measured']:.2g} "
                                     f"({r['Ftr_ci_low']:.2g}-{r['Ftr_ci_high']:.2g}, 95 %): {r['verdict_fit']}")
                    ax.axvline(r["Ftr_measured"], color="C3", ls=":", lw=1.2)
            ax.set(xscale="log", yscale="log", xlabel="F / (E* L²)", ylabel="k / (E* L)",
                   title=f"H = {hurst:g}, R = {radius:g}, h_rms = {h:g}, L = {L:g}, n = {n}")
            ax.legend(fontsize=7, loc="lower right")
            fig.tight_layout()
            save(fig, path)
        elif key == "fig4":
            r = np.linspace(-0.2 * L, 0.2 * L, 801)  # where z_p and z_s are of similar size
            zp = r**2 / (2 * R0)
            q3d = theory.profile_prefactor(H0, h0, L, zeta_used(H0))
            zs = q3d * np.abs(r) ** H0
            fig, axes = plt.subplots(1, 3, figsize=(10, 3.2))
            for ax, zz, title in zip(axes, (zp, zs, zp + zs),
                                     ("(a) z_p = r²/(2R)", "(b) z_s = Q3D |r|^H (eq. 6, 14)", "(c) z_c = z_p + z_s (eq. 15)")):
                ax.plot(r, zz)
                ax.set(title=title, xlabel="r")
            axes[0].set_ylabel("z")
            fig.suptitle(f"R = {R0:g}, H = {H0:g}, h_rms = {h0:g}, zeta = {zeta_used(H0):.3g}", fontsize=9)
            fig.tight_layout()
            save(fig, path)
        elif key == "zeta":
            fig, ax = plt.subplots(figsize=(5.5, 4))
            d = zeta_df.sort_values("hurst")
            yerr = np.array([d["zeta"] - d["zeta_ci_low"], d["zeta_ci_high"] - d["zeta"]])
            ax.errorbar(d["hurst"], d["zeta"], yerr=np.nan_to_num(np.abs(yerr)), fmt="o", capsize=3, color="C3",
                        label=f"fit ({d['source'].iloc[0]}), {100 * d['confidence'].iloc[0]:.0f}% bootstrap CI")
            hg = np.linspace(0.05, 1.95, 200)
            ax.plot(hg, theory.zeta_estimate(hg), "k-", label="1.7/(H+1), eq. 13")
            ax.set(xlabel="H", ylabel="zeta(H)", xlim=(0, 2) if d["hurst"].max() > 1 else (0, 1))
            ax.legend(fontsize=7)
            fig.tight_layout()
            save(fig, path)
        elif key == "collapse":
            fig, ax = plt.subplots(figsize=(6, 4.6))
            y = np.geomspace(0.05, 30, 300)
            for j, hurst in enumerate(cfg["hurst"]):
                ax.plot(y**3 + y ** (hurst + 1), y, "-", color=f"C{j}", lw=1,
                        label=f"eq. 16, H = {hurst:g}: F/F_tr = y³ + y^(H+1)")
                for radius in finite:
                    for h in cfg["h_rms"]:
                        zf = zeta_used(hurst)
                        ftr = theory.crossover_force(radius, hurst, h, L, E, zf)
                        ktr = theory.hertz_stiffness(ftr, radius, E)
                        sub = ens.sel(hurst=hurst, radius=radius, h_rms=h)
                        ok = sub["contact_cells_mean"].values >= min_cells
                        ax.plot(sub["force"].values[ok] / ftr, sub["k_mean"].values[ok] / ktr, "o", ms=3,
                                color=f"C{j}", alpha=0.7)
            ax.set(xscale="log", yscale="log", xlabel="F / F_tr", ylabel="k / k_tr",
                   title="all sphere runs (ensemble means, >= min_cells) over eq. 16")
            ax.legend(fontsize=7)
            fig.tight_layout()
            save(fig, path)
    log.info("wrote %s", ", ".join(paths))
