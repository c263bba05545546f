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
    adhesion_figures._pull_off(pyplot(), table, tmp_path / "pull_off.png")
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
