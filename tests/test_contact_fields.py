"""Contact fields and patches kept by a run (config section ``fields``): the kept pressure carries
the load, the kept gap closes on the contact, the patch counts are those of the contact set, and a
study that keeps nothing more keeps its runs' names and hashes."""
import math

import numpy as np
import pytest
import xarray as xr
import yaml

from roughcontact import errors
from roughcontact.bem.patches import contact_patches
from roughcontact.study.config import resolve_config
from roughcontact.study.files import io, provenance, runfile
from roughcontact.study.runs import indent, jobs, naming

CONFIG = {"grid": {"n": 65, "length": 1.0}, "hurst": [0.7], "radius": [0.5], "h_rms": [2e-3], "seeds": 1,
          "forces": {"sphere": {"from": 1e-5, "to": 1e-3, "count": 5}}}


def _job(**fields):
    cfg = resolve_config({**CONFIG, "fields": fields})
    return jobs.job_settings(cfg, naming.runs(cfg)[0])


@pytest.fixture(scope="module")
def kept(tmp_path_factory):
    """One run keeping its patches and the fields of its loads 1e-4 and 1e-3 (indices 2 and 4)."""
    job = _job(patches=True, at=[1e-4, 1e-3])
    path = tmp_path_factory.mktemp("fields") / "run.nc"
    out = indent.compute_run(job)
    indent.write_run(path, job, out)
    return job, path, out


def test_kept_loads_are_the_nearest(kept):
    job, _, _ = kept
    assert job.field_loads == (2, 4)


def test_kept_pressure_carries_the_load(kept):
    """F = Σ p Δ² over the window (it holds every contact cell), to round-off."""
    _, path, out = kept
    with xr.open_dataset(path, group=runfile.FIELD_GROUP.format(index=4)) as ds:
        carried = float(ds["pressure"].sum()) * ds.attrs["cell_size"] ** 2
    assert carried == pytest.approx(out["force"][4], rel=1e-12)


def test_kept_gap_closes_on_the_contact(kept):
    """The gap on contact cells is zero to the solver's tolerance (tol · d, d the approach)."""
    job, path, out = kept
    with xr.open_dataset(path, group=runfile.FIELD_GROUP.format(index=2)) as ds:
        gap = ds["gap"].values[ds["contact"].values == 1]
    assert np.abs(gap).max() <= 10 * job.tol * out["depth"][2]


def test_kept_contact_is_the_runs_contact_cells(kept):
    _, path, out = kept
    with xr.open_dataset(path, group=runfile.FIELD_GROUP.format(index=2)) as ds:
        assert int(ds["contact"].sum()) == out["contact_cells"][2]


def test_largest_patch_is_at_most_the_contact(kept):
    _, _, out = kept
    assert (out["largest_patch_cells"] <= out["contact_cells"]).all()


def test_patches_are_those_of_the_kept_contact(kept):
    _, path, out = kept
    with xr.open_dataset(path, group=runfile.FIELD_GROUP.format(index=4)) as ds:
        patches = contact_patches(ds["contact"].values == 1)
    assert (patches.count, patches.largest) == (out["contact_patches"][4], out["largest_patch_cells"][4])


def test_the_file_reads_back_with_its_patches(kept):
    job, path, _ = kept
    ds = io.read_run(path, job)
    assert {"contact_patches", "largest_patch_cells"} <= set(ds.data_vars)


def test_fields_at_their_defaults_leave_the_hash():
    assert provenance.config_hash(_job().record()) == provenance.config_hash(
        jobs.job_settings(resolve_config(CONFIG), naming.runs(resolve_config(CONFIG))[0]).record())


def test_fields_change_the_hash_of_the_runs_that_keep_them():
    assert provenance.config_hash(_job(patches=True).record()) != provenance.config_hash(_job().record())


@pytest.mark.parametrize("fields, key", [({"at": [1.0]}, "fields.at[0]"), ({"at": [-1e-4]}, "fields.at"),
                                          ({"patches": "yes"}, "fields.patches"), ({"color": 1}, "fields")])
def test_bad_fields_name_their_key(fields, key):
    with pytest.raises(errors.ConfigError) as err:
        resolve_config({**CONFIG, "fields": fields})
    assert err.value.key.startswith(key), err.value.key


def test_fields_with_adhesion_are_refused():
    with pytest.raises(errors.ConfigError, match="work_of_adhesion"):
        resolve_config({**CONFIG, "work_of_adhesion": [1e-4], "fields": {"patches": True}})


def test_the_merge_stacks_the_patch_counts(kept):
    from roughcontact.study.analysis.merge import merge_runs

    job, path, out = kept
    cfg = resolve_config({**CONFIG, "fields": {"patches": True, "at": [1e-4, 1e-3]}})
    merged = merge_runs(cfg, [path])["sphere"]
    assert merged["contact_patches"].values.ravel().tolist() == out["contact_patches"].tolist()
