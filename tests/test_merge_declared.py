"""The merge reads each run file against its own declaration (roughcontact.study.analysis.merge.read_declared):
the job record its ``config`` attribute holds says what the file holds; its surface and seed must
be those of its name, its other settings the study's for its kind (jobs.shared_settings, once per
kind). Each wrong or stale file stops the merge with one MergeError naming the file, what is wrong
and what to do."""
from __future__ import annotations

import dataclasses
import json

import netCDF4
import numpy as np
import pytest
import xarray as xr

from pathlib import Path

from roughcontact.errors import MergeError
from roughcontact.study import quantities
from roughcontact.study.analysis.merge import read_declared
from roughcontact.study.config import load_config, study_settings
from roughcontact.study.files import provenance, runfile
from roughcontact.study.files.provenance import canonical_json
from roughcontact.study.runs import naming
from roughcontact.study.runs.jobs import JobSettings, job_settings, shared_settings

from test_run_io import GENERATED

ROOT = Path(__file__).resolve().parents[1]
#: the run GENERATED is, as its name says it (a dict of naming.runs)
ROW = {"kind": "sphere", "hurst": 0.7, "radius": 0.5, "h_rms": 9e-3, "seed": 3}
#: the study's settings every sphere run shares, those of GENERATED
SHARED = {key: getattr(GENERATED, key) for key in ("n", "length", "e_star", "force_from", "force_to", "force_count",
                                                   "tol", "stiffness_method", "rel_step", "maxiter",
                                                   "realization_of", "patches", "quantities", "field_loads")}


def _generated_file(path, s: JobSettings, *, record: dict | None = None):
    """A generated run file of *s* with made-up per-load numbers, declaring *record* (default: its own)."""
    count = s.force_count
    out = {"force": s.forces(), **{name: np.ones(count, meta.dtype)
                                   for name, meta in quantities.variables(quantities.recorded(s)).items()}}
    runfile.write_run(path, out, variables=quantities.variables(out), stiffness_method=s.stiffness_method,
                      scalars={name: getattr(s, name) for name in runfile.SCALARS},
                      attrs=provenance.provenance_attrs(config=record or s.record()))


def test_a_run_of_the_current_settings_reads_with_the_quantities_it_declares(tmp_path):
    _generated_file(tmp_path / "r.nc", GENERATED)
    ds, kept = read_declared(tmp_path / "r.nc", ROW, SHARED)
    assert kept == ("depth", "stiffness", "contact_area", "contact_cells", "iterations", "converged")
    np.testing.assert_allclose(ds["force"].values, GENERATED.forces(), rtol=1e-15, atol=0)


def test_a_stale_run_names_the_setting_that_differs(tmp_path):
    """tol 1e-8 in the file, 1e-6 in the study: the message names tol with both values."""
    _generated_file(tmp_path / "r.nc", GENERATED)
    with pytest.raises(MergeError, match=r"r\.nc: was computed with other settings; differs in tol: 1e-08 in the "
                                         r"file, 1e-06 now; delete .*r\.nc and rerun snakemake"):
        read_declared(tmp_path / "r.nc", ROW, {**SHARED, "tol": 1e-6})


def test_a_run_of_another_optional_axis_value_is_stale(tmp_path):
    """A run computed with a roll-off under the name of the run without one: options differ."""
    _generated_file(tmp_path / "r.nc", dataclasses.replace(GENERATED, options=(("rolloff", 0.5),)))
    with pytest.raises(MergeError, match=r"differs in options: \[\['rolloff', 0.5\]\] in the file, \[\] now"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


def test_a_run_of_another_seed_names_the_seed_and_its_name(tmp_path):
    _generated_file(tmp_path / "r.nc", GENERATED)
    with pytest.raises(MergeError, match="r.nc: holds seed = 3, expected 4 from its name"):
        read_declared(tmp_path / "r.nc", {**ROW, "seed": 4}, SHARED)


def test_a_run_that_lacks_a_quantity_it_declares_is_foreign(tmp_path):
    """Declared with fields.patches but written without its two quantities."""
    patched = dataclasses.replace(GENERATED, patches=True)
    _generated_file(tmp_path / "r.nc", GENERATED, record=patched.record())
    with pytest.raises(MergeError, match=r"r\.nc: foreign NetCDF file \(lacks contact_patches, largest_patch_cells\)"):
        read_declared(tmp_path / "r.nc", ROW, {**SHARED, "patches": True})


def test_an_adhesive_declaration_without_its_retract_path_is_foreign(tmp_path):
    adhesive = dataclasses.replace(GENERATED, options=(("work_of_adhesion", 1e-3),))
    _generated_file(tmp_path / "r.nc", GENERATED, record=adhesive.record())
    with pytest.raises(MergeError, match=r"foreign NetCDF file \(lacks retract_depth"):
        read_declared(tmp_path / "r.nc", {**ROW, "work_of_adhesion": 1e-3}, SHARED)


def _set_attrs(path, **attrs):
    with netCDF4.Dataset(path, "a") as nc:
        nc.setncatts(attrs)


def test_a_file_without_a_job_record_is_foreign(tmp_path):
    xr.Dataset({"temperature": ("time", [1.0, 2.0])}).to_netcdf(tmp_path / "r.nc")
    with pytest.raises(MergeError, match=r"r\.nc: foreign NetCDF file \(no job record in its 'config' attribute\); "
                                         r"delete .*r\.nc and rerun snakemake"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


def test_a_record_that_is_not_the_files_own_is_refused(tmp_path):
    """Its config edited after the write: config_hash is no longer its hash."""
    _generated_file(tmp_path / "r.nc", GENERATED)
    _set_attrs(tmp_path / "r.nc", config=canonical_json({**GENERATED.record(), "tol": 1e-6}))
    with pytest.raises(MergeError, match=r"r\.nc: its 'config' attribute is not the one its config_hash was made of"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


def test_a_record_of_another_kind_of_run_is_foreign(tmp_path):
    """A stickiness run's record (no surface radius) under an indent run's name."""
    from roughcontact.study.files.provenance import config_hash

    _generated_file(tmp_path / "r.nc", GENERATED)
    record = {"n": 33, "length": 1.0, "e_star": 1.0, "tol": 1e-8, "number": 0.5}
    _set_attrs(tmp_path / "r.nc", config=canonical_json(record), config_hash=config_hash(record))
    with pytest.raises(MergeError, match=r"r\.nc: foreign NetCDF file \(its 'config' attribute is no job record"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


def test_a_truncated_file_says_so(tmp_path):
    _generated_file(tmp_path / "r.nc", GENERATED)
    data = (tmp_path / "r.nc").read_bytes()
    (tmp_path / "r.nc").write_bytes(data[: len(data) // 2])
    with pytest.raises(MergeError, match=r"r\.nc: not a readable NetCDF file .*it may be truncated"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


def test_a_missing_file_says_so(tmp_path):
    with pytest.raises(MergeError, match=r"r\.nc: run file is missing; rerun snakemake"):
        read_declared(tmp_path / "r.nc", ROW, SHARED)


@pytest.mark.parametrize("preset", ["config.yaml", "presets/plastic.yaml", "presets/tangential.yaml",
                                    "presets/adhesion.yaml", "presets/generality.yaml"])
def test_every_job_reads_back_from_the_record_its_file_declares(preset):
    """JobSettings.from_record inverts record() through the JSON a run file holds, for every run of the preset."""
    study = study_settings(load_config(ROOT / preset))
    for row in naming.runs(study):
        job = job_settings(study, row)
        assert JobSettings.from_record(json.loads(canonical_json(job.record()))) == job, job.describe()


def test_fields_settings_read_back_too():
    job = dataclasses.replace(GENERATED, patches=True, quantities=("gap_mean",), field_loads=(0, 2),
                              realization_of=65, slip_loads=(1,), slip_steps=3,
                              options=(("poisson", 0.3), ("friction", 0.5)))
    assert JobSettings.from_record(json.loads(canonical_json(job.record()))) == job


def test_shared_settings_and_the_runs_own_make_its_job():
    """job_settings is shared_settings (once per kind) with the run's own fields."""
    study = study_settings(load_config(ROOT / "presets/tiny.yaml"))
    row = naming.runs(study)[0]
    job = job_settings(study, row)
    assert {key: getattr(job, key) for key in shared_settings(study, job.kind)} == shared_settings(study, job.kind)


#: one sliding sphere run (friction > 0: a partial-slip path at one load, 2 tangential steps), small
SLIDING = {"grid": {"n": 33, "length": 1.0}, "hurst": [0.7], "radius": [0.5], "h_rms": [2e-3], "seeds": 1,
           "forces": {"sphere": {"from": 1e-4, "to": 1e-3, "count": 3}}, "poisson": [0.3], "friction": [0.4],
           "tangential": {"at": [1e-3], "steps": 2}}


@pytest.fixture(scope="module")
def sliding_run(tmp_path_factory):
    """The run file of SLIDING, computed (``indent.compute_run``) and written as the indent rule does."""
    from roughcontact.study.config.resolve import resolve_config
    from roughcontact.study.runs import indent

    study = study_settings(resolve_config(SLIDING))
    job = job_settings(study, naming.runs(study)[0])
    path = tmp_path_factory.mktemp("sliding") / "seed0.nc"
    indent.write_run(path, job, indent.compute_run(job))
    return path


def test_a_sliding_run_of_the_current_settings_merges(sliding_run):
    from roughcontact.study.analysis.merge import merge_runs
    from roughcontact.study.config.resolve import resolve_config

    groups = merge_runs(resolve_config(SLIDING), [sliding_run])
    assert groups["sphere"].sizes["seed"] == 1


def test_the_merge_names_a_sliding_runs_stale_slip_steps(sliding_run):
    """tangential.steps 2 in the file, 3 now: the normal merge (not only the tangential one) stops
    with one line naming slip_steps and both values."""
    from roughcontact.study.analysis.merge import merge_runs
    from roughcontact.study.config.resolve import resolve_config

    with pytest.raises(MergeError, match=r"^[^\n]*seed0\.nc: was computed with other settings; differs in "
                                         r"slip_steps: 2 in the file, 3 now; delete [^\n]*$"):
        merge_runs(resolve_config({**SLIDING, "tangential": {"at": [1e-3], "steps": 3}}), [sliding_run])


def test_the_merge_names_a_sliding_runs_stale_slip_loads(sliding_run):
    """tangential.at moved from the last load (index 2) to the first (index 0)."""
    from roughcontact.study.analysis.merge import merge_runs
    from roughcontact.study.config.resolve import resolve_config

    with pytest.raises(MergeError, match=r"differs in slip_loads: \[2\] in the file, \[0\] now"):
        merge_runs(resolve_config({**SLIDING, "tangential": {"at": [1e-4], "steps": 2}}), [sliding_run])
