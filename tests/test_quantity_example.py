"""The guide's per-load quantity, done (``docs/guide/extending/quantity_example.py``): copied as one
new module into a scratch copy of the package, with no other edit, it is listed, a study that names
it runs end to end through the real ``snakemake`` and keeps it in the merged files, and a study made
before it was copied in reruns none of its runs."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml
from examples import EXAMPLES, module_of

pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
EXAMPLE = EXAMPLES / "quantity_example.py"
BASE = {"grid": {"n": 65, "length": 1.0, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [2.0e-2],
        "seeds": 2, "forces": {"sphere": {"from": 1.0e-4, "to": 1.0e-2, "count": 5}}}


def _run(where: Path, config: Path, *args: str, tool=("-m", "snakemake", "--cores", "2", "--configfile")):
    env = {**os.environ, "PYTHONPATH": str(where / "src")}
    done = subprocess.run([sys.executable, *tool, str(config), *args], cwd=where, env=env, capture_output=True,
                          text=True, timeout=900)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    return done


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    """A scratch checkout in which BASE ran before the example was copied in, then BASE with the
    example's quantity named, in a directory of its own."""
    where = tmp_path_factory.mktemp("quantity")
    target = Path(*module_of(EXAMPLE).split(".")).with_suffix(".py")
    shutil.copytree(ROOT / "src", where / "src", ignore=lambda folder, names: {
        n for n in names if n == "__pycache__" or n.endswith(".egg-info") or Path(folder, n) == ROOT / "src" / target})
    for folder in ("workflow", "envs"):
        shutil.copytree(ROOT / folder, where / folder, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "Snakefile", where / "Snakefile")
    base = where / "base.yaml"
    base.write_text(yaml.safe_dump(BASE))
    _run(where, base, "-q", "--directory", str(where))   # in the checkout's results/, not studies/base/
    before = {p: p.read_bytes() for p in sorted((where / "results" / "runs").rglob("*.nc"))}
    assert not (where / "src" / target).exists()
    shutil.copy(EXAMPLE, where / "src" / target)
    planned = _run(where, base, "-n", "--directory", str(where)).stdout
    study = where / "with.yaml"
    study.write_text(yaml.safe_dump({**BASE, "fields": {"quantities": ["peak_pressure", "mean_contact_pressure"]}}))
    _run(where, study, "-q", "--directory", str(where / "with"))
    return where, before, planned


def test_the_example_is_listed(scratch):
    where, _, _ = scratch
    done = _run(where, Path("quantities"), "--json", tool=("-m", "roughcontact.cli", "list"))
    assert "peak_pressure" in [row["name"] for row in json.loads(done.stdout)]


def test_a_study_without_it_reruns_no_run(scratch):
    where, before, planned = scratch
    assert "indent" not in planned, planned[-2000:]
    assert {p: p.read_bytes() for p in before} == before


def test_the_merged_files_keep_it_and_it_bounds_the_mean_contact_pressure(scratch):
    """The peak pressure is at least the mean over the contact, F/A, at every load of every run (a
    bound that fails for a wrong quantity: e.g. the mean over the grid is far below it)."""
    import xarray as xr

    where, _, _ = scratch
    with xr.open_dataset(where / "with" / "results" / "stiffness.nc", group="sphere") as ds:
        peak, mean = ds["peak_pressure"].values, ds["mean_contact_pressure"].values
        assert ds["peak_pressure"].attrs["units"] == "e_star"
    assert np.isfinite(peak).all()
    assert (peak >= mean * (1 - 1e-12)).all()
    assert (peak > 1.5 * mean).any(), "a sphere's peak stays near its mean pressure at no load"
    with xr.open_dataset(where / "with" / "results" / "ensemble.nc", group="sphere") as ens:
        assert np.allclose(ens["peak_pressure_mean"].values, peak.mean(axis=-2), rtol=1e-12)
