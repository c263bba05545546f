"""The report's figures describe the sweep that was run (issue "Figures drawn from the sweep"): no
sphere figure on a flat sweep, placeholders that say why for the sweep at hand, Fig. 3's eq. 17 with
ζ = 1.7/(H+1) and with the fitted ζ each with crossover.csv's own verdict, axes set by the measured
values (a predicted force beyond them an arrow at the edge), no adhesive run against the elastic
eq. 16, no title cut or hidden, every mark explained, no legend over the data. Drawn in process on
small synthetic merged data, read from the matplotlib objects."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.models import paper
from roughcontact.study.config import resolve as config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.report import figures
from roughcontact.study.report.plotting import pyplot
from roughcontact.study.runs import naming as runs

pytest.importorskip("matplotlib")

ROOT = Path(__file__).resolve().parents[1]
FORCE = np.geomspace(1e-5, 1e-2, 8)


def _study(**extra):
    base = {"grid": {"n": 33, "length": 1.0, "coarse": None}, "e_star": 1.0, "hurst": [0.7], "radius": [0.5],
            "h_rms": [9e-3], "seeds": 2, "fit": {"resolved_cells": 10}}
    return StudySettings.of(config.resolve_config({**base, **extra}))


def _ensemble(study):
    """The merged sphere ensemble of every sphere combination of *study*: eq. 16 with ζ = 1.7/(H+1)
    (the combination's body exponent), 2 % standard error, 50 contact cells at every load."""
    combos = figures._sphere_combos(study)
    axes = runs.AXES["sphere"]
    coords = {a: sorted({c[a] for c in combos}) for a in axes}
    shape = tuple(len(coords[a]) for a in axes) + (FORCE.size,)
    k = np.full(shape, np.nan)
    for c in combos:
        index = tuple(coords[a].index(c[a]) for a in axes)
        k[index] = paper.stiffness_from_force(FORCE, radius=c["radius"], hurst=c["hurst"], h_rms=c["h_rms"], length=1.0,
                                              e_star=1.0, zeta=float(paper.zeta_estimate(c["hurst"])),
                                              exponent=c["exponent"])
    dims = (*axes, "force")
    return xr.Dataset({"k_mean": (dims, k), "k_sem": (dims, 0.02 * k), "contact_cells_mean": (dims, 50 + 0 * k)},
                      coords={**coords, "force": FORCE}, attrs={"n_seeds": 2})


ZETA = pd.DataFrame([{"hurst": 0.7, "zeta": 1.1, "zeta_ci_low": 1.0, "zeta_ci_high": 1.2, "confidence": 0.95,
                      "source": "flat"}])


def _crossover(study, **columns):
    """crossover.csv of every sphere combination of *study*: the paper's sphere's numbers (eq. 17:
    8.0e-5 with ζ = 1.7/(H+1), 7.2e-5 with the fitted ζ; measured 1.08e-4 [0.95, 1.23]e-4), and *columns*."""
    rows = []
    for c in figures._sphere_combos(study):
        rows.append({**{a: c[a] for a in runs.AXES["sphere"]}, "zeta_fit": 1.1, "zeta_estimate": 1.0,
                     "Ftr_pred_estimate": 8.0e-5, "Ftr_pred_fit": 7.2e-5, "Ftr_measured": 1.08e-4,
                     "Ftr_ci_low": 0.95e-4, "Ftr_ci_high": 1.23e-4, "verdict_estimate": "differs",
                     "verdict_fit": "differs", **columns})
    return pd.DataFrame(rows)


def _inputs(study, crossover=None):
    return figures.Inputs(study=study, ensemble=_ensemble(study), zeta=ZETA,
                          crossover=_crossover(study) if crossover is None else crossover,
                          hurst=0.7, h_rms=9e-3, radius=0.5, seed=0)


def _fig3_key(study, **where):
    return next(s["key"] for s in figures.figure_specs(study) if s["key"][0] == "fig3"
                and all(s["key"][1][a] == v for a, v in where.items()))


def _legend_texts(fig):
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]


def _boxes(fig):
    """The drawn figure's axes and legends as window extents."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    axes = [ax.get_window_extent(renderer) for ax in fig.axes if ax.axison]
    legends = [ax.get_legend().get_window_extent(renderer) for ax in fig.axes if ax.get_legend()]
    return axes, legends


def _legends_over_axes(fig) -> int:
    """How many legends overlap an axes (a panel's data area)."""
    axes, legends = _boxes(fig)
    return sum(any(lg.overlaps(a) for a in axes) for lg in legends)


@pytest.fixture
def plt():
    plt = pyplot()
    yield plt
    plt.close("all")


def _drawn(module, monkeypatch):
    """The figures *module* saves, kept instead of written."""
    kept = []
    monkeypatch.setattr(module, "save_png", lambda fig, path, **_: kept.append(fig))
    return kept


# ---------------------------------------------------------------- 1. a flat-only sweep
FLAT = {"radius": [math.inf]}


@pytest.mark.parametrize("key", ["fig2", "fig3", "fig4", "collapse"])
def test_a_flat_sweep_draws_no_sphere_figure(key):
    assert key not in {s["key"][0] for s in figures.figure_specs(_study(**FLAT))}


def test_a_sphere_sweep_draws_the_rough_sphere():
    assert "fig2" in {s["key"][0] for s in figures.figure_specs(_study())}


def test_the_area_placeholder_of_a_flat_sweep_says_it_has_no_sphere():
    from roughcontact.study.report.area import no_area_reason

    assert no_area_reason(_study(**FLAT)).startswith("the sweep has no sphere (every radius is .inf)")


def test_the_area_placeholder_of_an_adhesive_sweep_says_every_sphere_is_adhesive():
    from roughcontact.study.report.area import no_area_reason

    reason = no_area_reason(_study(work_of_adhesion=[1e-3]))
    assert reason.startswith("every sphere combination of the sweep is adhesive"), reason


def test_the_area_placeholder_draws_its_reason(tmp_path, monkeypatch):
    from roughcontact.study.report import area

    kept = _drawn(area, monkeypatch)
    area.no_area_figure(tmp_path / "a.png", "the sweep has no sphere")
    assert [t.get_text() for t in kept[0].axes[0].texts] == ["the sweep has no sphere"]


def test_the_area_rule_of_a_flat_sweep_writes_the_flat_reason(tmp_path, monkeypatch):
    """rules.area on a merged file without a sphere: area_models.csv's reason is the flat sweep's."""
    from roughcontact.study.files.io import read_csv
    from roughcontact.study.report import area
    from roughcontact.study.rules import area as area_rule

    import roughcontact.study.files.io as io

    _drawn(area, monkeypatch)
    monkeypatch.setattr(io, "read_groups", lambda path: {})
    area_rule.run(_study(**FLAT), tmp_path / "stiffness.nc", tmp_path / "area_models.csv",
                  tmp_path / "area_models.html", tmp_path / "area.png")
    assert read_csv(tmp_path / "area_models.csv").attrs["reason"].startswith("the sweep has no sphere")


# ---------------------------------------------------------------- 2. Fig. 3's eq. 17
def _vertical_lines(ax):
    return {line.get_label(): line.get_xdata()[0] for line in ax.lines
            if len(line.get_xdata()) == 2 and line.get_xdata()[0] == line.get_xdata()[1]}


@pytest.mark.parametrize("label, value", [
    ("F_tr eq. 17, ζ = 1.7/(H+1)", 8.0e-5),   # eq. 17 with ζ of eq. 13
    ("F_tr eq. 17, fitted ζ", 7.2e-5),         # the fitted ζ, its own line
])
def test_fig3_draws_each_eq17_line_at_its_value(plt, label, value):
    study = _study()
    fig = figures.fig3(plt, _inputs(study), _fig3_key(study))
    lines = _vertical_lines(fig.axes[0])
    drawn = [x for name, x in lines.items() if name.startswith(label)]
    assert drawn == [pytest.approx(value)], lines


@pytest.mark.parametrize("column, text", [
    ("verdict_estimate", "F_tr eq. 17, ζ = 1.7/(H+1) = 1: 8e-05: consistent"),
    ("verdict_fit", "F_tr eq. 17, fitted ζ = 1.1: 7.2e-05: consistent"),
])
def test_fig3_legend_gives_crossover_csv_verdict_of_each_prediction(plt, column, text):
    """The table's verdict, not one recomputed: "consistent" although 8e-5 and 7.2e-5 lie below the
    measured interval [0.95, 1.23]e-4 here."""
    study = _study()
    fig = figures.fig3(plt, _inputs(study, _crossover(study, **{column: "consistent"})), _fig3_key(study))
    assert text in _legend_texts(fig), _legend_texts(fig)


def test_fig3_measured_crossover_carries_no_verdict_of_its_own(plt):
    study = _study()
    fig = figures.fig3(plt, _inputs(study), _fig3_key(study))
    measured = [t for t in _legend_texts(fig) if t.startswith("F_tr measured")]
    assert measured == ["F_tr measured = 0.00011 (9.5e-05-0.00012, 95 %)"], measured


# ---------------------------------------------------------------- 3. a cone: axes set by the data
CONE = {"exponent": [1.0]}


def _cone_figure(plt):
    study = _study(**CONE)
    crossover = _crossover(study, Ftr_pred_estimate=4.6e-12, Ftr_pred_fit=4.7e-13, Ftr_measured=math.nan,
                           Ftr_ci_low=math.nan, Ftr_ci_high=math.nan, verdict_estimate="unresolved",
                           verdict_fit="unresolved")
    return figures.fig3(plt, _inputs(study, crossover), _fig3_key(study, exponent=1.0))


def test_fig3_of_a_cone_keeps_the_x_axis_to_the_loads(plt):
    low, high = _cone_figure(plt).axes[0].get_xlim()
    assert (low >= FORCE[0] / 2, high <= FORCE[-1] * 2) == (True, True), (low, high)


def test_fig3_of_a_cone_keeps_the_y_axis_to_the_measured_stiffness(plt):
    fig = _cone_figure(plt)
    k = paper.stiffness_from_force(FORCE, radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, e_star=1.0,
                                   zeta=float(paper.zeta_estimate(0.7)), exponent=1.0)
    low, high = fig.axes[0].get_ylim()
    assert (low >= k.min() / 2, high <= k.max() * 2) == (True, True), (low, high, k.min(), k.max())


def test_fig3_of_a_cone_marks_eq17_beyond_the_axis_with_an_arrow(plt):
    notes = [t for t in _cone_figure(plt).axes[0].texts if getattr(t, "arrow_patch", None) is not None]
    assert [t.get_text() for t in notes] == ["eq. 17, ζ = 1.7/(H+1) = 4.6e-12", "eq. 17, fitted ζ = 4.7e-13"]


def test_fig3_of_a_cone_says_in_its_legend_where_the_arrow_is(plt):
    texts = _legend_texts(_cone_figure(plt))
    assert "F_tr eq. 17, ζ = 1.7/(H+1) = 1: 4.6e-12: unresolved (beyond the left edge: arrow)" in texts, texts


def test_fig3_title_names_the_body_exponent_off_the_paper(plt):
    assert _cone_figure(plt).axes[0].get_title() == "H = 0.7, R = 0.5, h_rms = 0.009, L = 1, n = 33, m = 1"


# ---------------------------------------------------------------- 4. collapse, Fig. 1, legends, area, scorecard
ADHESIVE = {"work_of_adhesion": [0.0, 1e-3]}


def test_collapse_leaves_out_the_adhesive_combination(plt):
    """Two combinations, w = 0 and w = 0.001: one set of points, the elastic one's."""
    study = _study(**ADHESIVE)
    fig = figures.collapse(plt, _inputs(study), ("collapse",))
    points = [line.get_label() for ax in fig.axes for line in ax.lines if line.get_marker() == "o"]
    assert points == ["R = 0.5, h_rms = 0.009"], points


def test_collapse_title_says_how_many_adhesive_combinations_it_left_out(plt):
    study = _study(**ADHESIVE)
    fig = figures.collapse(plt, _inputs(study), ("collapse",))
    assert "1 adhesive combination (w > 0) left out" in fig._suptitle.get_text(), fig._suptitle.get_text()


@pytest.mark.parametrize("extra", [{}, ADHESIVE])
def test_collapse_title_lies_inside_the_figure(plt, extra):
    study = _study(**extra)
    fig = figures.collapse(plt, _inputs(study), ("collapse",))
    fig.canvas.draw()
    box = fig._suptitle.get_window_extent(fig.canvas.get_renderer())
    assert (box.x0 >= 0, box.x1 <= fig.bbox.x1, box.y1 <= fig.bbox.y1) == (True, True, True), (box, fig.bbox)


def test_fig1_colorbar_hides_no_title(plt):
    study = _study()
    fig = figures.fig1(plt, _inputs(study), ("fig1",))
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    image, cut, colorbar = fig.axes
    titles = [ax.title.get_window_extent(renderer) for ax in (image, cut)]
    assert not any(t.overlaps(colorbar.get_window_extent(renderer)) for t in titles), titles


@pytest.mark.parametrize("draw", ["fig3", "fig3 cone", "collapse"])
def test_the_figures_legends_cover_no_axes(plt, draw):
    study = _study(**(CONE if draw == "fig3 cone" else ADHESIVE if draw == "collapse" else {}))
    inputs = _inputs(study)
    fig = (figures.collapse(plt, inputs, ("collapse",)) if draw == "collapse"
           else figures.fig3(plt, inputs, _fig3_key(study)))
    assert _legends_over_axes(fig) == 0


@pytest.mark.parametrize("draw", ["fig3", "collapse"])
def test_the_figures_legends_lie_inside_the_figure(plt, draw):
    study = _study()
    inputs = _inputs(study)
    fig = (figures.collapse(plt, inputs, ("collapse",)) if draw == "collapse"
           else figures.fig3(plt, inputs, _fig3_key(study)))
    _, legends = _boxes(fig)
    assert all(lg.x0 >= 0 and lg.y0 >= 0 and lg.x1 <= fig.bbox.x1 for lg in legends), (legends, fig.bbox)


def _area_curves(crossover_force):
    """One paraboloid's area curves whose loads stop at 0.02 (F/(E* L²)), F_A at *crossover_force*."""
    force = np.geomspace(1e-4, 2e-2, 6)
    return {"H0.7_R0.5_h0.009": {"force": force, "area": 3 * force, "band_low": -0.1 + 0 * force,
                                  "band_high": 0.1 + 0 * force, "resolved": force > 1e-3,
                                  "crossover_force": crossover_force, "min_cells": 600.0, "rms_slope": 0.5,
                                  "radius": 0.5, "exponent": 2.0, "models": {"persson_area": 2.5 * force}}}


def _area_figure(tmp_path, monkeypatch, crossover_force):
    from roughcontact.study.report import area

    kept = _drawn(area, monkeypatch)
    area.area_figure(tmp_path / "area.png", _area_curves(crossover_force), _study())
    return kept[0]


def test_area_x_axis_stops_near_the_last_load(tmp_path, monkeypatch, plt):
    """F_A = 2 beyond loads that stop at 0.02: the axis does not run to 2."""
    _, high = _area_figure(tmp_path, monkeypatch, 2.0).axes[0].get_xlim()
    assert high <= 0.04, high


def test_area_marks_f_a_beyond_the_loads_with_an_arrow(tmp_path, monkeypatch, plt):
    notes = [t.get_text() for t in _area_figure(tmp_path, monkeypatch, 2.0).axes[0].texts]
    assert notes == ["F_A = 2"], notes


@pytest.mark.parametrize("crossover_force", [2.0, 1e-3])
def test_area_labels_every_line(tmp_path, monkeypatch, plt, crossover_force):
    """Every line of the panel (the F_A line or its arrow's legend entry included) has a label."""
    ax = _area_figure(tmp_path, monkeypatch, crossover_force).axes[0]
    assert [line for line in ax.lines if line.get_label().startswith("_")] == []


def test_area_legend_names_f_a(tmp_path, monkeypatch, plt):
    texts = _legend_texts(_area_figure(tmp_path, monkeypatch, 1e-3))
    assert "F_A = 0.001: Hertz = linear law" in texts, texts


def test_area_legend_covers_no_axes(tmp_path, monkeypatch, plt):
    assert _legends_over_axes(_area_figure(tmp_path, monkeypatch, 1e-3)) == 0


def test_area_of_a_cone_draws_no_hertz_area(tmp_path, monkeypatch, plt):
    from roughcontact.study.report import area

    kept = _drawn(area, monkeypatch)
    curves = _area_curves(1e-3)
    curves["H0.7_R0.5_h0.009"]["exponent"] = 1.0
    area.area_figure(tmp_path / "area.png", curves, _study())
    assert not any("Hertz" in t for t in _legend_texts(kept[0])), _legend_texts(kept[0])


def _scorecard_figure(tmp_path, monkeypatch, decisions):
    from roughcontact.study.report import scorecard

    kept = _drawn(scorecard, monkeypatch)
    dev = 0.1 * np.linspace(-1, 1, FORCE.size)
    curve = xr.Dataset({"eq16_paper": ("force", dev), "mdr": ("force", -dev), "band_low": ("force", np.full(8, -0.05)),
                        "band_high": ("force", np.full(8, 0.05)), "resolved": ("force", np.ones(8, dtype=int))},
                       coords={"force_normalized": ("force", FORCE)})
    table = pd.DataFrame([{"combination": "c", "model": m, "max_rel_dev": 0.1, "not_modelled": "", "decision": d}
                          for m, d in zip(("eq16_paper", "mdr"), decisions)])
    scorecard.scorecard_figure(tmp_path / "f.png", "c", curve, table)
    return kept[0]


def test_scorecard_legend_explains_its_marks(tmp_path, monkeypatch, plt):
    fig = _scorecard_figure(tmp_path, monkeypatch, ("recommended", "tied"))
    title = fig.axes[0].get_legend().get_title().get_text()
    assert title == "★ recommended by the decision rule; ≈ tied with the recommended model", title


def test_scorecard_legend_explains_only_the_marks_it_uses(tmp_path, monkeypatch, plt):
    fig = _scorecard_figure(tmp_path, monkeypatch, ("recommended", "worse"))
    assert fig.axes[0].get_legend().get_title().get_text() == "★ recommended by the decision rule"


def test_scorecard_legend_covers_no_band(tmp_path, monkeypatch, plt):
    assert _legends_over_axes(_scorecard_figure(tmp_path, monkeypatch, ("recommended", "tied"))) == 0


# ---------------------------------------------------------------- 5. every mark explained
def _exponents_figure(tmp_path, monkeypatch):
    from roughcontact.study.report import exponents

    kept = _drawn(exponents, monkeypatch)
    table = pd.DataFrame([{"kind": kind, "hurst": 0.7, "radius": radius, "force": f, "local_exponent": 0.5,
                           "ci_low": 0.45, "ci_high": 0.55} for kind, radius in (("sphere", 0.5), ("flat", math.inf))
                          for f in FORCE[:3]])
    exponents.exponents_figure(table, tmp_path / "e.png")
    return kept[0]


def test_exponents_reference_lines_are_labelled(tmp_path, monkeypatch, plt):
    fig = _exponents_figure(tmp_path, monkeypatch)
    assert [line.get_label() for ax in fig.axes for line in ax.lines if line.get_label().startswith("_")] == []


def test_exponents_legend_names_the_fractal_law(tmp_path, monkeypatch, plt):
    texts = _legend_texts(_exponents_figure(tmp_path, monkeypatch))
    assert "1/(H+1) = 0.588: fractal law, eq. 11 (H = 0.7)" in texts, texts


def test_exponents_legends_cover_no_axes(tmp_path, monkeypatch, plt):
    assert _legends_over_axes(_exponents_figure(tmp_path, monkeypatch)) == 0


def test_histograms_legends_cover_no_axes(tmp_path, monkeypatch, plt):
    """The histogram figure of a small merged file (one sphere, two seeds, one load's histograms)."""
    from roughcontact.study.report import histograms

    kept = _drawn(histograms, monkeypatch)
    bins, seeds = 8, 2
    p_edges, g_edges = np.linspace(0, 2, bins + 1), np.linspace(0, 3, bins + 1)
    ds = xr.Dataset(
        {"pressure_histogram": (("hurst", "radius", "h_rms", "seed", "histogram_load", "pressure_bin"),
                                np.ones((1, 1, 1, seeds, 1, bins))),
         "gap_histogram": (("hurst", "radius", "h_rms", "seed", "histogram_load", "gap_bin"),
                           np.ones((1, 1, 1, seeds, 1, bins))),
         "histogram_force_normalized": ("histogram_load", [1e-2])},
        coords={"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seed": np.arange(seeds), "histogram_load": [4]})
    mean = _histogram_means(ds, p_edges, g_edges)
    monkeypatch.setattr(histograms, "mean_histograms", lambda first: mean)
    path = tmp_path / "stiffness.nc"
    ds.to_netcdf(path, group="sphere", engine="netcdf4")
    histograms.make_histogram_figure(_study(), path, tmp_path / "h.png")
    assert _legends_over_axes(kept[0]) == 0


def _histogram_means(ds, p_edges, g_edges):
    """What analysis.histograms.mean_histograms gives the figure, for flat densities."""
    seeds, bins = ds.sizes["seed"], p_edges.size - 1
    out = xr.Dataset(coords={"seed": ds["seed"].values, "histogram_load": [4]})
    for name, edges in (("pressure", p_edges), ("gap", g_edges)):
        ratio = "pressure_ratio" if name == "pressure" else "gap_ratio"
        out[f"{ratio}_edges"] = (f"{name}_edge", edges)
        out[f"{name}_density"] = (("histogram_load", "seed", f"{name}_bin"), np.full((1, seeds, bins), 0.5))
        out[f"{name}_density_mean"] = (("histogram_load", f"{name}_bin"), np.full((1, bins), 0.5))
        out[f"{name}_density_sem"] = (("histogram_load", f"{name}_bin"), np.full((1, bins), 0.05))
    return out


# ---------------------------------------------------------------- the captions say what the figures show
CAPTIONS = {
    "fig3.rst": "the crossover force of eq. 17 with ζ = 1.7/(H+1) (dash-dotted) and with the fitted ζ (dashed), "
                "each with its verdict of crossover.csv",
    "collapse.rst": "adhesive combinations (w > 0) are left out",
    "area_figure.rst": "the labelled vertical line at their crossover F_A",
    "models_figure.rst": "★ marks the model the decision rule recommends, ≈ one tied with it",
    "exponents.rst": "dotted lines: the fractal law's 1/(H+1) (eq. 11)",
}


@pytest.mark.parametrize("name", sorted(CAPTIONS))
def test_the_caption_says_what_the_figure_shows(name):
    text = re.sub(r"\s+", " ", (ROOT / "workflow" / "report" / name).read_text(encoding="utf-8"))
    assert CAPTIONS[name] in text, text
