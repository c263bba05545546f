"""Figures of the parameter study: the paper's Figs. 1-4, ζ(H) and a collapse plot.

:func:`figure_specs` (no heavy imports) tells the workflow which files the
``figures`` rule writes; :func:`make_figures` draws them, one function per
figure (:data:`DRAW`), from a :class:`Inputs` bundle (matplotlib, xarray and
pandas are imported there). Forces are F/(E* L²), stiffnesses k/(E* L).
"""
from __future__ import annotations

import dataclasses
import logging
import math

from ... import surfaces
from ...models import paper
from ..config import axes
from ..runs import naming as runs
from ..analysis.ensemble import resolved
from ..config.settings import StudySettings
from .crossover_marks import crossover_marks, crossover_row, variant_text
from .plotting import data_limits, fixed_layout, layout_with_legends, legend_below

log = logging.getLogger(__name__)

def _sphere_combos(study: StudySettings) -> list[dict]:
    """Sphere combinations as merged-file coordinates (optional axes as numbers)."""
    L = study.grid.length
    out = []
    for c in runs.combinations(study):
        if c["kind"] == "sphere":
            name = runs.combo_name(c)
            out.append({**{a: runs.coordinate(a, c[a], L) if a in runs.DEFAULTS else c[a]
                           for a in runs.AXES["sphere"]},
                        # the tags of the optional axes off the paper's setting ("" at the paper's setting)
                        "name": name, "variant": name.split("_", 3)[3] if name.count("_") > 2 else ""})
    return out


def figure_specs(study) -> list[dict]:
    """One dict per figure: key, file (a PNG name), caption (an ``.rst`` name), category, labels.
    The figures of a sphere (Figs. 2-4, the collapse) only where the sweep has one (a finite radius).

    The workflow places the files and finds the captions; nothing here knows its folders."""
    study = StudySettings.of(study)
    sphere = any(math.isfinite(r) for r in study.radius)   # Figs. 2 and 4 draw a sphere: none on a flat sweep
    specs = [
        {"key": ("fig1",), "file": "fig1_surface.png", "caption": "fig1.rst",
         "category": "Surfaces", "labels": {"figure": "Fig. 1 self-affine surface"}},
    ]
    if sphere:
        specs.append({"key": ("fig2",), "file": "fig2_rough_sphere.png", "caption": "fig2.rst",
                      "category": "Surfaces", "labels": {"figure": "Fig. 2 rough sphere"}})
    for combo in _sphere_combos(study):
        labels = {"figure": "Fig. 3", "H": f"{combo['hurst']:g}", "R": f"{combo['radius']:g}",
                  "h_rms": f"{combo['h_rms']:g}"}
        if combo["variant"]:
            labels["variant"] = combo["variant"]
        specs.append({"key": ("fig3", combo), "file": f"fig3_{combo['name']}.png", "caption": "fig3.rst",
                      "category": "Fig. 3 stiffness vs force", "labels": labels})
    if sphere:
        specs.append({"key": ("fig4",), "file": "fig4_profiles.png", "caption": "fig4.rst",
                      "category": "Surfaces", "labels": {"figure": "Fig. 4 equivalent profiles"}})
    specs.append({"key": ("zeta",), "file": "zeta.png", "caption": "zeta.rst",
                  "category": "zeta(H) and collapse", "labels": {"figure": "zeta(H)"}})
    if sphere:
        specs.append({"key": ("collapse",), "file": "collapse.png", "caption": "collapse.rst",
                      "category": "zeta(H) and collapse", "labels": {"figure": "collapse"}})
    return specs


def _pick(values, preferred):
    return preferred if preferred in values else values[len(values) // 2]


def shown_combination(study) -> str | None:
    """The name of the sphere combination of Figs. 1, 2 and 4 (H, h_rms, R near the paper's
    0.7, 9e-3, 0.5; the paper's setting of the optional axes), whose Fig. 3 the report's
    landing page shows; None without sphere combinations."""
    study = StudySettings.of(study)
    combos = _sphere_combos(study)
    if not combos:
        return None
    finite = [r for r in study.radius if math.isfinite(r)]
    want = {"hurst": _pick(study.hurst, 0.7), "h_rms": _pick(study.h_rms, 9e-3),
            "radius": _pick(finite, 0.5) if finite else None}
    for combo in combos:
        if not combo["variant"] and all(combo[a] == v for a, v in want.items()):
            return combo["name"]
    return combos[0]["name"]


@dataclasses.dataclass(frozen=True)
class Inputs:
    """What the figures draw from: the study's settings, the sphere ensemble (or None),
    the ζ and crossover tables, the surface shown in Figs. 1, 2 and 4, and the precomputed
    models' curves (the groups of ``model_curves.nc``, or None: computed here)."""

    study: StudySettings
    ensemble: object
    zeta: object
    crossover: object
    hurst: float
    h_rms: float
    radius: float
    seed: int
    curves: dict | None = None

    def _fitted(self, hurst) -> float:
        """ζ(H) of the ζ table at *hurst*; NaN where it has none (no row, no fit, not a number)."""
        if "zeta" not in self.zeta or "hurst" not in self.zeta:
            return math.nan
        try:
            return float(dict(zip(self.zeta["hurst"], self.zeta["zeta"])).get(hurst, math.nan))
        except (TypeError, ValueError):
            return math.nan

    def zeta_fitted(self, hurst) -> bool:
        """Whether ζ(H) was fitted at *hurst* (a finite ``zeta`` in the ζ table)."""
        return math.isfinite(self._fitted(hurst))

    def zeta_used(self, hurst):
        """Fitted ζ(H), or 1.7/(H+1) (eq. 13) where none was fitted."""
        z = self._fitted(hurst)
        return z if math.isfinite(z) else float(paper.zeta_estimate(hurst))

    def zeta_label(self, hurst) -> str:
        """The legend's name of :meth:`zeta_used`: "fitted ζ = …" only where ζ was fitted."""
        if self.zeta_fitted(hurst):
            return f"fitted ζ = {self.zeta_used(hurst):.3g}"
        return f"ζ = 1.7/(H+1) = {self.zeta_used(hurst):.3g} (eq. 13)"


def fig1(plt, inputs: Inputs, _key):
    """Fig. 1: (a) a self-affine surface, (b) a cut through it."""
    import numpy as np

    H0, h0, seed = inputs.hurst, inputs.h_rms, inputs.seed
    L, n = inputs.study.grid.length, inputs.study.grid.n
    z = surfaces.self_affine(n, hurst=H0, h_rms=h0, length=L, seed=seed)
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 4), gridspec_kw={"width_ratios": [1, 1.4]})
    im = a.imshow(z.T, cmap="gray", origin="lower", extent=(0, L, 0, L))
    fig.colorbar(im, ax=a, label="z")
    # two short lines: the square image is narrower than its axes' slot, its title must not reach the colorbar
    a.set_title(f"(a) H = {H0:g}, h_rms = {h0:g}\nseed {seed}", fontsize=10)
    a.set(xlabel="x", ylabel="y")
    b.plot((np.arange(n) + 0.5) * L / n, z[:, n // 2], lw=0.8)
    b.set(title="(b) cut at y = L/2", xlabel="x", ylabel="z")
    fixed_layout(fig, left=0.7, right=0.2, bottom=0.6, top=0.4, wspace=1.45)
    return fig


def fig2(plt, inputs: Inputs, _key):
    """Fig. 2: the rough sphere, central half of the grid."""
    import numpy as np

    H0, h0, R0 = inputs.hurst, inputs.h_rms, inputs.radius
    L, n = inputs.study.grid.length, inputs.study.grid.n
    z = surfaces.rough_sphere(n, radius=R0, hurst=H0, h_rms=h0, length=L, seed=inputs.seed)
    x = (np.arange(n) - n // 2) * L / n
    c = slice(n // 4, n - n // 4)  # central half: the roughness stays visible
    X, Y = np.meshgrid(x[c], x[c], indexing="ij")
    step = max(1, X.shape[0] // 96)
    fig = plt.figure(figsize=(6, 5))
    ax = fig.add_subplot(projection="3d")
    ax.plot_surface(X[::step, ::step], Y[::step, ::step], z[c, c][::step, ::step], cmap="viridis",
                    linewidth=0, antialiased=False)
    ax.set(title=f"rough sphere R = {R0:g}, H = {H0:g}, h_rms = {h0:g} (central half)",
           xlabel="x", ylabel="y", zlabel="z")
    return fig


def fig3(plt, inputs: Inputs, key):
    """Fig. 3 for one sphere combination: the BEM ensemble, eq. 16 (any body),
    both asymptotes and the crossover force predicted (eq. 17 with ζ = 1.7/(H+1) and with the
    fitted ζ, each with crossover.csv's verdict) and measured (95 % interval); beside it,
    where there are any, the curves beyond the paper (Greenwood-Tripp at the paper's setting, the
    loading tangent of a plastic run) with the BEM ensemble and eq. 16 again, so that no panel
    holds more than seven curves. The axes hold the measured values (a curve or force beyond them
    does not stretch them); the legends lie under the panels."""
    import numpy as np

    combo = key[1]
    study = inputs.study
    L, E, n = study.grid.length, study.e_star, study.grid.n
    hurst, radius, h, m = combo["hurst"], combo["radius"], combo["h_rms"], combo["exponent"]
    sub = inputs.ensemble.sel({a: combo[a] for a in runs.AXES["sphere"]})
    F = sub["force"].values / (E * L**2)
    k = sub["k_mean"].values / (E * L)
    err = np.nan_to_num(sub["k_sem"].values / (E * L))
    res = resolved(sub["contact_cells_mean"].values, study.fit.resolved_cells)
    zf = inputs.zeta_used(hurst)
    plastic = "loading_k_mean" in sub and math.isfinite(combo["hardness"])
    beyond = plastic or axes.paper_setting(combo, L)  # a second panel: the curves beyond the paper
    fig, panels = plt.subplots(1, 2 if beyond else 1, figsize=(11, 4.6) if beyond else (6, 4.6), squeeze=False,
                               sharex=True, sharey=True)
    ax, other = panels[0][0], (panels[0][1] if beyond else None)
    Fg = np.geomspace(F.min() / 3, F.max() * 3, 200)
    for target in (ax, other) if beyond else (ax,):
        target.errorbar(F[res], k[res], yerr=err[res], fmt="o", color="C3", ms=4, capsize=2,
                        label=f"BEM mean of {inputs.ensemble.attrs['n_seeds']} seeds")
        if (~res).any():
            target.errorbar(F[~res], k[~res], yerr=err[~res], fmt="o", mfc="none", color="C3", ms=4, capsize=2,
                            label=f"< {study.fit.resolved_cells} contact cells (unresolved)")
    if beyond:
        other.plot(Fg, paper.stiffness_from_force(Fg * E * L**2, radius=radius, hurst=hurst, h_rms=h, length=L, e_star=E, zeta=zf, exponent=m) / (E * L),
                   "k-", lw=1.5, label=f"eq. 16, {inputs.zeta_label(hurst)}")
    loading = None
    if plastic:
        loading = sub["loading_k_mean"].values / (E * L)
        other.plot(F, loading, "s", mfc="none", color="C1", ms=4, label="loading tangent (plastic path)")
    body = "Hertz, eq. 9" if m == 2 else f"smooth body m = {m:g}, eq. 7"
    curves = [(zf, "k-", f"eq. 16, {inputs.zeta_label(hurst)}")]
    if inputs.zeta_fitted(hurst):  # else the same curve: eq. 13 is what eq. 16 already uses
        curves.append((float(paper.zeta_estimate(hurst)), "k:", "eq. 16, ζ = 1.7/(H+1) (eq. 13)"))
    for zeta, style, text in curves:
        ax.plot(Fg, paper.stiffness_from_force(Fg * E * L**2, radius=radius, hurst=hurst, h_rms=h, length=L, e_star=E, zeta=zeta, exponent=m) / (E * L),
                style, lw=1.5 if style == "k-" else 1, label=text)
    ax.plot(Fg, paper.body_stiffness(Fg * E * L**2, radius=radius, e_star=E, exponent=m) / (E * L), "--", color="C0",
            label=f"{body} (slope {1 / (m + 1):.3g})")
    ax.plot(Fg, paper.fractal_stiffness(Fg * E * L**2, hurst=hurst, h_rms=h, length=L, e_star=E, zeta=zf) / (E * L), "--", color="C2",
            label=f"roughness, eq. 11 (slope {1 / (hurst + 1):.3f})")
    if axes.paper_setting(combo, L):  # Greenwood-Tripp on the same spectrum (paraboloid, elastic, no cut)
        from ..analysis.model_curves import gt_curve

        gt = gt_curve(inputs.curves, combo["name"], hurst=hurst, h_rms=h, n=n, length=L, radius=radius, e_star=E)
        shown = (gt.force >= Fg[0] * E * L**2) & (gt.force <= Fg[-1] * E * L**2)
        other.plot(gt.force[shown] / (E * L**2), gt.stiffness[shown] / (E * L), "-.", color="C4", lw=1,
                   label=f"Greenwood-Tripp (mu = {gt.mu:.3g})")
    xlim, ylim = data_limits(F, k, low=np.where(k - err > 0, k - err, np.nan), high=k + err if loading is None
                             else np.concatenate([k + err, loading]))
    ax.set(xscale="log", yscale="log", xlabel="F / (E* L²)", ylabel="k / (E* L)")
    if xlim:
        ax.set_xlim(xlim)
    if ylim:
        ax.set_ylim(ylim)
    row = crossover_row(inputs.crossover, combo)
    if row is not None:
        crossover_marks(ax, row, hurst)
    variant = variant_text(combo, L)
    title = f"H = {hurst:g}, R = {radius:g}, h_rms = {h:g}, L = {L:g}, n = {n}" + (f", {variant}" if variant else "")
    ax.set_title(title, fontsize=10)
    legends = [legend_below(ax, gap=0.62)]
    if beyond:
        other.set(xscale="log", yscale="log", xlabel="F / (E* L²)", title="beyond the paper")
        legends.append(legend_below(other, gap=0.62))
    layout_with_legends(fig, legends, left=0.8, right=0.32, bottom=0.62, top=0.38, wspace=0.36)
    return fig


def fig4(plt, inputs: Inputs, _key):
    """Fig. 4: the parabola, the equivalent profile of the roughness (eqs. 6, 14) and their sum (eq. 15)."""
    import numpy as np

    H0, h0, R0, L = inputs.hurst, inputs.h_rms, inputs.radius, inputs.study.grid.length
    r = np.linspace(-0.2 * L, 0.2 * L, 801)  # where z_p and z_s are of similar size
    profile = {"hurst": H0, "h_rms": h0, "length": L, "zeta": inputs.zeta_used(H0)}
    zs = paper.equivalent_height(r, radius=math.inf, **profile)
    zc = paper.equivalent_height(r, radius=R0, **profile)
    fig, axes = plt.subplots(1, 3, figsize=(10, 3.2))
    for ax, zz, title in zip(axes, (zc - zs, zs, zc),
                             ("(a) z_p = r²/(2R)", "(b) z_s = Q3D |r|^H (eq. 6, 14)", "(c) z_c = z_p + z_s (eq. 15)")):
        ax.plot(r, zz)
        ax.set(title=title, xlabel="r")
    axes[0].set_ylabel("z")
    fig.suptitle(f"R = {R0:g}, H = {H0:g}, h_rms = {h0:g}, {inputs.zeta_label(H0)}", fontsize=9)
    fixed_layout(fig, left=0.78, right=0.18, bottom=0.6, top=0.68, wspace=0.67)
    return fig


def zeta(plt, inputs: Inputs, _key):
    """ζ(H) with its bootstrap interval against 1.7/(H+1) (eq. 13). The legend names the curves
    only (the fit's source in a few words); where ζ was not fitted at some H, a short note in the
    axes says so (the full reason is the ``source`` column of zeta.csv)."""
    import numpy as np

    d = inputs.zeta.sort_values("hurst") if "hurst" in inputs.zeta else inputs.zeta
    fitted = d[np.isfinite(d["zeta"].astype(float))] if len(d) else d
    fig, ax = plt.subplots(figsize=(5.5, 4))
    if len(fitted):
        yerr = np.array([fitted["zeta"] - fitted["zeta_ci_low"], fitted["zeta_ci_high"] - fitted["zeta"]])
        sources = sorted({_zeta_source(s) for s in fitted["source"]})
        ax.errorbar(fitted["hurst"], fitted["zeta"], yerr=np.nan_to_num(np.abs(yerr)), fmt="o", capsize=3,
                    color="C3", label=f"fit ({', '.join(sources)}), "
                                      f"{100 * fitted['confidence'].iloc[0]:.0f}% bootstrap CI")
    hg = np.linspace(0.05, 1.95, 200)
    ax.plot(hg, paper.zeta_estimate(hg), "k-", label="1.7/(H+1), eq. 13")
    top = float(d["hurst"].max()) if len(d) else 1.0
    ax.set(xlabel="H", ylabel="zeta(H)", xlim=(0, 2) if top > 1 else (0, 1))
    missing = d[~d.index.isin(fitted.index)] if len(d) else d
    if len(missing):
        why = sorted({_zeta_source(s) for s in missing["source"]})
        hs = ", ".join(f"{h:g}" for h in missing["hurst"])
        ax.text(0.03, 0.03, f"ζ not fitted at H = {hs}: {'; '.join(why)} (zeta.csv)", transform=ax.transAxes,
                fontsize=7, va="bottom", ha="left", wrap=True, color="0.3")
    ax.legend(fontsize=7, loc="upper right")
    fixed_layout(fig, left=0.7, right=0.28, bottom=0.6, top=0.18)
    return fig


def _zeta_source(text) -> str:
    """A few words of zeta.csv's ``source`` (its text before the first colon or parenthesis):
    where the fit's points came from, or why there is none."""
    text = str(text)
    cut = min((i for i in (text.find(":"), text.find(" (")) if i > 0), default=len(text))
    return text[:cut].strip()


def adhesive(combo: dict) -> bool:
    """Whether a sphere combination is adhesive (a work of adhesion > 0): eq. 16 is adhesion-free."""
    return float(combo.get("work_of_adhesion", 0.0) or 0.0) > 0


def collapse(plt, inputs: Inputs, _key):
    """The elastic, adhesion-free comparison of eq. 16: every sphere combination without adhesion as
    k/k_tr against F/F_tr over the master curves of eq. 16 (the adhesive ones left out, the figure
    says how many), one panel per Hurst exponent and group of combinations (at most ``MAX_CURVES``
    curves a panel, the master curves included), one colour per combination; the master curves
    span the data, the legends lie under the panels."""
    import numpy as np

    from .plotting import MAX_CURVES, chunks, panel_grid

    study = inputs.study
    L, E = study.grid.length, study.e_star
    spheres = _sphere_combos(study)
    left_out = [c for c in spheres if adhesive(c)]
    facets = []
    for hurst in study.hurst:
        mine = [c for c in spheres if c["hurst"] == hurst and not adhesive(c)]
        exponents = sorted({c["exponent"] for c in mine})
        facets += [(hurst, exponents, group) for group in chunks(mine, MAX_CURVES - len(exponents)) if group]
    fig, panels = panel_grid(plt, len(facets), width=5.0, height=4.0, max_columns=3, sharex=True, sharey=True)
    for ax, (hurst, exponents, group) in zip(panels, facets):
        zf = inputs.zeta_used(hurst)
        points, ys = [], {m: [0.05, 30.0] for m in exponents}
        for combo in group:
            m = combo["exponent"]
            ftr = paper.crossover_force(combo["radius"], hurst=hurst, h_rms=combo["h_rms"], length=L, e_star=E, zeta=zf, exponent=m)
            ktr = paper.body_stiffness(ftr, radius=combo["radius"], e_star=E, exponent=m)
            sub = inputs.ensemble.sel({a: combo[a] for a in runs.AXES["sphere"]})
            ok = resolved(sub["contact_cells_mean"].values, study.fit.resolved_cells)
            x, y = sub["force"].values[ok] / ftr, sub["k_mean"].values[ok] / ktr
            points.append((combo, x, y))
            ys[m] += [v for v in y if np.isfinite(v) and v > 0]
        for m in exponents:
            grid = np.geomspace(min(ys[m]) / 2, max(ys[m]) * 2, 300)   # the master curve reaches its points
            ax.plot(grid ** (m + 1) + grid ** (hurst + 1), grid, "k-" if m == 2 else "k--", lw=1,
                    label=f"eq. 16, m = {m:g}: F/F_tr = y^(m+1) + y^(H+1)")
        for i, (combo, x, y) in enumerate(points):
            variant = variant_text(combo, L)
            label = f"R = {combo['radius']:g}, h_rms = {combo['h_rms']:g}" + (f", {variant}" if variant else "")
            ax.plot(x, y, "o", ms=3, color=f"C{i % 10}", alpha=0.8, label=label)
        ax.set(xscale="log", yscale="log", xlabel="F / F_tr", ylabel="k / k_tr (y)", title=f"H = {hurst:g}")
    if not facets:
        panels[0].text(0.5, 0.5, "no adhesion-free sphere combination: eq. 16 has nothing to compare",
                       ha="center", va="center", fontsize=8, wrap=True, transform=panels[0].transAxes)
    title = ("sphere runs over eq. 16: ensemble means at the loads\n"
             f"with >= {study.fit.resolved_cells} contact cells (fit.resolved_cells), ζ of zeta.csv or 1.7/(H+1)")
    if left_out:
        title += (f"\n{len(left_out)} adhesive combination{'s' if len(left_out) > 1 else ''} (w > 0) "
                  "left out: eq. 16 is adhesion-free")
    fig.suptitle(title, fontsize=8)
    top = 0.75 + 0.14 * title.count("\n")
    legends = [legend_below(ax, gap=0.62, fontsize=6) for ax in panels[:len(facets)]]
    layout_with_legends(fig, legends, left=0.8, right=0.18, bottom=0.62, top=top, wspace=0.42, hspace=1.0)
    return fig


#: figure key -> the function that draws it
DRAW = {"fig1": fig1, "fig2": fig2, "fig3": fig3, "fig4": fig4, "zeta": zeta, "collapse": collapse}


def make_figures(study, ensemble_nc, zeta_csv, crossover_csv, outputs, model_curves_nc=None):
    """Draw every figure of :func:`figure_specs` to *outputs* (paths, in the same order);
    *model_curves_nc*: the precomputed models' curves (rule ``model_curves``; ``None``: Greenwood
    and Tripp's curve computed here)."""
    from ..files.io import read_csv, read_groups
    from .plotting import pyplot, save_png

    plt = pyplot()

    study = StudySettings.of(study)
    specs = figure_specs(study)
    paths = list(outputs)
    if len(paths) != len(specs):
        raise ValueError(f"make_figures got {len(paths)} output paths for {len(specs)} figures")
    finite = [r for r in study.radius if math.isfinite(r)]
    inputs = Inputs(
        study=study, ensemble=read_groups(ensemble_nc).get("sphere"), zeta=read_csv(zeta_csv),
        crossover=read_csv(crossover_csv),
        hurst=_pick(study.hurst, 0.7), h_rms=_pick(study.h_rms, 9e-3),
        radius=_pick(finite, 0.5) if finite else math.inf, seed=study.seeds[0],
        curves=read_groups(model_curves_nc) if model_curves_nc else None)
    for spec, path in zip(specs, paths):
        save_png(DRAW[spec["key"][0]](plt, inputs, spec["key"]), path)
    log.info("wrote %s", ", ".join(paths))
