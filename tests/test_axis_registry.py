"""A sweep axis registered in one place (roughcontact.study.config.axes) reaches the schema, the
configuration, run names, job settings, the surface or solver arguments, the merged files'
coordinates and the command line; the registry's own axes keep their names and hashes."""
from __future__ import annotations

import math

import numpy as np
import pytest
from examples import in_order, loaded, scoped_registry  # noqa: F401 -- scoped_registry: every test in its own registries

from roughcontact import errors
from roughcontact.cli import build_parser
from roughcontact.study.config import axes, resolve as config, schema
from roughcontact.study.files import provenance, runfile
from roughcontact.study.runs import naming as runs, jobs as settings

BASE = {"hurst": [0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 2}


@pytest.fixture
def toy_axis():
    """The package guide's worked example: a roll-off exponent of the spectrum, passed to the
    surface generator (role ``roughness``), paper value 0 (none); registered in the test's own
    registry (:func:`examples.scoped_registry`)."""
    spec = axes.register(axes.Axis(
        "rolloff_power", "rp", "power of the roll-off", "1", "power of the roll-off plateau (0: flat plateau)",
        {"type": "number", "minimum": 0, "maximum": 4}, "roughness", paper=0.0,
        flag_help="power of the roll-off plateau (default 0)"))
    schema._package_schema.cache_clear()
    return spec


def test_registered_axis_is_a_config_key_with_its_default(toy_axis):
    cfg = config.resolve_config(BASE)
    assert cfg["rolloff_power"] == [0.0], f"default of the new axis: {cfg['rolloff_power']}"


def test_registered_axis_is_checked_by_its_schema(toy_axis):
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config({**BASE, "rolloff_power": [5.0]})
    assert info.value.key == "rolloff_power[0]", f"error key: {info.value.key}"


def test_registered_axis_multiplies_the_runs(toy_axis):
    cfg = config.resolve_config({**BASE, "rolloff_power": [0.0, 1.5]})
    assert len(runs.runs(cfg)) == 4, f"runs: {[runs.combo_name(r) for r in runs.runs(cfg)]}"


def test_run_name_carries_the_tag_off_the_paper_value(toy_axis):
    cfg = config.resolve_config({**BASE, "rolloff_power": [0.0, 1.5]})
    names = [runs.combo_name(c) for c in runs.combinations(cfg)]
    assert names == ["H0.7_R0.5_h0.009", "H0.7_R0.5_h0.009_rp1.5"], f"names: {names}"


def test_run_name_parses_back(toy_axis):
    parsed = runs.parse_combo("H0.7_R0.5_h0.009_rp1.5")
    assert parsed["rolloff_power"] == 1.5, f"parsed: {parsed}"


def test_settings_pass_the_axis_to_its_role(toy_axis):
    cfg = config.resolve_config({**BASE, "rolloff_power": [1.5]})
    job = settings.job_settings(cfg, runs.runs(cfg)[0])
    assert job.arguments("roughness")["rolloff_power"] == 1.5, f"arguments: {job.arguments('roughness')}"


def test_merged_coordinate_has_the_axis_attributes(toy_axis):
    assert axes.coordinate_attrs("rolloff_power") == {"long_name": "power of the roll-off", "units": "1"}, \
        f"attributes: {axes.coordinate_attrs('rolloff_power')}"


def test_command_line_has_the_axis_flag(toy_axis):
    args = build_parser().parse_args(["indent", "--hurst", "0.7", "--radius", "0.5", "--h-rms", "9e-3",
                                      "--rolloff-power", "1.5", "-o", "x.nc"])
    assert args.rolloff_power == 1.5, f"parsed flag: {args.rolloff_power}"


def test_paper_setting_keeps_the_run_hash(toy_axis):
    """A run at the new axis's paper value has the settings record (and so the config_hash) of
    the same run without the axis: finished runs stay valid."""
    cfg = config.resolve_config(BASE)
    record = settings.job_settings(cfg, runs.runs(cfg)[0]).record()
    assert "rolloff_power" not in record, f"record: {record}"


#: the registry's own axes of the sphere runs' merged files, in the order of their dimensions
SPHERE_AXES = ("hurst", "radius", "exponent", "h_rms", "rolloff", "cutoff", "hardness", "work_of_adhesion")


def test_registry_order_is_the_merged_dimension_order():
    """The built-in axes lead the sphere dimensions, in order; an axis of a further module follows."""
    assert runs.AXES["sphere"][:len(SPHERE_AXES)] == SPHERE_AXES, f"sphere dimensions: {runs.AXES['sphere']}"


def test_flat_surfaces_do_not_sweep_the_body_axes():
    flat = runs.AXES["flat"]
    assert in_order(("hurst", "h_rms", "rolloff", "cutoff", "hardness", "work_of_adhesion"), flat) \
        and not {"radius", "exponent"} & set(flat), f"flat dimensions: {flat}"


def test_an_axis_of_a_further_module_follows_the_builtins(toy_axis):
    assert runs.AXES["sphere"][len(SPHERE_AXES):][-1] == "rolloff_power", f"sphere dimensions: {runs.AXES['sphere']}"


def test_the_axis_example_loads_twice():
    """Loading the guide's axis twice (as a test run after another, or with the example copied
    into the package) is no error: each load has its own registry."""
    for _ in range(2):
        with loaded("axis_example.py", axes.AXES, "plateau"):
            assert "plateau" in axes.AXES


def test_the_axis_example_cuts_the_touching_side():
    """Heights grow from the half-space towards the indenter and the lowest touch first
    (:mod:`roughcontact.bem.contact`): the worn roughness raises every height below
    ``−plateau·h_rms`` to it and leaves the others as they are, exactly."""
    from roughcontact.surfaces import self_affine

    heights = self_affine(64, hurst=0.7, h_rms=0.02, length=1.0, seed=0)
    run = type("Run", (), {"h_rms": 0.02})()
    with loaded("axis_example.py", axes.AXES, "plateau") as example:
        worn = example.truncate(heights, 1.5, run)
    below = heights < -1.5 * 0.02
    assert below.any() and np.array_equal(worn[below], np.full(below.sum(), -1.5 * 0.02)), "the summits are not cut"
    assert np.array_equal(worn[~below], heights[~below]), "heights above the plateau changed"


@pytest.mark.parametrize("extra, recorded", [({}, "61a64f8073b3e8ec"),
                                             ({"hardness": [0.3], "rolloff": [0.25]}, "ab53f61d41f06bf7")])
def test_run_hash_is_the_recorded_one(extra, recorded):
    """The config_hash of a sphere run on 129² with every other setting at the schema's default,
    recorded with the code before the axis registry (commit 4bed618): the registry changed no
    finished run's identity (a hash of the settings' text, exact on every machine)."""
    cfg = config.resolve_config({**BASE, "grid": {"n": 129}, **extra})
    record = settings.job_settings(cfg, runs.runs(cfg)[0]).record()
    assert provenance.config_hash(record) == recorded, f"config_hash of {record}"


def test_nullable_axis_coordinate_round_trips():
    length = 2.0
    value = runs.axis_value("rolloff", runs.coordinate("rolloff", None, length), length)
    assert value is None, f"rolloff at the paper's setting came back as {value}"


def test_hardness_coordinate_of_the_elastic_setting_is_inf():
    assert math.isinf(runs.coordinate("hardness", None, 1.0)), "elastic hardness coordinate is not inf"

