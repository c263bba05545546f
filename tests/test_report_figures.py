"""The report's figures are faceted: no panel holds more than plotting.MAX_CURVES curves, and the
figures keep every curve (synthetic data, no run needed)."""
from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from roughcontact.study.config import resolve as config
from roughcontact.study.report import measured as measured_figures
from roughcontact.study.report.plotting import MAX_CURVES, chunks, pyplot
from roughcontact.study.config.settings import StudySettings

pytest.importorskip("matplotlib")


def _scan(radii, models):
    force = np.geomspace(1e-6, 1e-3, 6)
    k = np.outer(np.asarray(radii) ** (1 / 3), force ** (1 / 3)) * 1e6
    dims = ("radius", "force")
    sphere = xr.Dataset({"k_mean": (dims, k), "k_ci_low": (dims, 0.9 * k), "k_ci_high": (dims, 1.1 * k)},
                        coords={"radius": radii, "force": force}, attrs={"half_space": "free"})
    flat = xr.Dataset({"k_mean": ("force", k[0]), "k_ci_low": ("force", 0.9 * k[0]),
                       "k_ci_high": ("force", 1.1 * k[0])}, coords={"force": force}, attrs={"half_space": "free"})
    pred = {"sphere": xr.Dataset({"stiffness": (("model", "radius", "force"),
                                                np.stack([k * (1 + 0.05 * i) for i in range(len(models))]))},
                                 coords={"model": models, "radius": radii, "force": force}),
            "flat": xr.Dataset({"stiffness": (("model", "force"), np.stack([k[0] * (1 + 0.05 * i) for i in range(len(models))]))},
                               coords={"model": models, "force": force})}
    return {"sphere": sphere, "flat": flat}, pred


def _study():
    cfg = config.resolve_config({"grid": {"n": 33, "length": 1.0}, "e_star": 1.0, "hurst": [0.7], "radius": [0.5],
                                 "h_rms": [0.01], "seeds": 1, "units": {"length": "um", "e_star": "GPa"}})
    return StudySettings.of(cfg)


def test_chunks():
    assert chunks(range(7), 5) == [[0, 1, 2, 3, 4], [5, 6]]
    assert chunks([], 5) == [[]]


@pytest.mark.parametrize("with_models", [True, False])
def test_measured_stiffness_figure_is_faceted(with_models):
    """15 radii and 7 models (the scan of the issue: one colour per radius, 15 legend entries):
    every panel holds at most MAX_CURVES lines, every radius and every model is drawn."""
    radii = [float(r) for r in np.geomspace(1, 100, 15)]
    models = [f"model{i}" for i in range(7)]
    groups, pred = _scan(radii, models)
    fig = measured_figures.draw_stiffness_figure(pyplot(), groups, pred if with_models else {}, _study())
    try:
        drawn = [ax for ax in fig.axes if ax.lines]
        assert all(len(ax.lines) <= MAX_CURVES for ax in drawn), [len(ax.lines) for ax in drawn]
        titles = {ax.get_title() for ax in drawn}
        assert len(titles) == len(radii) + 1, titles  # every radius and the flat punch
        labels = {line.get_label() for ax in drawn for line in ax.lines}
        assert set(models) <= labels if with_models else not set(models) & labels
    finally:
        pyplot().close(fig)


def test_pull_off_figure_is_faceted(tmp_path, monkeypatch):
    """Ten Hurst exponents: the pull-off figure has at most MAX_CURVES labelled curves a panel
    and every exponent on one of them."""
    import pandas as pd

    from roughcontact.study.report import adhesion as adhesion_figures

    hursts = [round(0.1 * i, 1) for i in range(1, 11)]
    table = pd.DataFrame([{"kind": "sphere", "hurst": h, "johnson_parameter": j, "pull_off_ratio": 0.5,
                           "pull_off_ratio_ci_low": 0.4, "pull_off_ratio_ci_high": 0.6}
                          for h in hursts for j in (0.1, 1.0)])
    figures = []
    monkeypatch.setattr(adhesion_figures, "save_png", lambda fig, path: figures.append(fig))
    adhesion_figures.pull_off_figure(pyplot(), table, tmp_path / "pull_off.png")
    (fig,) = figures
    try:
        drawn = [ax for ax in fig.axes if ax.get_legend() is not None]
        entries = [[t.get_text() for t in ax.get_legend().get_texts()] for ax in drawn]
        assert all(len(e) <= MAX_CURVES for e in entries), entries
        assert {f"H = {h:g}" for h in hursts} <= {t for e in entries for t in e}
    finally:
        pyplot().close(fig)


def test_scorecard_figure_is_faceted(tmp_path, monkeypatch):
    """Every registered model (eight): every panel of a combination's scorecard figure holds at most
    MAX_CURVES lines (the zero line included) and every model is drawn once."""
    import pandas as pd

    from roughcontact.models import scorecard as registry
    from roughcontact.study.report import scorecard

    figures = []
    monkeypatch.setattr(scorecard, "save_png", lambda fig, path, **_: figures.append(fig))
    force = np.geomspace(1e-5, 1e-2, 8)
    names = list(registry.models())
    curve = xr.Dataset({**{name: ("force", np.full(8, 0.01 * i)) for i, name in enumerate(names)},
                        "band_low": ("force", np.full(8, -0.05)), "band_high": ("force", np.full(8, 0.05)),
                        "resolved": ("force", np.ones(8, dtype=int))}, coords={"force_normalized": ("force", force)})
    table = pd.DataFrame([{"combination": "H0.7_R0.5_h0.01", "model": m, "max_rel_dev": 0.1, "not_modelled": "",
                           "decision": "worse"} for m in names])
    scorecard.scorecard_figure(tmp_path / "f.png", "H0.7_R0.5_h0.01", curve, table)
    try:
        drawn = [ax for ax in figures[0].axes if ax.lines]
        assert max(len(ax.lines) for ax in drawn) <= MAX_CURVES, [len(ax.lines) for ax in drawn]
        labels = [line.get_label().split(" ")[0] for ax in drawn for line in ax.lines[1:]]
        assert sorted(labels) == sorted(names), labels
    finally:
        pyplot().close(figures[0])


def test_scorecard_figure_scales_to_the_scored_loads(tmp_path, monkeypatch):
    """An unresolved load whose grid error is 3e15 (as on a coarse companion with no contact there)
    does not set the axis: the y-range stays that of the scored loads' bands and models (within
    ±0.5 here, where the largest |value| drawn at a resolved load is 0.3)."""
    import pandas as pd

    from roughcontact.study.report import scorecard

    figures = []
    monkeypatch.setattr(scorecard, "save_png", lambda fig, path, **_: figures.append(fig))
    force = np.geomspace(1e-5, 1e-2, 6)
    resolved = np.array([0, 1, 1, 1, 1, 1])
    curve = xr.Dataset({"eq16_paper": ("force", np.array([9.0, 0.1, 0.05, 0.0, -0.05, -0.1])),
                        "band_low": ("force", np.array([-50.0, -0.1, -0.1, -0.1, -0.1, -0.1])),
                        "band_high": ("force", np.array([50.0, 0.1, 0.1, 0.1, 0.1, 0.1])),
                        "grid_error": ("force", np.array([3e15, 0.3, 0.2, 0.1, 0.0, 0.0])),
                        "resolved": ("force", resolved)}, coords={"force_normalized": ("force", force)})
    table = pd.DataFrame([{"combination": "c", "model": "eq16_paper", "max_rel_dev": 0.1, "not_modelled": "",
                           "decision": "worse"}])
    scorecard.scorecard_figure(tmp_path / "f.png", "c", curve, table)
    try:
        low, high = figures[0].axes[0].get_ylim()
        assert -0.5 < low and high < 0.5, (low, high)
    finally:
        pyplot().close(figures[0])


def _sphere_inputs(zeta_rows):
    """figures.Inputs of one sphere combination (H 0.7, R 0.5, h 0.01 on 33²) whose ensemble follows
    eq. 16, with the ζ table *zeta_rows* (dicts of zeta.csv's columns) and no crossover row."""
    import pandas as pd

    from roughcontact.models import paper
    from roughcontact.study.report import figures
    from roughcontact.study.runs import naming as runs

    cfg = config.resolve_config({"grid": {"n": 33, "length": 1.0, "coarse": None}, "e_star": 1.0, "hurst": [0.7],
                                 "radius": [0.5], "h_rms": [0.01], "seeds": 2})
    study = StudySettings.of(cfg)
    force = np.geomspace(1e-5, 1e-2, 6)
    k = paper.stiffness_from_force(force, radius=0.5, hurst=0.7, h_rms=0.01, length=1.0, e_star=1.0,
                                   zeta=float(paper.zeta_estimate(0.7)))
    spec = next(s for s in figures.figure_specs(cfg) if s["key"][0] == "fig3")
    combo = spec["key"][1]
    axes = runs.AXES["sphere"]
    shape = (1,) * len(axes) + (force.size,)
    ens = xr.Dataset({name: ((*axes, "force"), values.reshape(shape))
                      for name, values in (("k_mean", k), ("k_sem", 0.01 * k), ("contact_cells_mean", 50 + 0 * k))},
                     coords={**{a: [combo[a]] for a in axes}, "force": force}, attrs={"n_seeds": 2})
    inputs = figures.Inputs(study=study, ensemble=ens, zeta=pd.DataFrame(zeta_rows), crossover=pd.DataFrame(),
                            hurst=0.7, h_rms=0.01, radius=0.5, seed=0)
    return figures, inputs, spec["key"]


def _legend_texts(fig):
    return [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]


NOT_FITTED = {"hurst": 0.7, "zeta": float("nan"), "zeta_ci_low": float("nan"), "zeta_ci_high": float("nan"),
              "confidence": 0.95, "source": "no loads in the fit window (sphere small-force branch (no flat runs): "
                                            "eq. 16 minus its Hertz term; no free exponent (the window is too narrow))"}


def test_zeta_figure_of_a_sphere_only_sweep_has_no_reason_in_its_legend():
    """ζ not fitted (a sphere-only sweep whose fit window is empty): the legend names the curves only,
    the axes keep most of the figure's width, and a short note in the axes says why."""
    figures, inputs, _ = _sphere_inputs([NOT_FITTED])
    plt = pyplot()
    fig = figures.zeta(plt, inputs, ("zeta",))
    try:
        texts = _legend_texts(fig)
        assert texts == ["1.7/(H+1), eq. 13"], texts
        assert fig.axes[0].get_position().width > 0.6, "the axes are a strip beside their legend"
        notes = [t.get_text() for t in fig.axes[0].texts]
        assert any("not fitted" in n and "no loads in the fit window" in n for n in notes), notes
        assert not any("Hertz term" in n for n in notes), "the whole reason string is in the axes"
    finally:
        plt.close(fig)
    fitted = {**NOT_FITTED, "zeta": 1.1, "zeta_ci_low": 1.0, "zeta_ci_high": 1.2, "source": "flat"}
    figures, inputs, _ = _sphere_inputs([fitted])
    fig = figures.zeta(plt, inputs, ("zeta",))
    try:
        assert sorted(_legend_texts(fig)) == ["1.7/(H+1), eq. 13", "fit (flat), 95% bootstrap CI"], _legend_texts(fig)
        assert not fig.axes[0].texts
    finally:
        plt.close(fig)


@pytest.mark.parametrize("fitted", [False, True])
def test_fig3_says_fitted_only_when_zeta_was_fitted(fitted):
    """Fig. 3's eq. 16 curve: "fitted ζ = …" where zeta.csv has ζ at that H, else ζ = 1.7/(H+1)
    (eq. 13), drawn once."""
    row = {**NOT_FITTED, "zeta": 1.1, "source": "flat"} if fitted else NOT_FITTED
    figures, inputs, key = _sphere_inputs([row])
    plt = pyplot()
    fig = figures.fig3(plt, inputs, key)
    try:
        eq16 = [t for t in _legend_texts(fig) if t.startswith("eq. 16")]
        if fitted:
            assert "eq. 16, fitted ζ = 1.1" in eq16 and "eq. 16, ζ = 1.7/(H+1) (eq. 13)" in eq16, eq16
        else:
            assert not any("fitted" in t for t in _legend_texts(fig)), _legend_texts(fig)
            assert eq16 and all(t == "eq. 16, ζ = 1.7/(H+1) = 1 (eq. 13)" for t in eq16), eq16
    finally:
        plt.close(fig)


def test_fixed_layout_places_the_panels_at_its_margins():
    """report.plotting.fixed_layout: the outer panels' edges at the margins and the gap between two
    columns as given, in inches (a 10 x 4 in figure of 2 panels; to 1e-9 in)."""
    from roughcontact.study.report.plotting import fixed_layout

    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    try:
        fixed_layout(fig, left=1.0, right=0.5, bottom=0.6, top=0.4, wspace=0.8)
        a, b = (ax.get_position() for ax in (left, right))
        assert (a.x0 * 10, (1 - b.x1) * 10, a.y0 * 4, (1 - a.y1) * 4) == pytest.approx((1.0, 0.5, 0.6, 0.4), abs=1e-9)
        assert (b.x0 - a.x1) * 10 == pytest.approx(0.8, abs=1e-9)
    finally:
        plt.close(fig)


@pytest.mark.parametrize("fitted", [False, True])
def test_fig3_text_lies_inside_the_figure(fitted):
    """Fig. 3 with its fixed margins (no tight_layout): every tick label, axis label and title is
    drawn inside the figure (its bounding box within the figure's, to half a pixel)."""
    row = {**NOT_FITTED, "zeta": 1.1, "source": "flat"} if fitted else NOT_FITTED
    figures, inputs, key = _sphere_inputs([row])
    plt = pyplot()
    fig = figures.fig3(plt, inputs, key)
    try:
        renderer = fig.canvas.get_renderer()
        frame = fig.bbox
        for ax in fig.axes:
            box = ax.get_tightbbox(renderer)
            assert box.x0 >= frame.x0 - 0.5 and box.y0 >= frame.y0 - 0.5, (ax.get_title(), box, frame)
            assert box.x1 <= frame.x1 + 0.5 and box.y1 <= frame.y1 + 0.5, (ax.get_title(), box, frame)
    finally:
        plt.close(fig)
