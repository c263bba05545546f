"""`snakemake --cores 2` on a tiny tangential study (axes poisson and friction): the run files hold the
tangential path kind, the normal merged files keep their dimensions, tangential.nc has both groups,
claims (r)-(t) have rows with verdict words, and the report's three figures are drawn."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr
import yaml

from roughcontact.study.analysis.statistics import VERDICTS
from roughcontact.study.files.io import read_groups

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

REPO = Path(__file__).resolve().parents[1]

CONFIG = {
    "grid": {"n": 65, "length": 1.0, "coarse": None},
    "hurst": [0.7],
    "radius": [0.5],
    "h_rms": [9e-3],
    "poisson": [0.3],
    "friction": [0.4],
    "seeds": 2,
    "forces": {"sphere": {"from": 1e-5, "to": 5e-3, "count": 8}},
    "tangential": {"at": [1e-4, 3e-3], "steps": 4},
    "fit": {"resolved_cells": 10, "bootstrap": 200},
}


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    work = tmp_path_factory.mktemp("tangential")
    (work / "tangential.yaml").write_text(yaml.safe_dump(CONFIG))
    r = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(work),
                        "--configfile", str(work / "tangential.yaml"), "--cores", "2", "-q"],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    return work


def test_run_files_hold_the_partial_slip_path(workdir):
    runs = sorted((workdir / "results" / "runs").rglob("*.nc"))
    assert [p.parent.name for p in runs] == ["H0.7_R0.5_h0.009_nu0.3_mu0.4"] * 2
    with xr.open_dataset(runs[0]) as ds:
        assert (ds.sizes["slip_load"], ds.sizes["slip_step"]) == (2, 4)


def test_normal_merged_files_keep_their_dimensions(workdir):
    sphere = read_groups(workdir / "results" / "stiffness.nc")["sphere"]
    assert sphere["stiffness"].dims == ("hurst", "radius", "exponent", "h_rms", "rolloff", "cutoff", "hardness",
                                        "work_of_adhesion", "seed", "force")


def test_tangential_file_has_both_groups(workdir):
    groups = read_groups(workdir / "results" / "tangential" / "tangential.nc")
    assert groups["partial_slip"]["slip_stiffness"].dims[-4:] == ("friction", "seed", "slip_load", "slip_step")
    assert "poisson" in groups["full_stick"]["tangential_stiffness"].dims


@pytest.mark.parametrize("letter", ["r", "s", "t"])
def test_tangential_claims_have_rows_with_verdict_words(workdir, letter):
    import pandas as pd

    claims = pd.read_csv(workdir / "results" / "claims.csv")
    rows = claims[claims["claim"] == letter]
    assert len(rows) and set(rows["verdict"]) <= set(VERDICTS) - {"error"}, rows[["verdict", "reason"]]


@pytest.mark.parametrize("name", ["ratio.png", "partial_slip.png", "micro_slip.png"])
def test_figures_are_drawn(workdir, name):
    assert (workdir / "results" / "tangential" / name).stat().st_size > 10_000
