"""No warning leaks from the report's figures (issue #30 item 8): every figure function of the report
drawn on small synthetic data, with every warning an error (``-W error`` semantics), including the
edge cases of a real study (unresolved loads, no crossover interval, runs below resolution, one
tile, no resolved window)."""
from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.study.config import resolve as config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.report import adhesion as adhesion_figures
from roughcontact.study.report import figures as study_figures
from roughcontact.study.report import measured as measured_figures
from roughcontact.study.report.plotting import pyplot

pytest.importorskip("matplotlib")

FORCE = np.geomspace(1e-5, 1e-2, 8)


@pytest.fixture(autouse=True)
def warnings_are_errors(monkeypatch):
    """Every warning raised while a figure is drawn fails the test; the figures are not written."""
    monkeypatch.setattr(adhesion_figures, "save_png", lambda fig, path, **_: pyplot().close(fig))
    pyplot()   # matplotlib's own import-time warnings (a font cache, a backend) are not the figures'
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield
    pyplot().close("all")


def _study(**extra):
    return StudySettings.of(config.resolve_config({
        "grid": {"n": 33, "length": 1.0}, "e_star": 1.0, "hurst": [0.7], "radius": [0.5, math.inf],
        "h_rms": [0.01], "seeds": 2, "fit": {"resolved_cells": 10}, **extra}))


def _ensemble(study, *, resolved: bool):
    """The merged ensemble of every sphere combination of *study*: k 0.8 of Hertz, 2 % standard error,
    2 to 400 contact cells (the first loads below min_cells), or every load unresolved."""
    combos = study_figures._sphere_combos(study)
    axes = [a for a in combos[0] if a not in ("name", "variant")]
    coords = {a: [combos[0][a]] for a in axes}
    shape = (1,) * len(axes) + (FORCE.size,)
    k = (0.8 * 2 * (0.75 * FORCE * 0.5) ** (1 / 3)).reshape(shape)
    cells = np.geomspace(2, 400, FORCE.size).reshape(shape) * (1 if resolved else 0.01)
    dims = (*axes, "force")
    return xr.Dataset({"k_mean": (dims, k), "k_sem": (dims, 0.02 * k), "contact_cells_mean": (dims, cells)},
                      coords={**coords, "force": FORCE}, attrs={"n_seeds": 2})


def _inputs(study, *, resolved=True):
    combo = study_figures._sphere_combos(study)[0]
    axes = {a: combo[a] for a in combo if a not in ("name", "variant")}
    zeta = pd.DataFrame([{"hurst": 0.7, "zeta": 1.0, "zeta_ci_low": 0.9, "zeta_ci_high": 1.1,
                          "source": "flat runs", "confidence": 0.95}])
    finite = 1.0 if resolved else math.nan
    crossover = pd.DataFrame([{**axes, "Ftr_pred_fit": 2e-4, "Ftr_pred_estimate": 3e-4, "Ftr_measured": 2.5e-4 * finite,
                               "Ftr_ci_low": 1e-4 * finite, "Ftr_ci_high": 5e-4 * finite, "verdict_fit": "consistent"}])
    return study_figures.Inputs(study=study, ensemble=_ensemble(study, resolved=resolved), zeta=zeta,
                                crossover=crossover, hurst=0.7, h_rms=0.01, radius=0.5, seed=0)


@pytest.mark.parametrize("resolved", [True, False])
def test_the_studys_figures_draw_without_a_warning(resolved):
    study = _study()
    inputs = _inputs(study, resolved=resolved)
    plt = pyplot()
    for spec in study_figures.figure_specs(study):
        plt.close(study_figures.DRAW[spec["key"][0]](plt, inputs, spec["key"]))


@pytest.mark.parametrize("with_grid, shown", [(True, True), (False, True), (False, False)])
def test_the_scorecard_figure_draws_without_a_warning(tmp_path, monkeypatch, with_grid, shown):
    from roughcontact.study.report import scorecard

    monkeypatch.setattr(scorecard, "save_png", lambda fig, path, **_: pyplot().close(fig))
    dev = 0.1 * np.linspace(-1, 1, FORCE.size)
    curve = xr.Dataset({"eq16_paper": ("force", dev), "mdr": ("force", -dev), "band_low": ("force", np.full(8, -0.05)),
                        "band_high": ("force", np.full(8, 0.05)), "resolved": ("force", np.full(8, int(shown))),
                        **({"grid_error": ("force", np.full(8, 0.02))} if with_grid else {})},
                       coords={"force_normalized": ("force", FORCE)})
    table = pd.DataFrame([{"combination": "H0.7_R0.5_h0.01", "model": m, "max_rel_dev": 0.1, "not_modelled": "",
                           "decision": d} for m, d in (("eq16_paper", "recommended"), ("mdr", "tied"))])
    scorecard.scorecard_figure(tmp_path / "f.png", "H0.7_R0.5_h0.01", curve, table)


@pytest.mark.parametrize("rows", [2, 0])
def test_the_exponents_figure_draws_without_a_warning(tmp_path, monkeypatch, rows):
    from roughcontact.study.report import exponents

    monkeypatch.setattr(exponents, "save_png", lambda fig, path, **_: pyplot().close(fig))
    table = pd.DataFrame([{"kind": kind, "hurst": 0.7, "radius": radius, "force": f, "local_exponent": 0.5,
                           "ci_low": 0.45, "ci_high": 0.55} for kind, radius in (("sphere", 0.5), ("flat", math.inf))
                          for f in FORCE[:rows]], columns=["kind", "hurst", "radius", "force", "local_exponent", "ci_low",
                                                          "ci_high"])
    exponents.exponents_figure(table, tmp_path / "f.png")


def _pull_off_table():
    """Two Hurst exponents, each a resolved and an unresolved (R, w) pair, and a flat row."""
    rows = [{"kind": "sphere", "hurst": h, "radius": 0.5, "h_rms": j * 0.01, "work_of_adhesion": w,
             "johnson_parameter": j, "pull_off_ratio": 1 / (1 + j), "pull_off_ratio_ci_low": 0.9 / (1 + j),
             "pull_off_ratio_ci_high": 1.1 / (1 + j), "method_error": e, "resolved": e <= 0.03}
            for h in (0.5, 0.8) for w, e in ((1e-3, 0.11), (3e-2, 0.02)) for j in (0.01, 0.3, 1.0)]
    rows.append({"kind": "flat", "hurst": 0.5, "radius": math.inf, "h_rms": 0.01, "work_of_adhesion": 1e-3,
                 "method_error": math.nan, "resolved": False})
    return pd.DataFrame(rows)


@pytest.mark.parametrize("empty", [False, True])
def test_the_adhesion_figures_draw_without_a_warning(tmp_path, empty):
    table = _pull_off_table().iloc[:0] if empty else _pull_off_table()
    adhesion_figures.pull_off_figure(pyplot(), table, tmp_path / "p.png")
    seeds, retract = 2, 6
    axes = {"hurst": [0.7], "radius": [0.5], "h_rms": [1e-5], "work_of_adhesion": [1e-3]}
    dims = (*axes, "seed")
    shape = (1, 1, 1, 1, seeds)
    adhesion = {} if empty else {"sphere": xr.Dataset(
        {"pull_off_force": (dims, np.full(shape, -2e-3)),
         "retract_depth": ((*dims, "retract"), np.broadcast_to(np.linspace(1e-2, -1e-2, retract), (*shape, retract))),
         "retract_force": ((*dims, "retract"), np.broadcast_to(np.linspace(1e-2, -2e-3, retract), (*shape, retract)))},
        coords={**axes, "seed": np.arange(seeds)})}
    stiffness = {"sphere": xr.Dataset({"depth": ((*dims, "force"), np.broadcast_to(FORCE ** (2 / 3), (*shape, 8)))},
                                      coords={**axes, "seed": np.arange(seeds), "force": FORCE})}
    rows = _pull_off_table()
    rows.loc[0, ["hurst", "h_rms"]] = [0.7, 1e-5]
    adhesion_figures.paths_figure(pyplot(), adhesion, stiffness, _study(work_of_adhesion=[1e-3]), tmp_path / "q.png", rows)


def _scan(tiles_ci: bool):
    radii = [5.0, 20.0]
    k = np.outer(np.asarray(radii) ** (1 / 3), FORCE ** (1 / 3)) * 1e6
    dims = ("radius", "force")
    band = (0.9, 1.1) if tiles_ci else (math.nan, math.nan)
    sphere = xr.Dataset({"k_mean": (dims, k), "k_ci_low": (dims, band[0] * k), "k_ci_high": (dims, band[1] * k)},
                        coords={"radius": radii, "force": FORCE}, attrs={"half_space": "free"})
    flat = xr.Dataset({"k_mean": ("force", k[0]), "k_ci_low": ("force", band[0] * k[0]),
                       "k_ci_high": ("force", band[1] * k[0])}, coords={"force": FORCE}, attrs={"half_space": "periodic"})
    models = ["eq16_paper", "eq16_law", "mdr"]
    stiff = np.stack([k * (1 + 0.05 * i) for i in range(len(models))])
    stiff[-1, :, :2] = np.nan                      # a model without a value at the lightest loads
    pred = {"sphere": xr.Dataset({"stiffness": (("model", "radius", "force"), stiff)},
                                 coords={"model": models, "radius": radii, "force": FORCE}),
            "flat": xr.Dataset({"stiffness": (("model", "force"), stiff[:, 0])}, coords={"model": models, "force": FORCE}),
            "spectrum": xr.Dataset(attrs={"hurst": 1.18, "tile": 256})}
    return {"sphere": sphere, "flat": flat}, pred


@pytest.mark.parametrize("tiles_ci", [True, False])
def test_the_measured_figures_draw_without_a_warning(tmp_path, tiles_ci):
    from roughcontact.study.files.io import write_groups

    study = _study(units={"length": "um", "e_star": "GPa"})
    groups, pred = _scan(tiles_ci)
    pyplot().close(measured_figures.draw_stiffness_figure(pyplot(), groups, pred, study))
    pyplot().close(measured_figures.draw_stiffness_figure(pyplot(), groups, {}, study))
    q = np.geomspace(1.0, 100.0, 30)
    spectrum = xr.Dataset({"C": ("q", q ** -3.4), "fit_c": ("bin", q[::6] ** -3.4), "fit_model": ("bin", q[::6] ** -3.4)},
                          coords={"q": q, "fit_q": ("bin", q[::6])},
                          attrs={"q_min": 2.0, "q_max": 50.0, "hurst": 0.7, "hurst_ci_low": 0.65, "hurst_ci_high": 0.75,
                                 "prefactor_persson": 1.0})
    write_groups(tmp_path / "spectrum.nc", {"spectrum": spectrum}, {"title": "test"})
    surface = xr.Dataset({"heights": (("x", "y"), np.random.default_rng(0).standard_normal((32, 32)) * 1e-3)},
                         attrs={"length": 10.0, "tile": 16, "units_length": "um", "file": "scan.di"})
    surface.to_netcdf(tmp_path / "surface.nc", engine="netcdf4")
    fig, ax = pyplot().subplots()
    measured_figures.draw_heights(ax, tmp_path / "surface.nc", "scan")
    measured_figures.draw_spectrum(ax, tmp_path / "spectrum.nc", "um")
    pyplot().close(fig)


def test_the_stickiness_figure_draws_without_a_warning(tmp_path, monkeypatch):
    """Two numbers N, two seeds: a sticky path (tension at small areas) and a non-sticky one."""
    from roughcontact.study.config.stickiness import StickinessSettings
    from roughcontact.study.report import stickiness
    from roughcontact.study.rules import stickiness_figures

    monkeypatch.setattr(stickiness, "save_png", lambda fig, path, **_: pyplot().close(fig))
    sweep = StickinessSettings.of(config.resolve_config({
        "grid": {"n": 33, "length": 1.0}, "hurst": [0.7], "radius": [0.5], "h_rms": [0.01], "seeds": 2,
        "stickiness": {"n": 64, "cutoff": 4, "seeds": 2, "number": [0.3, 1000.0], "steps": 12}}))
    paths = []
    for i, job in enumerate(sweep.jobs()):
        cells = np.linspace(10, 0.06 * 64 * 64, 12)
        offset = -0.02 if job.number < 1 else 0.0
        force = (cells / (64 * 64) / 2 + offset) * job.rms_slope
        path = tmp_path / f"run{i}.nc"
        xr.Dataset({"contact_cells": ("step", cells), "force": ("step", force), "loading_slope": 0.5 + offset}).to_netcdf(
            path, engine="netcdf4")
        paths.append(path)
    stickiness_figures.run(sweep, runs=paths, loading=tmp_path / "loading.png")
