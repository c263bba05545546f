"""A model declares the optional axes it models (Model.axes); off the paper value of an axis it does
not declare, its scorecard row names the axis in ``not_modelled``, keeps its deviations and is not
scored (no rank, every verdict untested); at the paper value the row is the one without the axis.

The ensembles are eq. 16 with the fitted ζ at every seed (test_scorecard._groups), so a model
``scale × eq. 16`` deviates by ``scale − 1`` at every load, exactly.
"""
from __future__ import annotations

import contextlib
import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from examples import scoped_registries, scoped_registry  # noqa: F401 -- scoped_registry: every test in its own registries
from test_scorecard import CFG, FORCE, HURST, RADIUS, ZETA, _groups

from roughcontact.models import paper
from roughcontact.models import scorecard as registry
from roughcontact.study.config import axes
from roughcontact.study.analysis import not_modelled, scorecard

ZETA_DF = pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]})
#: a model 10 % above the ensemble: max_rel_dev 0.1 at every combination
SCALE = 1.1
#: an off-paper coordinate of each optional axis the scorecard scores (work_of_adhesion > 0 is skipped)
OFF = {"exponent": 4.0, "rolloff": 0.5, "cutoff": 0.05, "hardness": 0.5}


def _eq16(force, s: registry.Surface):
    return paper.stiffness_from_force(force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length,
                                      e_star=s.e_star, zeta=ZETA, exponent=s.exponent)


def _blind(force, s: registry.Surface):
    """10 % above eq. 16 whatever the optional axes say."""
    return SCALE * _eq16(force, s)


@contextlib.contextmanager
def _blind_model():
    """A model that declares no optional axis, in a scope of the registries of its own."""
    with scoped_registries():
        yield registry.register(registry.Model("blind", "blind: declares no optional axis", _blind))


@pytest.fixture
def blind_model():
    with _blind_model() as model:
        yield model


@pytest.fixture(scope="module")
def hardness_table():
    """The scorecard of hardness = [inf, 0.5] with the blind model."""
    with _blind_model():
        return scorecard.scorecard(_swept("hardness", [math.inf, 0.5]), ZETA_DF, CFG)[0]


@pytest.fixture(scope="module")
def plateau_table():
    """The scorecard of a throwaway optional axis ``plateau`` = [1, 1.5] (role roughness, paper
    value 1) with the blind model and a model that declares the axis and reads its value from
    Surface.axes (k = plateau × eq. 16), in a scope of the registries of their own (in place of an
    axis ``plateau`` of the package: the guide's example, copied in)."""
    with scoped_registries():
        axes.AXES.pop("plateau", None)
        axes.register(axes.Axis("plateau", "pl", "plateau factor", "1", "a test axis",
                                {"type": "number", "exclusiveMinimum": 0}, "roughness", paper=1.0))
        registry.register(registry.Model("plateau_reader", "plateau_reader: reads the plateau axis",
                                         lambda force, s: s.axes["plateau"] * _eq16(force, s), axes=("plateau",)))
        with _blind_model():
            return scorecard.scorecard(_swept("plateau", [1.0, 1.5]), ZETA_DF, CFG)[0]


def _swept(axis: str, values) -> dict:
    """The one-combination groups of test_scorecard with *axis* swept over *values* (coordinates),
    the same stiffness at every value."""
    ds = _groups(np.ones(4))["sphere"]
    if axis in ds.dims:
        ds = ds.isel({axis: 0}, drop=True)
    ds = xr.concat([ds] * len(values), dim=xr.DataArray(list(values), dims=axis, name=axis))
    order = [a for a in axes.names("sphere") if a in ds.dims] + ["seed", "force"]
    return {"sphere": ds.transpose(*order)}


def _row(table, model, **where):
    rows = table[table["model"] == model]
    for axis, value in where.items():
        rows = rows[rows[axis] == value]
    assert len(rows) == 1, f"{model} {where}: {len(rows)} rows"
    return rows.iloc[0]


def test_off_paper_row_names_the_axis(hardness_table):
    assert _row(hardness_table, "blind", hardness=0.5)["not_modelled"] == "hardness = 0.5"


def test_off_paper_row_keeps_its_deviation(hardness_table):
    row = _row(hardness_table, "blind", hardness=0.5)
    assert row["max_rel_dev"] == pytest.approx(SCALE - 1, rel=1e-12), "max_rel_dev of a 10 % model"


def test_off_paper_row_has_no_rank(hardness_table):
    assert math.isnan(_row(hardness_table, "blind", hardness=0.5)["rank"]), "rank of a not-modelled row"


def test_off_paper_row_has_every_verdict_untested(hardness_table):
    row = _row(hardness_table, "blind", hardness=0.5)
    verdicts = {c: row[c] for c in row.index if c.endswith("_verdict")}
    assert verdicts, "no verdict column"
    assert all(v == "untested: not modelled: hardness = 0.5" for v in verdicts.values()), verdicts


def test_paper_row_is_scored(hardness_table):
    row = _row(hardness_table, "blind", hardness=math.inf)
    assert row["not_modelled"] == "", f"not_modelled at the paper value: {row['not_modelled']!r}"


def test_paper_row_is_the_row_without_the_axis(hardness_table):
    """The paper-value rows of the swept study equal those of the study without the sweep, every
    number to 1e-12 and every verdict and rank exactly."""
    swept = hardness_table[hardness_table["hardness"] == math.inf].reset_index(drop=True)
    with _blind_model():
        alone = scorecard.scorecard(_groups(np.ones(4)), ZETA_DF, CFG)[0]
    pd.testing.assert_frame_equal(swept, alone, check_exact=False, rtol=1e-12, atol=0)


def test_no_rank_off_paper_where_no_model_models_the_axis(hardness_table):
    """Off the paper's hardness every built-in model is not modelled too: no row ranks there."""
    off = hardness_table[hardness_table["hardness"] == 0.5]
    assert off["rank"].isna().all(), off[["model", "rank", "not_modelled"]].to_string()


def test_a_declared_axis_is_scored_off_paper(blind_model):
    """cutoff: contact_scale declares it (scored), the blind model does not (not scored)."""
    table = scorecard.scorecard(_swept("cutoff", [0.0, 0.05]), ZETA_DF, CFG)[0]
    row = _row(table, "contact_scale", cutoff=0.05)
    assert (row["not_modelled"], row["rank"] >= 1) == ("", True), row[["not_modelled", "rank"]].to_dict()


@pytest.mark.parametrize("axis", sorted(OFF))
def test_paper_setting_column_is_false_off_paper(axis):
    table = scorecard.scorecard(_swept(axis, [axes.paper_coordinates(1.0)[axis], OFF[axis]]), ZETA_DF, CFG)[0]
    assert not table[table[axis] == OFF[axis]]["paper_setting"].any(), f"{axis} = {OFF[axis]}"


def test_paper_setting_column_is_true_at_the_paper_setting():
    table = scorecard.scorecard(_groups(np.ones(4)), ZETA_DF, CFG)[0]
    assert table["paper_setting"].all(), "every optional axis at the paper value"


def test_registered_axis_off_paper_is_not_the_paper_setting(plateau_table):
    assert not _row(plateau_table, "blind", plateau=1.5)["paper_setting"], "plateau = 1.5"


def test_registered_axis_is_not_modelled_by_a_model_that_does_not_declare_it(plateau_table):
    assert _row(plateau_table, "eq16_paper", plateau=1.5)["not_modelled"] == "plateau = 1.5"


def test_model_declaring_a_registered_axis_reads_its_value(plateau_table):
    """plateau_reader is plateau × eq. 16: at plateau = 1.5 it deviates by 0.5, scored, rank 1."""
    row = _row(plateau_table, "plateau_reader", plateau=1.5)
    assert row["max_rel_dev"] == pytest.approx(0.5, rel=1e-12), "deviation read from Surface.axes"
    assert row["rank"] == 1, row[["not_modelled", "rank"]].to_dict()


def test_surface_carries_every_optional_axis():
    combo = scorecard.Combination(hurst=HURST, radius=RADIUS, h_rms=9e-3, exponent=2.0, rolloff=1.0, cutoff=0.05,
                                  hardness=math.inf, work_of_adhesion=0.0, n=129, length=1.0, e_star=1.0,
                                  zeta_fit=ZETA)
    assert dict(combo.surface().axes) == {"exponent": 2.0, "rolloff": 1.0, "cutoff": 0.05, "hardness": math.inf,
                                          "work_of_adhesion": 0.0}


def test_surface_axes_are_read_only():
    surface = registry.Surface(hurst=HURST, h_rms=9e-3, radius=RADIUS, length=1.0, n=129, e_star=1.0,
                               axes={"cutoff": 0.05})
    with pytest.raises(TypeError):
        surface.axes["cutoff"] = 0.1


def test_model_axes_must_be_names():
    with pytest.raises(TypeError, match="axis names"):
        registry.Model("bad", "bad", _blind, axes="exponent")


def test_not_modelled_names_undeclared_axes_in_registry_order():
    combo = {"exponent": 4.0, "cutoff": 0.05, "hardness": 0.5}
    assert not_modelled.not_modelled("contact_scale", combo, 1.0) == "hardness = 0.5"
    assert not_modelled.not_modelled("eq16_paper", combo, 1.0) == "cutoff = 0.05; hardness = 0.5"


def test_built_in_models_declare_their_axes():
    """The package's models (a model of a module added to the package declares its own)."""
    spectral = ("exponent", "rolloff", "cutoff")
    expected = {"eq16_paper": ("exponent",), "eq16_fitted": ("exponent",), "eq16_law": ("exponent",),
                "contact_scale": spectral, "contact_scale_h": spectral, "contact_scale_tail": spectral,
                "greenwood_tripp": spectral, "mdr": spectral, "persson": spectral}
    declared = {name: model.axes for name, model in registry.models().items() if name in expected}
    assert declared == expected, declared


def test_measured_rank_skips_not_modelled_rows():
    """The measured scorecard's rank (per kind and radius) ranks the scored rows only."""
    table = pd.DataFrame({"kind": "sphere", "radius": 0.5, "model": ["a", "b", "c"],
                          "max_rel_dev": [0.3, 0.1, 0.2], "not_modelled": ["", "hardness = 0.5", ""]})
    np.testing.assert_array_equal(not_modelled.rank(table, ["kind", "radius"]), [2.0, np.nan, 1.0])


def test_measured_surface_is_at_the_paper_setting():
    """A measured scan's Surface (study.analysis.measured_models.surface_of) carries the paper's coordinates."""
    from roughcontact.study.analysis.measured_models import surface_of
    from roughcontact.surfaces import self_affine
    from roughcontact.surfaces.spectrum_fit import fit_spectrum

    fit = fit_spectrum(self_affine(64, hurst=0.8, h_rms=0.009, length=1.0, seed=1), length=1.0, window=None,
                       detrend="mean", resamples=10)
    surface = surface_of(fit, radius=0.5, e_star=1.0, length=1.0, n=64)
    assert dict(surface.axes) == axes.paper_coordinates(1.0), dict(surface.axes)


def _measured_groups(hardness=None):
    """Merged runs of one scan (two radii, three tiles, four loads, every load resolved) with k = 1,
    and the predictions of two models, eq16_paper (k = 1.2) and contact_scale (k = 1.1);
    *hardness*: a scalar coordinate of the merged runs (none in today's measured runs)."""
    force = np.geomspace(1e-6, 1e-3, 4)
    shape = (2, 3, 4)
    runs = xr.Dataset({"stiffness": (("radius", "tile", "force"), np.ones(shape)),
                       "contact_cells": (("radius", "tile", "force"), np.full(shape, 100)),
                       **{v: (("radius", "force"), np.ones((2, 4))) for v in ("k_mean", "k_ci_low", "k_ci_high")}},
                      coords={"radius": [0.5, 1.0], "force": force, "force_normalized": ("force", force)})
    if hardness is not None:
        runs = runs.assign_coords(hardness=hardness)
    models = xr.Dataset({"stiffness": (("model", "radius", "force"),
                                       np.stack([np.full((2, 4), 1.2), np.full((2, 4), 1.1)]))},
                        coords={"model": ["eq16_paper", "contact_scale"], "radius": [0.5, 1.0], "force": force,
                                "force_normalized": ("force", force)})
    spectrum = xr.Dataset(attrs={"tile_length": 1.0})
    return {"sphere": runs}, {"sphere": models, "spectrum": spectrum}


def test_measured_scorecard_at_the_paper_setting_ranks_every_model():
    from roughcontact.study.analysis.measured_scorecard import measured_scorecard

    table = measured_scorecard(*_measured_groups(), name="scan", min_cells=10)
    assert table["rank"].tolist() == [2.0, 1.0, 2.0, 1.0], table[["radius", "model", "rank"]].to_string()


def test_measured_scorecard_names_an_undeclared_axis():
    from roughcontact.study.analysis.measured_scorecard import measured_scorecard

    table = measured_scorecard(*_measured_groups(hardness=0.5), name="scan", min_cells=10)
    assert table["not_modelled"].tolist() == ["hardness = 0.5"] * 4, table[["model", "not_modelled"]].to_string()


def test_measured_scorecard_does_not_rank_not_modelled_rows():
    from roughcontact.study.analysis.measured_scorecard import measured_scorecard

    table = measured_scorecard(*_measured_groups(hardness=0.5), name="scan", min_cells=10)
    assert table["rank"].isna().all(), table[["model", "rank"]].to_string()
