"""The typed study-wide settings: every key of the schema has its typed home, read once."""
from __future__ import annotations

import dataclasses
import json
import math
import pickle
from pathlib import Path

import pytest

from roughcontact.errors import ConfigError
from roughcontact.study.config import axes, schema
from roughcontact.study.config.resolve import load_config, resolve_config, study_settings
from roughcontact.study.files.provenance import canonical_json
from roughcontact.study.runs import naming as runs
from roughcontact.study.config.settings import ForceRange, StudySettings

ROOT = Path(__file__).resolve().parents[1]
#: the schema's nested sections and the typed record that holds each
SECTIONS = {("grid",): "grid", ("solver",): "solver", ("fit", "zeta"): "fit.zeta", ("fit", "slopes"): "fit.slopes",
            ("units",): "units"}
#: keys whose typed name differs from the configuration's: fit.spectrum.band is fit.spectrum_band
RENAMED = {("fit", "spectrum"): "spectrum_band"}


def _resolve(obj, dotted: str):
    for part in dotted.split("."):
        obj = getattr(obj, part)
    return obj


@pytest.fixture(scope="module")
def study():
    return study_settings(load_config(ROOT / "config.yaml"))


def test_every_top_level_key_is_an_attribute(study):
    root = schema.load_schema(None)
    missing = [key for key in root["properties"] if not hasattr(study, key)]
    assert not missing, f"schema keys without a typed attribute of StudySettings: {missing}"


@pytest.mark.parametrize("path, record", SECTIONS.items(), ids=[".".join(p) for p in SECTIONS])
def test_every_key_of_a_section_is_a_field(study, path, record):
    node = schema.load_schema(None)
    for part in path:
        node = node["properties"][part]
    fields = {f.name for f in dataclasses.fields(_resolve(study, record))}
    missing = sorted(set(node["properties"]) - fields)
    assert not missing, f"keys of {'.'.join(path)} without a field of {record}: {missing}"


def test_fit_sections_are_all_typed(study):
    fit = schema.load_schema(None)["properties"]["fit"]["properties"]
    typed = {f.name for f in dataclasses.fields(study.fit)}
    missing = [k for k in fit if k not in typed and RENAMED.get(("fit", k)) not in typed]
    assert not missing, f"fit sections without a typed home: {missing}"


def test_values_are_those_of_the_resolved_config(study):
    cfg = resolve_config(load_config(ROOT / "config.yaml"))
    assert study.grid.n == cfg["grid"]["n"], "grid.n"
    assert study.forces["sphere"] == ForceRange(cfg["forces"]["sphere"]["from"], cfg["forces"]["sphere"]["to"],
                                                cfg["forces"]["sphere"]["count"]), "forces.sphere"
    assert study.fit.resolved_cells == cfg["fit"]["resolved_cells"], "fit.resolved_cells"
    assert study.seeds == tuple(cfg["seeds"]), "seeds"


@pytest.mark.parametrize("name", list(axes.AXES))
def test_every_registered_axis_is_an_attribute(study, name):
    cfg = resolve_config(load_config(ROOT / "config.yaml"))
    assert getattr(study, name) == tuple(cfg[name]), f"sweep values of {name}"


def test_unknown_attribute_is_an_attribute_error(study):
    with pytest.raises(AttributeError, match="hurts"):
        study.hurts   # noqa: B018  (a typo is an error, not an empty sweep)


def test_settings_are_frozen(study):
    with pytest.raises(dataclasses.FrozenInstanceError):
        study.e_star = 2.0


def test_typing_twice_is_the_identity(study):
    assert StudySettings.of(study) is study, "StudySettings.of of typed settings returns them"


def test_config_recorded_in_a_file_reads_back_equal(study):
    """A run file records the resolved configuration as canonical JSON (inf as "inf"): typed again,
    it compares equal, radius inf included."""
    again = StudySettings.of(json.loads(canonical_json(study.config)))
    assert again == study, "the typed settings of the recorded configuration"
    assert math.isinf(again.radius[-1]), f"radius read back from JSON: {again.radius}"


def test_force_range_is_the_log_spaced_path(study):
    forces = study.forces["flat"].normalized()
    assert forces[0] == pytest.approx(study.forces["flat"].start, rel=1e-15), "first load"
    assert forces[-1] == pytest.approx(study.forces["flat"].stop, rel=1e-15), "last load"
    assert forces.size == study.forces["flat"].count, "number of loads"


def test_settings_survive_pickling(study):
    """Snakemake passes params to jobs pickled: the settings come back equal, config included."""
    again = pickle.loads(pickle.dumps(study))
    assert again == study, "the unpickled settings"
    assert dict(again.config) == dict(study.config), "the unpickled resolved configuration"


def test_coarse_companion_presses_the_same_surfaces():
    """grid.coarse: the companion study runs on the coarse grid with the study's surfaces."""
    study = study_settings({**load_config(ROOT / "presets" / "tiny.yaml"), "grid": {"n": 65, "coarse": 33}})
    coarse = study.coarse_study()
    assert (coarse.grid.n, coarse.grid.realization_of, coarse.grid.coarse) == (33, 65, None), coarse.grid
    spheres = [run for run in runs.runs(study) if run["kind"] == "sphere"]
    assert runs.runs(coarse) == spheres, "the study's sphere runs, and no flat one"


def test_coarse_grid_must_be_coarser():
    with pytest.raises(ConfigError) as err:
        study_settings({**load_config(ROOT / "presets" / "tiny.yaml"), "grid": {"n": 65, "coarse": 65}})
    assert err.value.key == "grid.coarse", err.value


def test_an_axis_the_mapping_lacks_takes_its_paper_value(study):
    """A file's configuration recorded before an optional axis existed: the axis at its paper value."""
    old = {k: v for k, v in study.config.items() if k != "hardness"}
    assert StudySettings.of(old).hardness == (None,), "hardness of a configuration without the key"


def test_capped_tol_is_the_solvers_at_most_1e_8():
    """The adhesive and cohesive solves' tolerance: solver.tol, at most 1e-8 (exact)."""
    from roughcontact.study.config.defaults import ADHESIVE_TOL_CAP, capped_tol

    assert ADHESIVE_TOL_CAP == 1e-8
    assert capped_tol(1e-6) == 1e-8 and capped_tol(1e-10) == 1e-10 and capped_tol(1e-8) == 1e-8


def test_solver_maxiter_defaults_to_the_solvers():
    """solver.maxiter None: the solver's default (roughcontact.bem.DEFAULT_MAXITER), else the value."""
    from roughcontact.bem import DEFAULT_MAXITER
    from roughcontact.study.config.defaults import solver_maxiter

    assert solver_maxiter(None) == DEFAULT_MAXITER and solver_maxiter(37) == 37
