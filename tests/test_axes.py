"""The optional sweep axes end to end: bodies of revolution, a spectral cutoff and a
hardness through the real `snakemake` on a 65^2 grid (16 indent jobs), then the
merged dimensions, the run names, the plastic variables and the claims rows."""
from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from roughcontact import errors
from roughcontact.study.claims.registry import off_theory
from roughcontact.study.config import resolve as config
from roughcontact.study.files import io as study_io
from roughcontact.study.runs import naming as runs

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
CONFIG = {
    "grid": {"n": 65, "length": 1.0}, "e_star": 1.0, "hurst": [0.7], "radius": [0.5], "h_rms": [9.0e-3],
    "exponent": [2.0, 4.0], "cutoff": [None, 0.05], "hardness": [None, 0.05], "seeds": 2,
    "forces": {"sphere": {"from": 1.0e-4, "to": 5.0e-3, "count": 6}},
    "solver": {"tol": 1.0e-8, "stiffness": "punch"},
    "fit": {"resolved_cells": 10, "bootstrap": 100, "zeta": {"max_area_fraction": 0.1},
            "slopes": {"low_max_ratio": 0.3, "high_min_ratio": 3.0}},
}


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    work = tmp_path_factory.mktemp("axes")
    (work / "config.yaml").write_text(yaml.safe_dump(CONFIG))
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "--configfile",
                           str(work / "config.yaml"), "--cores", "2"], cwd=work, capture_output=True, text=True,
                          timeout=900, env=env)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return work, config.resolve_config(CONFIG)


def test_run_names_tag_only_the_axes_off_the_paper_setting(run):
    work, cfg = run
    names = sorted(p.name for p in (work / "results/runs").iterdir())
    assert "H0.7_R0.5_h0.009" in names, names
    assert "H0.7_R0.5_h0.009_m4.0_cutoff0.05_hardness0.05" in names, names
    assert len(names) == 8, names


def test_merged_dimensions_and_plastic_variables(run):
    work, cfg = run
    ds = study_io.read_groups(work / "results/stiffness.nc")["sphere"]
    assert ds["stiffness"].dims == (*runs.AXES["sphere"], "seed", "force"), ds["stiffness"].dims
    assert ds["exponent"].values.tolist() == [2.0, 4.0], ds["exponent"].values
    assert ds["cutoff"].values.tolist() == [0.0, 0.05], "cutoff null is the coordinate 0"
    assert ds["rolloff"].values.tolist() == [1.0], "rolloff null is the coordinate L"
    assert ds["hardness"].values[0] == 0.05 and math.isinf(ds["hardness"].values[1]), ds["hardness"].values
    assert np.issubdtype(ds["plastic_cells"].dtype, np.integer), ds["plastic_cells"].dtype
    elastic = ds.sel(hardness=math.inf)
    assert int(elastic["plastic_cells"].max()) == 0, "an elastic run has no plastic cell"
    np.testing.assert_array_equal(elastic["loading_stiffness"].values, elastic["stiffness"].values,
                                  err_msg="an elastic run's loading tangent is its stiffness")
    plastic = ds.sel(hardness=0.05)
    assert int(plastic["plastic_cells"].isel(force=-1).min()) > 0, "hardness 0.05 E* flows at the largest load"
    assert not ds["stiffness"].isnull().any(), "no NaN padding"


def test_claims_rows_of_the_axes(run):
    work, _ = run
    table = pd.read_csv(work / "results/claims.csv", keep_default_na=False, na_values=[""])
    assert set(table["verdict"]) <= {"consistent", "differs", "untested"}, set(table["verdict"])
    for claim in "ik":
        rows = table[table["claim"] == claim]
        assert len(rows) >= 2, f"claim ({claim}) has {len(rows)} rows"
    unloading = table[(table["claim"] == "k") & table["statement"].str.contains("unloading")]
    assert (unloading["measured"] > 0).all(), unloading[["measured", "verdict"]]
    rolloff = table[table["claim"] == "j"]
    assert rolloff["reason"].tolist() == ["no rolloff swept"], rolloff["reason"]
    body = table[(table["claim"] == "a") & (table["exponent"] == 4.0)]
    # two rows per combination (every resolved load, the fractal branch alone), 4 combinations
    assert len(body) == 8 and body["statement"].str.contains("m = 4").all(), body["statement"]


def test_the_papers_theory_is_not_judged_off_its_setting(run):
    """Rows (a)-(f) of a combination with a cutoff or a hardness keep their measured value
    but are 'untested', naming the claim that tests the axis; elastic self-affine rows are judged."""
    work, _ = run
    table = pd.read_csv(work / "results/claims.csv", keep_default_na=False, na_values=[""])
    theory_rows = table[table["claim"].isin(list("abcdef")) & table["radius"].notna()]
    plastic = theory_rows[theory_rows["hardness"] == 0.05]
    assert len(plastic) >= 12, f"{len(plastic)} rows (a)-(f) with a hardness"
    assert (plastic["verdict"] == "untested").all(), plastic[["claim", "verdict"]]
    assert plastic["reason"].str.contains("claim k").all(), plastic["reason"]
    assert plastic["measured"].notna().any(), "the measured values are kept"
    cut = theory_rows[(theory_rows["cutoff"] == 0.05) & np.isinf(theory_rows["hardness"])]
    assert len(cut) >= 6, f"{len(cut)} rows (a)-(f) with a cutoff alone"
    assert cut["reason"].str.contains("claim i").all(), cut["reason"]
    assert not cut["reason"].str.contains("claim k").any(), cut["reason"]
    elastic = theory_rows[(theory_rows["cutoff"] == 0.0) & np.isinf(theory_rows["hardness"])]
    assert len(elastic) >= 6, f"{len(elastic)} rows (a)-(f) at the paper's setting"
    assert not elastic["reason"].str.contains("self-affine").any(), elastic[["claim", "reason"]]


@pytest.mark.parametrize("axis, value, claim", [("rolloff", 0.25, "j"), ("cutoff", 0.05, "i"),
                                                ("hardness", 0.2, "k")])
def test_off_theory_reason_names_the_claim_of_each_axis(axis, value, claim):
    """A combination off the paper's setting in one optional axis is untested by eqs. 11-17,
    and the reason names the claim that tests that axis; the paper's setting has no reason."""
    paper = {"rolloff": 1.0, "cutoff": 0.0, "hardness": math.inf, "exponent": 2.0}
    assert off_theory(paper, 1.0) == "", "the paper's setting is judged"
    reason = off_theory({**paper, axis: value}, 1.0)
    assert reason.startswith("untested: ") and f"{axis} = {value:g} (claim {claim}" in reason, reason


def test_a_figure_per_body_and_variant(run):
    work, _ = run
    names = {p.name for p in (work / "results/figures").glob("fig3_*.png")}
    assert len(names) == 8, names
    assert "fig3_H0.7_R0.5_h0.009_m4.0.png" in names, names


@pytest.mark.parametrize("change, key", [
    ({"hurst": [1.0], "exponent": [1.0, 2.0]}, "'exponent[0]'"),   # parallel asymptotes: no crossover
    ({"rolloff": [None, 1.0]}, "'rolloff'"),                         # a roll-off at L is no roll-off
    ({"rolloff": [2.0]}, "'rolloff[0]'"),                            # longer than the surface
    ({"cutoff": [0.01]}, "'cutoff[0]'"),                             # below 2 cells of L/65
    ({"cutoff": [0.3], "rolloff": [0.25]}, "'cutoff[0]'"),           # no self-affine band left
    ({"hardness": [0.001]}, "'hardness[0]'"),                        # fully plastic beyond L/4
])
def test_optional_axes_reject_nonsense_in_one_line(change, key):
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config({**CONFIG, **change})
    line = config.error_line(info.value)
    assert len(line.splitlines()) == 1 and line.startswith("Invalid configuration"), line
    assert key in line, line


@pytest.mark.parametrize("axis, value", [("rolloff", None), ("rolloff", 0.25), ("cutoff", None), ("cutoff", 0.03),
                                         ("hardness", None), ("hardness", 0.2)])
def test_axis_value_inverts_coordinate(axis, value):
    coordinate = runs.coordinate(axis, value, 1.0)
    assert runs.axis_value(axis, coordinate, 1.0) == value, f"{axis} {value} -> {coordinate} and back"
