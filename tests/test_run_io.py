"""The one atomic NetCDF write (roughcontact.study.files.provenance.write_netcdf) and the one reader of
run files of every kind (roughcontact.study.files.io.read_run): what each checks and the MergeError
that names the file, what is wrong and what to do."""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import xarray as xr

from roughcontact.errors import MergeError
from roughcontact.study import quantities
from roughcontact.study.files import provenance, runfile
from roughcontact.study.files.io import read_run
from roughcontact.study.runs.measured import MeasuredJob
from roughcontact.study.runs.jobs import JobSettings

GENERATED = JobSettings(hurst=0.7, radius=0.5, h_rms=9e-3, seed=3, n=33, length=1.0, e_star=1.0, force_from=1e-3,
                        force_to=0.3, force_count=4, tol=1e-8, stiffness_method="punch", rel_step=1e-3)


def test_a_failed_write_leaves_no_file_and_no_temporary(tmp_path):
    def fill(nc):
        nc.createDimension("x", 2)
        raise RuntimeError("killed mid-write")

    with pytest.raises(RuntimeError, match="mid-write"):
        provenance.write_netcdf(fill, tmp_path / "out.nc")
    assert list(tmp_path.iterdir()) == [], "neither the file nor its temporary"


def test_an_xarray_dataset_round_trips_exactly(tmp_path):
    rng = np.random.default_rng(7)
    ds = xr.Dataset({"a": ("x", rng.normal(size=5))}, attrs={"title": "t"})
    provenance.write_netcdf(ds, tmp_path / "d" / "out.nc")
    xr.testing.assert_identical(xr.load_dataset(tmp_path / "d" / "out.nc"), ds)


def _generated_file(path, s: JobSettings):
    """A generated run file of *s* with made-up per-load numbers (what is read, not solved;
    contact cells ``seed, seed + 1, ...``)."""
    rng = np.random.default_rng(11)
    count = s.force_count
    out = {"force": s.forces(), "depth": rng.random(count), "stiffness": rng.random(count) + 1.0,
           "contact_area": rng.random(count), "contact_cells": np.arange(count) + s.seed, "iterations": np.ones(count, int),
           "converged": np.ones(count, "i1")}
    runfile.write_run(path, out, variables=quantities.variables(out), stiffness_method=s.stiffness_method,
                      scalars={name: getattr(s, name) for name in runfile.SCALARS},
                      attrs=provenance.provenance_attrs(config=s.record()))


def test_a_generated_run_of_the_current_settings_reads(tmp_path):
    _generated_file(tmp_path / "r.nc", GENERATED)
    ds = read_run(tmp_path / "r.nc", GENERATED)
    np.testing.assert_allclose(ds["force"].values, GENERATED.forces(), rtol=1e-15, atol=0)


def test_a_stale_run_names_the_setting_that_differs(tmp_path):
    """tol 1e-8 in the file, 1e-6 in the current settings: the message names tol with both values."""
    _generated_file(tmp_path / "r.nc", GENERATED)
    with pytest.raises(MergeError, match=r"r\.nc: was computed with other settings .*differs in tol: 1e-08 in the "
                                         r"file, 1e-06 now.*delete .*r\.nc and rerun snakemake"):
        read_run(tmp_path / "r.nc", dataclasses.replace(GENERATED, tol=1e-6))


def test_a_run_of_another_seed_names_the_scalar(tmp_path):
    _generated_file(tmp_path / "r.nc", GENERATED)
    with pytest.raises(MergeError, match="holds seed = 3, expected 4 from its name"):
        read_run(tmp_path / "r.nc", dataclasses.replace(GENERATED, seed=4))


def test_an_elastic_file_is_no_adhesive_run(tmp_path):
    """The adhesive run's record asks for the retract path and pull-off: the file was made with
    other settings, and lacks them."""
    _generated_file(tmp_path / "r.nc", GENERATED)
    adhesive = dataclasses.replace(GENERATED, options=(("work_of_adhesion", 1e-3),))
    with pytest.raises(MergeError, match="other settings .*differs in work_of_adhesion.*lacks retract_depth"):
        read_run(tmp_path / "r.nc", adhesive)


MEASURED = MeasuredJob(source="spectrum", name="s", index=1, radius=0.5, e_star=1.0, length_unit="um",
                       pressure_unit="MPa", force_from=1e-4, force_to=1e-2, force_count=3, tol=1e-8, maxiter=100,
                       stiffness_method="punch", rel_step=1e-3, n=16, length=1.0)


def _measured_file(path, job: MeasuredJob, normalized):
    kept = quantities.variables(quantities.recorded(job))
    out = {"force": normalized * 2.0, **{name: np.ones(normalized.size, meta.dtype) for name, meta in kept.items()}}
    runfile.write_run(path, out, variables=kept, stiffness_method="punch", coordinates=("force_normalized",),
                      extra={"force_normalized": (normalized, {"long_name": "F/(E* L^2)", "units": "1"})},
                      attrs=provenance.provenance_attrs(config=dataclasses.asdict(job)))


def test_a_measured_run_is_checked_on_its_normalised_force_grid(tmp_path):
    """Its force grid is F/(E* L^2) (force_normalized): equal to 1e-12 relative reads, 1e-9 off does not."""
    grid = np.geomspace(1e-4, 1e-2, 3)
    _measured_file(tmp_path / "m.nc", MEASURED, grid)
    assert read_run(tmp_path / "m.nc", MEASURED).sizes["force"] == 3
    _measured_file(tmp_path / "off.nc", MEASURED, grid * (1 + 1e-9))
    with pytest.raises(MergeError, match="off.nc: its force grid differs"):
        read_run(tmp_path / "off.nc", MEASURED)
    with pytest.raises(MergeError, match=r"differs in index: 1 in the file, 2 now"):
        read_run(tmp_path / "m.nc", dataclasses.replace(MEASURED, index=2))


def test_gather_places_each_run_by_its_coordinates(tmp_path):
    """Two runs (seeds 3 and 4) given in reverse order land at seed 3, 4 of the merged array;
    their commits are collected once (roughcontact.study.analysis.merge.gather on a KindLayout)."""
    from roughcontact.study.analysis.merge import KindLayout, gather

    jobs = {seed: dataclasses.replace(GENERATED, seed=seed) for seed in (3, 4)}
    rows = []
    for seed in (4, 3):
        _generated_file(tmp_path / f"s{seed}.nc", jobs[seed])
        rows.append(({"seed": seed}, tmp_path / f"s{seed}.nc"))
    layout = KindLayout(kind="sphere", rows=rows, axes=(), coords={"seed": [3, 4]}, at={id(r): {} for r, _ in rows})
    got = gather(layout, lambda row: jobs[row["seed"]], {"force": "f8", "contact_cells": "i8"})
    assert got.data["contact_cells"].shape == (2, 4) and got.data["contact_cells"].dtype == np.int64
    np.testing.assert_array_equal(got.data["contact_cells"], [[3, 4, 5, 6], [4, 5, 6, 7]])
    np.testing.assert_allclose(got.data["force"][1], GENERATED.forces(), rtol=1e-15, atol=0)
    assert len(got.commits) == 1, got.commits
    assert got.attrs["contact_cells"]["units"] == "1"


def test_a_generated_runs_record_and_hash_are_those_of_finished_runs():
    """JobSettings.record() of the tiny preset's first run is the dict its run files have recorded
    since before this change (config_hash 74181d01403de942, read from a run file of 2026-11-27):
    finished result directories stay valid."""
    from pathlib import Path

    from roughcontact.study.runs import naming as runs, jobs as settings
    from roughcontact.study.config.resolve import load_config, resolve_config

    cfg = resolve_config(load_config(Path(__file__).resolve().parents[1] / "presets" / "tiny.yaml"))
    record = settings.job_settings(cfg, runs.runs(cfg)[0]).record()
    assert record == {"hurst": 0.5, "radius": 0.5, "h_rms": 0.009, "seed": 0, "n": 65, "length": 1.0, "e_star": 1.0,
                      "force_from": 1e-05, "force_to": 0.01, "force_count": 10, "tol": 1e-08,
                      "stiffness_method": "punch", "rel_step": 0.001, "maxiter": 10000, "kind": "sphere",
                      "periodic": False}
    assert provenance.config_hash(record) == "74181d01403de942"


def test_path_settings_are_derived_once_for_every_job_record():
    """A generated run's length, half-space and hardness (a pressure, hardness * E*) from its record;
    a measured run's tile length and half-space given; the solver from either record."""
    from roughcontact.study.runs.indent import path_settings

    plastic = dataclasses.replace(GENERATED, radius=float("inf"), options=(("hardness", 0.5),), e_star=2.0)
    p = path_settings(plastic)
    assert (p.length, p.periodic, p.hardness, p.tol, p.maxiter, p.force_key) == (1.0, True, 1.0, 1e-8, 10000,
                                                                                  "forces.flat.to")
    m = path_settings(MEASURED, length=3.2, periodic=False, edge_contact=False)
    assert (m.length, m.periodic, m.e_star, m.maxiter, m.hardness, m.force_key) == (3.2, False, 1.0, 100, None,
                                                                                    "forces.sphere.to")
    assert m.name == MEASURED.describe()


def test_the_one_writer_writes_a_stickiness_run_that_the_one_reader_reads(tmp_path):
    """write_run(kind="stickiness"): the approach path and scalars round-trip exactly; another kind
    is a ValueError naming both."""
    from roughcontact.study.config.stickiness import StickinessRun

    run = StickinessRun(hurst=0.8, number=0.5, seed=1, n=64, length=1.0, e_star=1.0, rms_slope=0.1, cutoff=4.0,
                        range_ratio=0.05, area=0.05, steps=8, tol=1e-8)
    rng = np.random.default_rng(3)
    out = {"depth": rng.random(5), "force": rng.normal(size=5), "contact_cells": np.arange(5), "zone_cells": np.arange(5),
           **{name: float(rng.random()) for name in runfile.STICKINESS_SCALARS}}
    runfile.write_run(tmp_path / "s.nc", out, kind="stickiness", attrs=provenance.provenance_attrs(config=run.record()))
    ds = read_run(tmp_path / "s.nc", run)
    np.testing.assert_array_equal(ds["force"].values, out["force"])
    assert float(ds["loading_slope"]) == out["loading_slope"] and ds["approach"].values.tolist() == [0, 1, 2, 3, 4]
    with pytest.raises(ValueError, match="'indentation' or 'stickiness'"):
        runfile.write_run(tmp_path / "x.nc", out, kind="sticky", attrs={})
