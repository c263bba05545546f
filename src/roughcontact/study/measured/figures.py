"""The report figures of one measured scan: height map, spectrum with its fit, k(F) with the models.

What the ``measured_figures`` rule draws from the files of
:func:`roughcontact.study.measured.prepare_surface`,
:func:`roughcontact.study.measured.merge_surface` and
:func:`roughcontact.study.measured.spectrum.run_spectrum`. matplotlib and xarray are imported
inside.
"""
from __future__ import annotations

import math

import numpy as np

from ..plotting import pyplot, save_png
from ..study_settings import StudySettings

__all__ = ["make_figures", "make_spectrum_figure", "draw_heights", "draw_spectrum", "draw_stiffness"]

#: line styles of the models' predictions, in the order of the spectrum file's ``model`` coordinate
#: (the registry's, :mod:`roughcontact.models.scorecard`), repeated if there are more models
LINE_STYLES = (":", "--", (0, (3, 1, 1, 1, 1, 1)), (0, (5, 1)), (0, (5, 1, 1, 1)), (0, (1, 2)), "-.")


def draw_heights(ax, surface_file, name: str):
    """The measured heights ``h = −z`` (nm) of the scan's square on *ax*, tiles outlined."""
    from .jobs import read_surface

    heights, length, attrs = read_surface(surface_file)
    unit = attrs["units_length"]
    from .config import to_metres

    nm = to_metres(unit) / 1e-9
    image = ax.imshow(-heights.T * nm, origin="lower", extent=(0, length, 0, length), cmap="viridis")
    tile = int(attrs["tile"])
    n = heights.shape[0]
    for k in range(1, n // tile):
        ax.axvline(k * tile * length / n, color="w", lw=0.6)
        ax.axhline(k * tile * length / n, color="w", lw=0.6)
    ax.set_xlabel(f"x ({unit})")
    ax.set_ylabel(f"y ({unit})")
    ax.set_title(f"{name}: {attrs.get('file', '')}, Sq = {float(np.std(heights)) * nm:.3g} nm, "
                 f"{(n // tile) ** 2} tiles of {tile}²", fontsize=9)
    return image


def draw_spectrum(ax, spectrum_file, unit: str):
    """The radially averaged spectrum, the fit's bins and the fitted power law over its band."""
    from ..io import read_groups

    ds = read_groups(spectrum_file)["spectrum"]
    a = ds.attrs
    ax.loglog(ds["q"].values, ds["C"].values, ".", color="0.6", ms=1.5, label="shells (mean over tiles)")
    ax.loglog(ds["fit_q"].values, ds["fit_c"].values, "o", color="C0", ms=4, label="log bins")
    q = np.geomspace(float(a["q_min"]), float(a["q_max"]), 50)
    power = float(a["prefactor_persson"]) * q ** (-2 * float(a["hurst"]) - 2)
    ax.loglog(q, power, "-", color="C3",
              label=f"H = {float(a['hurst']):.3g} [{float(a['hurst_ci_low']):.3g}, {float(a['hurst_ci_high']):.3g}]")
    ax.axvspan(float(a["q_min"]), float(a["q_max"]), color="C3", alpha=0.08, lw=0)
    ax.set_xlabel(f"wavenumber q (rad/{unit})")
    ax.set_ylabel(f"C(q) ({unit}^4)")
    ax.legend(fontsize=7)


def draw_stiffness(ax, merged_file, study: StudySettings, spectrum_file=None):
    """k(F) (N, N/m) of every radius: the mean over the tiles, its band, Hertz for spheres, and
    the models' predictions of *spectrum_file* (if given)."""
    from ..io import read_groups

    groups = read_groups(merged_file)
    models = read_groups(spectrum_file) if spectrum_file is not None else {}
    e_pa = None
    colors = iter(["C0", "C1", "C2", "C3", "C4", "C5"])
    for kind in ("sphere", "flat"):
        if kind not in groups:
            continue
        ds = groups[kind]
        radii = ds["radius"].values if kind == "sphere" else [math.inf]
        for radius in radii:
            sub = ds.sel(radius=radius) if kind == "sphere" else ds
            force = sub["force"].values
            color = next(colors)
            flat = "flat (rough punch)" if ds.attrs.get("half_space", "").startswith("free") else "flat (periodic)"
            label = f"R = {radius:g} {study.units.length}" if kind == "sphere" else flat
            ax.loglog(force, sub["k_mean"].values, "o-", color=color, ms=3, label=label)
            if np.all(np.isfinite(sub["k_ci_low"].values)):
                ax.fill_between(force, sub["k_ci_low"].values, sub["k_ci_high"].values, color=color,
                                alpha=0.25, lw=0)
            if kind in models:
                pred = models[kind].sel(radius=radius) if kind == "sphere" else models[kind]
                for i, model in enumerate(pred["model"].values.tolist()):
                    k = pred["stiffness"].sel(model=model).values
                    if np.any(np.isfinite(k)):
                        ax.loglog(pred["force"].values, k, linestyle=LINE_STYLES[i % len(LINE_STYLES)], color=color,
                                  lw=0.9, label=f"{model}" + (f", R = {radius:g}" if kind == "sphere" else ", flat"))
            if kind == "sphere":
                from .config import to_metres, to_pascals

                e_pa = study.e_star * to_pascals(study.units.e_star)
                r_m = float(radius) * to_metres(study.units.length)
                hertz = 2 * e_pa * (3 * force * r_m / (4 * e_pa)) ** (1 / 3)
                ax.loglog(force, hertz, "--", color=color, lw=0.8, label=f"Hertz, R = {radius:g}")
    ax.set_xlabel("normal force F (N)")
    ax.set_ylabel("normal stiffness k (N/m)")
    ax.legend(fontsize=7)
    return groups


def make_figures(study, name: str, surface_file, merged_file, output, spectrum_file=None) -> None:
    """Write *output* ``.heights``, ``.kf`` and (with *spectrum_file*) ``.psd`` (PNG, atomic)
    for the scan *name* of the study (:class:`~roughcontact.study.study_settings.StudySettings`
    or a resolved configuration)."""
    study = StudySettings.of(study)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5.2, 4.4), constrained_layout=True)
    image = draw_heights(ax, surface_file, name)
    fig.colorbar(image, ax=ax, label="measured height h (nm)")
    _save(fig, output.heights)
    if spectrum_file is not None:
        fig, ax = plt.subplots(figsize=(5.2, 4.4), constrained_layout=True)
        draw_spectrum(ax, spectrum_file, study.units.length)
        ax.set_title(f"{name}: power spectrum over the tiles and its self-affine fit", fontsize=9)
        _save(fig, output.psd)
    fig, ax = plt.subplots(figsize=(6.4, 5.0), constrained_layout=True)
    draw_stiffness(ax, merged_file, study, spectrum_file)
    level = 100 * study.fit.zeta.confidence
    ax.set_title(f"{name}: mean over tiles, {level:g} % bootstrap band", fontsize=9)
    _save(fig, output.kf)


def make_spectrum_figure(study, name: str, merged_file, output) -> None:
    """Write *output* ``.kf`` (PNG, atomic): k(F) of the surfaces drawn from the spectrum *name*."""
    study = StudySettings.of(study)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 5.0), constrained_layout=True)
    draw_stiffness(ax, merged_file, study)
    level = 100 * study.fit.zeta.confidence
    ax.set_title(f"{name}: mean over {len(study.seeds)} seeds, {level:g} % bootstrap band", fontsize=9)
    _save(fig, output.kf)


def _save(fig, path) -> None:
    save_png(fig, path, dpi=130)
