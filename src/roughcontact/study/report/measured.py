"""The report figures of one measured scan: height map, spectrum with its fit, k(F) with the models.

What the ``measured_figures`` and ``spectrum_figures`` rules (:mod:`roughcontact.study.rules.measured_figures`,
:mod:`roughcontact.study.rules.spectrum_figures`) draw from the files of
:func:`roughcontact.study.runs.measured.prepare_surface`,
:func:`roughcontact.study.analysis.measured_merge.merge_surface` and the ``measured_spectrum`` rule
(:func:`roughcontact.study.analysis.measured_spectrum.spectrum_groups`), and the page of the
``measured_scorecard`` rule (:func:`scorecard_page`). matplotlib and xarray are imported inside.
"""
from __future__ import annotations

import math

import numpy as np

from ..analysis import not_modelled as unmodelled
from ..analysis.measured_scorecard import MEASURED_SCORECARD_LEAD, range_note
from .plotting import MAX_CURVES, chunks, panel_grid
from ..config.settings import StudySettings

__all__ = ["draw_heights", "draw_spectrum", "draw_stiffness", "draw_stiffness_figure", "stiffness_panels",
           "scorecard_page", "FIGURE_DPI"]

#: line styles of the models' predictions, in the order of the spectrum file's ``model`` coordinate
#: (the registry's, :mod:`roughcontact.models.scorecard`), repeated if there are more models; one
#: colour per model too (the measurement is black, Hertz grey)
LINE_STYLES = (":", "--", (0, (3, 1, 1, 1, 1, 1)), (0, (5, 1)), (0, (5, 1, 1, 1)), (0, (1, 2)), "-.")


def draw_heights(ax, surface_file, name: str):
    """The measured heights ``h = −z`` (nm) of the scan's square on *ax*, tiles outlined."""
    from ..runs.measured import read_surface

    heights, length, attrs = read_surface(surface_file)
    unit = attrs["units_length"]
    from ..config.measured import to_metres

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
    from ..files.io import read_groups

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


def stiffness_panels(groups: dict, models: dict) -> list[tuple]:
    """The panels of the k(F) figure: one ``(kind, radius, model names)`` per surface (every
    radius, then the flat surface) and group of at most ``MAX_CURVES - 2`` models (the
    measurement and Hertz are on every panel), so that no panel holds more than
    :data:`~roughcontact.study.report.plotting.MAX_CURVES` curves."""
    panels = []
    for kind in ("sphere", "flat"):
        if kind not in groups:
            continue
        ds = groups[kind]
        radii = ds["radius"].values.tolist() if kind == "sphere" else [math.inf]
        for radius in radii:
            names = []
            if kind in models:
                pred = models[kind].sel(radius=radius) if kind == "sphere" else models[kind]
                names = [m for m in pred["model"].values.tolist()
                         if np.any(np.isfinite(pred["stiffness"].sel(model=m).values))]
            for group in chunks(names, MAX_CURVES - 2):
                panels.append((kind, radius, group))
    return panels


def draw_stiffness_panel(ax, groups: dict, models: dict, study: StudySettings, panel) -> None:
    """One panel of :func:`stiffness_panels` on *ax*: k(F) (N, N/m) of one surface, the mean over
    the tiles (or seeds) with its band, Hertz for a sphere, and the models' predictions named
    (``(outside its range)`` where the scan lies outside the model's stated range,
    :func:`roughcontact.study.analysis.measured_scorecard.outside_range`)."""
    kind, radius, names = panel
    ds = groups[kind]
    sub = ds.sel(radius=radius) if kind == "sphere" else ds
    force = sub["force"].values
    flat = "flat (rough punch)" if ds.attrs.get("half_space", "").startswith("free") else "flat (periodic)"
    surface = f"R = {radius:g} {study.units.length}" if kind == "sphere" else flat
    ax.loglog(force, sub["k_mean"].values, "o-", color="k", ms=3, lw=1, label=f"measured, {surface}")
    if np.all(np.isfinite(sub["k_ci_low"].values)):
        ax.fill_between(force, sub["k_ci_low"].values, sub["k_ci_high"].values, color="0.5", alpha=0.3, lw=0)
    if names:
        from ..analysis.measured_scorecard import outside_range, scan_values

        pred = models[kind].sel(radius=radius) if kind == "sphere" else models[kind]
        order = pred["model"].values.tolist()
        scan = scan_values(models["spectrum"].attrs if "spectrum" in models else {})
        for model in names:
            i = order.index(model)
            # a model whose stated range the scan lies outside of is named so (the scorecard's outside_range)
            flag = " (outside its range)" if outside_range(model, scan) else ""
            ax.loglog(pred["force"].values, pred["stiffness"].sel(model=model).values, color=f"C{i % 10}",
                      linestyle=LINE_STYLES[i % len(LINE_STYLES)], lw=1.1, label=model + flag)
    if kind == "sphere":
        from ..config.measured import to_metres, to_pascals

        e_pa = study.e_star * to_pascals(study.units.e_star)
        r_m = float(radius) * to_metres(study.units.length)
        hertz = 2 * e_pa * (3 * force * r_m / (4 * e_pa)) ** (1 / 3)
        ax.loglog(force, hertz, "--", color="0.4", lw=0.8, label="Hertz")
    ax.set_title(surface, fontsize=8)
    ax.set_xlabel("normal force F (N)")
    ax.set_ylabel("normal stiffness k (N/m)")
    ax.legend(fontsize=6.5)


def draw_stiffness(plt, merged_file, study: StudySettings, spectrum_file=None):
    """The k(F) figure: the panels of :func:`stiffness_panels` (one surface and at most
    ``MAX_CURVES - 2`` models each) from the merged file and the models' predictions of
    *spectrum_file* (if given); returns the figure."""
    from ..files.io import read_groups

    groups = read_groups(merged_file)
    models = read_groups(spectrum_file) if spectrum_file is not None else {}
    return draw_stiffness_figure(plt, groups, models, study)


def draw_stiffness_figure(plt, groups: dict, models: dict, study: StudySettings):
    """:func:`draw_stiffness` from the groups already read (``sphere``/``flat`` datasets)."""
    panels = stiffness_panels(groups, models)
    # one row per surface where its models take more than one panel, else three panels a row
    per_surface = max(sum(1 for p in panels if p[:2] == panel[:2]) for panel in panels) if panels else 1
    fig, axes = panel_grid(plt, len(panels), width=4.4, height=3.6,
                           max_columns=per_surface if per_surface > 1 else 3, constrained_layout=True)
    for ax, panel in zip(axes, panels):
        draw_stiffness_panel(ax, groups, models, study, panel)
    return fig


#: the resolution of the measured scans' figures (PNG, dots per inch)
FIGURE_DPI = 130


def scorecard_page(table, spectrum_attrs: dict, name: str, path) -> None:
    """The report's page of the scorecard *table* of the scan *name*
    (:func:`roughcontact.study.analysis.measured_scorecard.measured_scorecard`), its lead the range
    note of the spectrum fit's *spectrum_attrs* and
    :data:`~roughcontact.study.analysis.measured_scorecard.MEASURED_SCORECARD_LEAD`."""
    from .tables import write_html_table

    note = range_note(table, spectrum_attrs)
    write_html_table(table, path, title=f"Model scorecard of the scan {name}",
                     lead=f"{note} {MEASURED_SCORECARD_LEAD}", verdict_columns=(),
                     first=("kind", "radius", "model", "rank", unmodelled.COLUMN, "outside_range", "max_rel_dev",
                            "max_rel_dev_ci_low", "max_rel_dev_ci_high", "rms_rel_dev", "rms_rel_dev_ci_low",
                            "rms_rel_dev_ci_high", "inside_band", "n_loads"))
