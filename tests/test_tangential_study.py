"""The tangential problem in the study: the axes poisson and friction, the path kind, claims (r)-(t).

Closed forms (Johnson 1985 §7.2; Ciavarella 1998, Jäger 1998; Grzemba et al. 2014):
* ``ν = 0``: the Cerruti kernel's ``u_x`` equals the normal kernel's ``u_z`` (same ``E*``), so the
  full-stick ``k_t`` of a contact set equals its punch stiffness ``k_n`` to the solves' tolerance
  (1e-8; asserted 1e-6) and the largest micro-slip is ``μ d`` (``u_x[μp] = μ u_z[p] = μ(d − h)`` on the
  contact set; at the highest cell ``h`` is the cell-centre height below the apex, so the relative
  error is that cell's distance from the true apex, ≤ 1e-3 here);
* a smooth sphere with the contact radius ``a ≥ 14`` cells: ``k_t/k_n = 2(1 − ν)/(2 − ν)`` within 1 %
  (the bem tests measure the discretization error of the ratio at 0.3–0.6 % there);
* claims: synthetic ensembles that follow Mindlin, Cattaneo–Mindlin and Grzemba exactly are judged
  ``consistent``, ones 10 % off are ``differs``.
"""
from __future__ import annotations

import copy
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml

from roughcontact import errors
from roughcontact.models import tangential as theory
from roughcontact.study.config import axes
from roughcontact.study.config import resolve as config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.runs import indent, jobs, naming

REPO = Path(__file__).resolve().parents[1]

GOOD = {
    "grid": {"n": 65, "length": 1.0},
    "hurst": [0.7],
    "radius": [0.5],
    "h_rms": [2e-3],
    "seeds": 2,
    "forces": {"sphere": {"from": 1e-5, "to": 1e-3, "count": 5}},
    "poisson": [0.3],
    "friction": [0.4],
    "tangential": {"at": [1e-4], "steps": 4},
}


def _with(**changes):
    cfg = copy.deepcopy(GOOD)
    for key, value in changes.items():
        node = cfg
        *path, last = key.split("__")
        for part in path:
            node = node[part]
        node[last] = value
    return cfg


BAD = [
    ("poisson-minus-one", {"poisson": [-1.0]}, "poisson"),
    ("poisson-above-half", {"poisson": [0.6]}, "poisson"),
    ("poisson-nan", {"poisson": [math.nan]}, "poisson"),
    ("poisson-mixed-null", {"poisson": [None, 0.3]}, "poisson"),
    ("poisson-flat-only", {"radius": [math.inf], "forces": {"flat": {"from": 1e-5, "to": 1e-4, "count": 4}}},
     "poisson"),
    ("friction-negative", {"friction": [-0.1]}, "friction"),
    ("friction-nan", {"friction": [math.nan]}, "friction"),
    ("friction-without-poisson", {"poisson": [None]}, "friction"),
    ("friction-with-hardness", {"hardness": [0.5], "poisson": [None]}, "friction"),
    ("poisson-with-hardness", {"hardness": [0.5]}, "poisson"),
    ("poisson-with-adhesion", {"work_of_adhesion": [1e-4], "solver": {"tol": 1e-8, "stiffness": "punch"}}, "poisson"),
    ("slip-load-outside-path", {"tangential": {"at": [1e-1]}}, "tangential.at"),
    ("slip-steps-zero", {"tangential": {"steps": 0}}, "tangential.steps"),
]


@pytest.mark.parametrize("changes,named", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_tangential_config_rejected_with_one_line(changes, named):
    with pytest.raises(errors.ConfigError) as err:
        config.resolve_config(_with(**changes))
    msg = str(err.value)
    assert "\n" not in msg, msg
    assert named in msg, msg
    assert "allowed" in msg, msg


def test_bad_friction_stops_snakemake_before_any_job(tmp_path):
    (tmp_path / "bad.yaml").write_text(yaml.safe_dump(_with(friction=[-0.5])))
    r = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(REPO / "Snakefile"), "-d", str(tmp_path),
                        "--configfile", str(tmp_path / "bad.yaml"), "--cores", "1"],
                       capture_output=True, text=True, timeout=120)
    out = r.stdout + r.stderr
    assert r.returncode != 0, out
    lines = [line for line in out.splitlines() if "Invalid configuration" in line]
    assert len(lines) == 1 and "friction" in lines[0], out
    assert not (tmp_path / "results").exists()


def test_a_study_without_the_axes_keeps_its_runs_names_and_dimensions():
    """config.yaml: no run carries poisson or friction (names, records), and the merged files'
    dimensions are the normal axes only."""
    cfg = yaml.safe_load((REPO / "config.yaml").read_text())
    study = StudySettings.of(config.resolve_config(cfg))
    for run in naming.runs(study):
        record = jobs.job_settings(study, run).record()
        assert "poisson" not in record and "friction" not in record and "slip_loads" not in record
        assert "_nu" not in naming.combo_name(run) and "_mu" not in naming.combo_name(run)
    assert "poisson" not in naming.AXES["sphere"] and "friction" not in naming.AXES["sphere"]
    assert set(axes.paper_coordinates(1.0)).isdisjoint({"poisson", "friction"})


def test_runs_of_each_poisson_ratio_share_the_normal_representative():
    study = StudySettings.of(config.resolve_config(_with(poisson=[0.0, 0.3], friction=[0.0, 0.4])))
    table = naming.runs(study)
    assert len(table) == 2 * 2 * 2    # poisson x friction x seeds
    kept = [r for r in table if naming.normal_representative(study, r)]
    assert [(r["poisson"], r["friction"]) for r in kept] == [(0.0, 0.0)] * 2
    assert naming.sphere_names(study) == ["H0.7_R0.5_h0.002"]


def _run(poisson: float, h_rms: float = 2e-3, n: int = 65, **forces):
    cfg = _with(poisson=[poisson], grid={"n": n, "length": 1.0}, h_rms=[h_rms],
                forces={"sphere": {"from": 1e-5, "to": 1e-3, "count": 5, **forces}},
                tangential={"at": [1e-3], "steps": 4})
    study = StudySettings.of(config.resolve_config(cfg))
    settings = jobs.job_settings(study, naming.runs(study)[0])
    return settings, indent.compute_run(settings)


def test_at_poisson_zero_the_tangential_stiffness_is_the_normal_one():
    _, out = _run(0.0)
    np.testing.assert_allclose(out["tangential_stiffness"], out["stiffness"], rtol=1e-6)


def test_at_poisson_zero_the_largest_micro_slip_is_mu_d():
    settings, out = _run(0.0)
    np.testing.assert_allclose(out["gross_slip_displacement"], settings.friction * out["slip_depth"], rtol=1e-3)


def test_smooth_sphere_stiffness_ratio_is_mindlins():
    """a = (3FR/4E*)^(1/3) = 0.072 L at F = 1e-3, R = 0.5: 14 cells on 193²."""
    _, out = _run(0.3, h_rms=1e-9, n=193, **{"from": 5e-4, "count": 2})
    np.testing.assert_allclose(out["tangential_stiffness"][-1] / out["stiffness"][-1], theory.stiffness_ratio(0.3),
                               rtol=1e-2)


def test_partial_slip_path_is_in_the_run(tmp_path):
    settings, out = _run(0.3)
    indent.write_run(tmp_path / "run.nc", settings, out)
    from roughcontact.study.files.io import read_run

    ds = read_run(tmp_path / "run.nc", settings)
    assert ds.sizes["slip_step"] == 4
    assert np.all(np.diff(ds["slip_displacement"].values, axis=-1) > 0)   # δ_x grows with Q


# -- claims on synthetic ensembles ------------------------------------------------------------------
def _synthetic(factor: float = 1.0, seeds: int = 6):
    """A full_stick and a partial_slip group on a Hertzian sphere (k_n ∝ F^(1/3), a in cells ≥ 50)
    whose k_t, k_t(Q) and δ_max follow Mindlin, Cattaneo–Mindlin and Grzemba times *factor*, with
    1 % noise over seeds (δ_max: paired factors 1 ± 1 %); F_tr far below the loads (all on the Hertz
    branch)."""
    rng = np.random.default_rng(3)
    force = np.geomspace(1e-4, 1e-2, 8)
    nu, mu = 0.3, 0.5
    k_n = force ** (1 / 3) * (1 + 0.01 * rng.standard_normal((seeds, force.size)))
    ratio = theory.stiffness_ratio(nu) * factor
    coords = {"hurst": [0.7], "radius": [0.5], "h_rms": [1e-3], "poisson": [nu], "seed": np.arange(seeds)}
    stick = xr.Dataset(
        {"stiffness": (("hurst", "radius", "h_rms", "poisson", "seed", "force"), k_n[None, None, None, None]),
         "tangential_stiffness": (("hurst", "radius", "h_rms", "poisson", "seed", "force"),
                                  ratio * k_n[None, None, None, None]),
         "contact_cells": (("hurst", "radius", "h_rms", "poisson", "seed", "force"),
                           np.full((1, 1, 1, 1, seeds, force.size), 1e4)),
         "depth": (("hurst", "radius", "h_rms", "poisson", "seed", "force"),
                   np.broadcast_to(force ** (2 / 3), (1, 1, 1, 1, seeds, force.size)).copy())},
        coords={**coords, "force": force, "force_normalized": ("force", force)})
    f = np.arange(1, 5) / 5
    loads = np.array([4, 6])
    slip_k = ratio * k_n[:, loads, None] * theory.cattaneo_stiffness_ratio(f)[None, None] * factor
    depth = force[loads] ** (2 / 3) * np.ones((seeds, 1))
    # per-seed factors 1 ± 1 % in pairs (their mean is 1): δ_max has an interval over the seeds
    paired = 1 + 0.01 * np.array([-1.0, 1.0, -0.5, 0.5, -0.25, 0.25, -0.75, 0.75])[:seeds, None]
    delta = theory.largest_micro_slip(depth, friction=mu, poisson=nu) * factor * paired
    dims = ("hurst", "radius", "h_rms", "poisson", "friction", "seed")
    slip = xr.Dataset(
        {"slip_stiffness": ((*dims, "slip_load", "slip_step"), slip_k[None, None, None, None, None]),
         "slip_depth": ((*dims, "slip_load"), depth[None, None, None, None, None]),
         "gross_slip_displacement": ((*dims, "slip_load"), delta[None, None, None, None, None])},
        coords={**coords, "friction": [mu], "slip_load": force[loads], "slip_load_index": ("slip_load", loads),
                "slip_step": f})
    return {"full_stick": stick, "partial_slip": slip}


def _claims(groups):
    from roughcontact.study.claims import claims
    from roughcontact.study.claims.registry import ClaimInputs, table_rows

    study = StudySettings.of(config.resolve_config(_with(seeds=6, **{"fit": {"bootstrap": 200}})))
    cross = pd.DataFrame([{"hurst": 0.7, "radius": 0.5, "h_rms": 1e-3, "exponent": 2.0, "Ftr_measured": 1e-6,
                           "Ftr_pred_estimate": 1e-6}])
    inputs = ClaimInputs(cross=cross, replicates=None, zeta=None, study=study, tangential=groups)
    rows = []
    for letter in ("r", "s", "t"):
        rows += table_rows(claims()[letter], inputs)
    return pd.DataFrame(rows)


def _hertz(table, letter):
    return table[(table["claim"] == letter) & table["statement"].str.contains("Hertz branch")].iloc[0]


@pytest.mark.parametrize("letter", ["r", "s", "t"])
def test_claims_consistent_on_an_ensemble_that_follows_the_closed_forms(letter):
    assert _hertz(_claims(_synthetic()), letter)["verdict"] == "consistent"


@pytest.mark.parametrize("letter", ["r", "s", "t"])
def test_claims_differ_on_an_ensemble_ten_percent_off(letter):
    assert _hertz(_claims(_synthetic(factor=1.1)), letter)["verdict"] == "differs"


def test_fractal_branch_without_loads_is_untested_and_says_why():
    row = _claims(_synthetic()).query("claim == 'r'").iloc[0]
    assert (row["verdict"], row["untested_because"]) == ("untested", "not swept")
