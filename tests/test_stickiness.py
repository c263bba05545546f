"""Pastewka & Robbins' stickiness study (roughcontact.study.runs.stickiness): the config section, the
surface and interaction of a run against the closed-form criterion, the loading slope on paths
with known answers, the sign of the slope far from N = 1, the merged table and claim (q)."""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml

from roughcontact.bem import solve
from roughcontact.errors import ConfigError, MergeError
from roughcontact.models.rough_adhesion import STICKINESS_RANGE_LIMIT
from roughcontact import cli
from roughcontact.study import claims
from roughcontact.study.files import provenance, runfile
from roughcontact.study.config.resolve import load_config, resolve_config, study_settings
from roughcontact.study.config.stickiness import StickinessSettings
from roughcontact.study.runs.stickiness import loading_slope, stickiness_run
from roughcontact.study.analysis.stickiness import merge_stickiness, stickiness_table, threshold
from roughcontact.study.runs.stickiness import stickiness_surface
from roughcontact.surfaces.moments import spectral_moments

ROOT = Path(__file__).resolve().parents[1]
TINY = load_config(ROOT / "presets" / "tiny.yaml")


def _settings(**section) -> StickinessSettings:
    return StickinessSettings.of(resolve_config({**TINY, "stickiness": section}))


# --- the configuration -------------------------------------------------------------------------

def test_no_section_is_no_sweep():
    assert StickinessSettings.of(resolve_config(TINY)) is None, "a config without stickiness has no sweep"


def test_an_empty_section_takes_the_schemas_defaults():
    s = _settings()
    assert (s.n, s.hurst, s.number, s.seeds, s.cutoff, s.range_ratio) == (512, (0.8,), (0.5, 3.0), 4, 16.0, 0.05), s


@pytest.mark.parametrize("section, key", [
    ({"number": [-1.0]}, "stickiness.number"), ({"number": [math.nan]}, "stickiness.number"),
    ({"rms_slope": 0.0}, "stickiness.rms_slope"), ({"cutoff": 40, "n": 64}, "stickiness.cutoff"),
    ({"seeds": 1}, "stickiness.seeds"), ({"radius": 1.0}, "stickiness"), ({"area": 0.5}, "stickiness.area")])
def test_a_bad_value_is_one_line_naming_the_key(section, key):
    with pytest.raises(ConfigError) as err:
        resolve_config({**TINY, "stickiness": section})
    assert key in str(err.value) and "\n" not in str(err.value), str(err.value)


def test_check_config_counts_the_stickiness_runs(tmp_path, capsys):
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump({**TINY, "stickiness": {"number": [0.5, 2.0, 4.0], "seeds": 3}}))
    assert cli.main(["check-config", str(path)]) == 0, capsys.readouterr().err
    assert "stickiness: 9 runs (1 H x 3 N x 3 seeds on 512²)" in capsys.readouterr().out, "the count"


def test_check_config_names_a_bad_stickiness_key(tmp_path, capsys):
    path = tmp_path / "c.yaml"
    path.write_text(yaml.safe_dump({**TINY, "stickiness": {"range_ratio": -0.1}}))
    assert cli.main(["check-config", str(path)]) == 2, "exit code"
    err = capsys.readouterr().err
    assert "stickiness.range_ratio" in err and err.count("\n") == 1, err


def test_jobs_run_by_hurst_then_number_then_seed():
    s = _settings(hurst=[0.8, 0.5], number=[3.0, 0.5], seeds=2)
    got = [(j.hurst, j.number, j.seed) for j in s.jobs()]
    assert got[:3] == [(0.5, 0.5, 0), (0.5, 0.5, 1), (0.5, 3.0, 0)], got


def test_an_unknown_job_names_the_sweep():
    with pytest.raises(KeyError, match="H0.8_N0.5"):
        _settings().job("H0.8_N7", 0)


# --- a run's identity: its own settings, not the configuration -----------------------------------

def test_more_seeds_or_numbers_leave_a_runs_settings_and_hash_unchanged():
    """A run shared by two sweeps that differ by one more seed, number or H (or by the merge's
    interval, fit.zeta) has equal settings and config_hash: Snakemake reruns nothing."""
    base = _settings(hurst=[0.8], number=[0.5], seeds=2)
    run = base.job("H0.8_N0.5", 1)
    for other in (_settings(hurst=[0.8], number=[0.5], seeds=3), _settings(hurst=[0.8], number=[0.5, 3.0], seeds=2),
                  _settings(hurst=[0.5, 0.8], number=[0.5], seeds=2)):
        assert other.job("H0.8_N0.5", 1) == run, other
        assert provenance.config_hash(other.job("H0.8_N0.5", 1).record()) == provenance.config_hash(run.record())
    bootstrap = StickinessSettings.of(resolve_config({**TINY, "stickiness": {"hurst": [0.8], "number": [0.5]},
                                                      "fit": {"bootstrap": 17}}))
    assert bootstrap.job("H0.8_N0.5", 1) == run, "the merge's bootstrap is no setting of a run"


def test_another_grid_or_tolerance_is_another_run():
    run = _settings(hurst=[0.8], number=[0.5]).job("H0.8_N0.5", 0)
    for other in (_settings(hurst=[0.8], number=[0.5], n=256), _settings(hurst=[0.8], number=[0.5], steps=9)):
        assert provenance.config_hash(other.job("H0.8_N0.5", 0).record()) != provenance.config_hash(run.record())


def test_the_tolerance_is_the_solvers_capped_at_1e_8():
    """solver.tol 1e-6 gives 1e-8 exactly, 1e-10 stays 1e-10."""
    loose = resolve_config({**TINY, "solver": {**TINY["solver"], "tol": 1e-6}, "stickiness": {}})
    tight = resolve_config({**TINY, "solver": {**TINY["solver"], "tol": 1e-10}, "stickiness": {}})
    assert StickinessSettings.of(loose).tol == 1e-8 and StickinessSettings.of(tight).tol == 1e-10


def test_the_run_file_records_the_runs_settings_and_their_hash(tmp_path, monkeypatch):
    """config and config_hash of a stickiness run file are those of its StickinessRun (the
    loading path itself replaced by a stub: what is written, not what is solved)."""
    import roughcontact.study.runs.stickiness as run_module
    from roughcontact.study.rules import stickiness_run as rule

    s = _settings(hurst=[0.8], number=[0.5], steps=8)
    run = s.job("H0.8_N0.5", 0)
    stub = {"depth": np.zeros(2), "force": np.zeros(2), "contact_cells": np.zeros(2, int), "zone_cells": np.zeros(2, int),
            **{name: 0.5 for name in runfile.STICKINESS_SCALARS}}
    monkeypatch.setattr(run_module, "stickiness_run", lambda r: stub)
    rule.run(run, output=tmp_path / "r.nc")
    with xr.open_dataset(tmp_path / "r.nc") as ds:
        assert json.loads(ds.attrs["config"]) == run.record()
        assert ds.attrs["config_hash"] == provenance.config_hash(run.record())


# --- the surface and its interaction: the closed-form criterion ---------------------------------

@pytest.mark.parametrize("n", [64, 65])
def test_the_surface_has_the_sweeps_rms_gradient(n):
    s = _settings(n=n, cutoff=4)
    surface = stickiness_surface(s.run(hurst=0.8, number=0.5, seed=3))
    slope = math.sqrt(2.0 * spectral_moments(surface.heights, length=s.length).m2)
    assert slope == pytest.approx(s.rms_slope, rel=1e-12), f"h' on {n}^2"


@pytest.mark.parametrize("n", [64, 65])
@pytest.mark.parametrize("number", [0.5, 3.0])
def test_the_interaction_has_the_jobs_number_and_range(n, number):
    """w and dr invert Pastewka & Robbins' number N = (h'E* dr/(2w))(h'^2/(h'' dr))^(2/3) and
    dr/g0 exactly (rounding only)."""
    s = _settings(n=n, cutoff=4)
    criterion = stickiness_surface(s.run(hurst=0.8, number=number, seed=1)).criterion
    assert criterion.number == pytest.approx(number, rel=1e-12), "N"
    assert criterion.range_ratio == pytest.approx(s.range_ratio, rel=1e-12), "dr/g0"


# --- the loading slope on paths whose answer is known ------------------------------------------

def test_loading_slope_of_a_linear_path_is_its_slope():
    area = np.array([0.0, 0.01, 0.03, 0.06, 0.09])
    assert loading_slope(0.4 * area, area, at=0.05) == pytest.approx(0.4, rel=1e-12), "F = 0.4 A"


def test_loading_slope_of_a_jump_is_interpolated_from_the_surfaces_apart():
    """A path whose first state already covers 0.1 under F = -0.02: F(A*)/A* = -0.02/0.1 on the
    chord from (0, 0)."""
    assert loading_slope([-0.02, -0.01], [0.1, 0.2], at=0.05) == pytest.approx(-0.2, rel=1e-12), "jump"


def test_loading_slope_is_nan_short_of_the_area():
    assert math.isnan(loading_slope([0.0, 0.001], [0.0, 0.01], at=0.05)), "the path never reaches A*"


@pytest.fixture(scope="module")
def extremes():
    """128^2, cutoff 4 cells, one surface at N = 0.3 and N = 1000 (about 8 s)."""
    s = _settings(n=128, cutoff=4, number=[0.3, 1000.0], seeds=2, steps=16)
    return s, {number: stickiness_run(s.run(hurst=0.8, number=number, seed=0)) for number in s.number}


def test_far_below_one_the_surface_is_sticky(extremes):
    _, runs = extremes
    assert runs[0.3]["loading_slope"] < 0.0, runs[0.3]["loading_slope"]


def _repulsive_slope(s, heights):
    """F/(h'E* A) at A = s.area of *heights* without adhesion: force-controlled solves of
    roughcontact.bem.solve (another algorithm than the cohesive path's), the force that first
    covers s.area found by bisection to 1e-4 relative."""
    def covered(force):
        return float(np.mean(solve(heights, force=force, length=s.length, e_star=s.e_star, periodic=True,
                                   tol=1e-10).contact)) - s.area
    low, high = 0.1 * s.rms_slope * s.area, s.rms_slope * s.area
    while high - low > 1e-4 * high:
        low, high = (low, 0.5 * (low + high)) if covered(0.5 * (low + high)) > 0 else (0.5 * (low + high), high)
    return high / (s.rms_slope * s.e_star * s.area)


def test_far_above_one_the_slope_is_that_without_adhesion(extremes):
    """At N = 1000 the adhesion is a small correction: the slope F/A at A* of the surface without
    adhesion within 3 %. Measured (2026-11-25): -2.0 % at N = 300, -1.1 % at N = 1000 and -0.5 %
    at N = 1e5, that last the chord's own error (F interpolated between loading states); -20 % at
    N = 30."""
    s, runs = extremes
    expected = _repulsive_slope(s, stickiness_surface(s.run(hurst=0.8, number=1000.0, seed=0)).heights)
    assert runs[1000.0]["loading_slope"] == pytest.approx(expected, rel=0.03), "N = 1000 against no adhesion"


def test_the_path_starts_at_minus_the_range_and_ends_past_the_area(extremes):
    s, runs = extremes
    run = runs[1000.0]
    assert run["depth"][0] == pytest.approx(-run["interaction_range"], rel=1e-12), "first approach"
    assert run["contact_cells"][-1] > s.area * s.n**2 >= run["contact_cells"][-2], "ends past A*"


# --- the merged table ----------------------------------------------------------------------------

def _write_runs(tmp_path, s, slopes):
    """Run files with the loading slopes *slopes[(hurst, number)]* (one per seed)."""
    paths = []
    for job in s.jobs():
        out = {"depth": np.linspace(0, 1, s.steps), "force": np.zeros(s.steps),
               "contact_cells": np.arange(s.steps), "zone_cells": np.zeros(s.steps, int),
               "rms_slope": s.rms_slope, "rms_curvature": 2.0, "interaction_range": 1e-3, "work_of_adhesion": 1e-4,
               "pastewka_robbins_number": job.number, "range_ratio": s.range_ratio,
               "loading_slope": slopes[(job.hurst, job.number)][job.seed]}
        path = tmp_path / job.combination / f"seed{job.seed}.nc"
        runfile.write_run(path, out, kind="stickiness", attrs=provenance.provenance_attrs(config=job.record(),
                                                                                  grid_n=s.n))
        paths.append(path)
    return paths


def test_the_table_has_the_mean_slope_inside_its_interval(tmp_path):
    s = _settings(number=[0.5, 3.0], seeds=3, steps=8)
    slopes = {(0.8, 0.5): [-0.1, -0.2, -0.3], (0.8, 3.0): [0.1, 0.2, 0.3]}
    table = stickiness_table(merge_stickiness(s, _write_runs(tmp_path, s, slopes)), s)
    sticky = table[table["number"] == 0.5].iloc[0]
    assert sticky["loading_slope"] == pytest.approx(-0.2, rel=1e-12), "mean over seeds"
    assert -0.3 <= sticky["loading_slope_ci_low"] < -0.2 < sticky["loading_slope_ci_high"] <= -0.1, sticky
    assert sticky["sticky_fraction"] == 1.0, "every seed sticky"
    assert table[table["number"] == 3.0].iloc[0]["sticky_fraction"] == 0.0, "no seed sticky"
    assert sticky["threshold"] == pytest.approx(math.sqrt(0.5 * 3.0), rel=1e-12), "mean slopes -0.2, +0.2"


def test_the_merged_files_record_the_sweep_not_the_configuration(tmp_path):
    """stickiness.nc's config and config_hash are the sweep's (StickinessSettings.record): another
    generated seed does not change them; the table's rows are those of merge_stickiness."""
    from roughcontact.study.rules import stickiness

    s = _settings(number=[0.5], seeds=2, steps=8)
    assert StickinessSettings.of(s) is s, "typed settings are returned unchanged"
    other = StickinessSettings.of(resolve_config({**TINY, "seeds": 7, "stickiness": {"number": [0.5], "seeds": 2,
                                                                                      "steps": 8}}))
    assert other.record() == s.record(), "the generated study's seeds are no setting of the sweep"
    paths = _write_runs(tmp_path, s, {(0.8, 0.5): [-0.1, -0.2]})
    stickiness.run(s, runs=paths, nc=tmp_path / "m.nc", csv=tmp_path / "m.csv", html=tmp_path / "m.html")
    with xr.open_dataset(tmp_path / "m.nc") as ds:
        assert json.loads(ds.attrs["config"]) == json.loads(provenance.canonical_json(s.record()))
        assert ds.attrs["config_hash"] == provenance.config_hash(s.record())
    assert pd.read_csv(tmp_path / "m.csv")["loading_slope"].tolist() == pytest.approx([-0.15], rel=1e-12)


def test_the_merge_rejects_a_run_on_another_grid(tmp_path):
    s = _settings(number=[0.5], seeds=2, steps=8)
    paths = _write_runs(tmp_path, s, {(0.8, 0.5): [-0.1, -0.2]})
    with pytest.raises(MergeError, match=r"other settings .*differs in n: \d+ in the file, 256 now"):
        merge_stickiness(_settings(number=[0.5], seeds=2, steps=8, n=256), paths)


def test_the_merge_rejects_a_file_that_is_no_stickiness_run(tmp_path):
    s = _settings(number=[0.5], seeds=2, steps=8)
    paths = _write_runs(tmp_path, s, {(0.8, 0.5): [-0.1, -0.2]})
    xr.Dataset(attrs={"title": "something else"}).to_netcdf(paths[1])
    with pytest.raises(MergeError, match=f"{paths[1]}: foreign NetCDF file .*rerun snakemake"):
        merge_stickiness(s, paths)


def test_the_merge_rejects_a_run_file_of_another_kind(tmp_path):
    """A file with the variables of a stickiness run but another title (e.g. an indentation run's)."""
    s = _settings(number=[0.5], seeds=2, steps=8)
    paths = _write_runs(tmp_path, s, {(0.8, 0.5): [-0.1, -0.2]})
    with xr.open_dataset(paths[0]) as ds:
        other = ds.load().assign_attrs(title=runfile.TITLE)
    other.to_netcdf(paths[0])
    with pytest.raises(MergeError, match="is not a roughcontact stickiness run"):
        merge_stickiness(s, paths)


# --- claim (q) -----------------------------------------------------------------------------------

def _q_rows(rows):
    base = {"hurst": 0.8, "sticky_fraction": 0.5, "pastewka_robbins_number": 1.0, "range_ratio": 0.05,
            "interaction_range": 1e-3, "work_of_adhesion": 1e-4, "rms_curvature": 2.0, "rms_slope": 0.1,
            "threshold": math.nan, "threshold_ci_low": math.nan, "threshold_ci_high": math.nan,
            "n": 512, "n_seeds": 4}
    table = pd.DataFrame([{**base, **r} for r in rows])
    inputs = claims.ClaimInputs(cross=pd.DataFrame(), replicates=xr.Dataset(), zeta=pd.DataFrame(),
                                study=study_settings(TINY), stickiness=table)
    return claims.claims()["q"].rows(inputs)


def _slope(number, mean, half, **extra):
    return {"number": number, "predicted_sticky": number < 1, "loading_slope": mean,
            "loading_slope_ci_low": mean - half, "loading_slope_ci_high": mean + half, **extra}


@pytest.mark.parametrize("number, mean, verdict", [
    (0.5, -0.1, "consistent"), (3.0, 0.1, "consistent"), (0.5, 0.1, "differs"), (3.0, -0.1, "differs"),
    (3.0, 0.01, "untested")])
def test_claim_q_compares_the_sign_with_the_prediction(number, mean, verdict):
    row = _q_rows([_slope(number, mean, 0.05)])[0]
    assert row["verdict"] == verdict, row


def test_claim_q_makes_no_prediction_at_the_threshold_itself():
    row = _q_rows([_slope(1.0, -0.1, 0.05)])[0]
    assert row["verdict"] == "untested" and "threshold" in row["reason"], row


def test_claim_q_is_untested_outside_the_criterions_range():
    row = _q_rows([_slope(0.5, -0.1, 0.05, range_ratio=2 * STICKINESS_RANGE_LIMIT)])[0]
    assert row["verdict"] == "untested" and "dr/g0" in row["reason"], row


@pytest.mark.parametrize("low, high, verdict", [(0.7, 1.4, "consistent"), (1.3, 2.0, "differs")])
def test_claim_q_compares_the_measured_threshold_with_one(low, high, verdict):
    crossing = {"threshold": 0.5 * (low + high), "threshold_ci_low": low, "threshold_ci_high": high}
    rows = _q_rows([_slope(0.5, -0.1, 0.05, **crossing), _slope(3.0, 0.1, 0.05, **crossing)])
    assert [r["verdict"] for r in rows if r["note"] == "threshold"] == [verdict], rows


def test_claim_q_threshold_is_untested_without_a_sign_change():
    rows = _q_rows([_slope(0.5, 0.1, 0.05), _slope(3.0, 0.2, 0.05)])
    assert [r["verdict"] for r in rows if r["note"] == "threshold"] == ["untested"], rows


def test_threshold_interpolates_in_ln_n():
    """Slopes -1 at N = 1 and +1 at N = 4: the sign changes half-way in ln N, at N = 2."""
    assert threshold([0.5, 1.0, 4.0], [-2.0, -1.0, 1.0]) == pytest.approx(2.0, rel=1e-12), "ln-N midpoint"


def test_threshold_is_nan_without_a_sign_change():
    assert math.isnan(threshold([0.5, 1.0], [0.1, 0.2])), "no crossing"


def test_claim_q_has_no_rows_without_a_stickiness_table():
    inputs = claims.ClaimInputs(cross=pd.DataFrame(), replicates=xr.Dataset(), zeta=pd.DataFrame(),
                                study=study_settings(TINY))
    table = claims.claims_table(pd.DataFrame(), xr.Dataset(), pd.DataFrame(), inputs.study)
    assert "q" not in set(table.get("claim", [])), table


def test_a_cohesive_failure_names_the_run_and_its_approach(monkeypatch):
    """The solver fails after two approaches: IndentError naming the run, approach 3/steps and
    what to change (the cohesive path replaced by a stub that fails)."""
    import roughcontact.study.runs.stickiness as run_module
    from roughcontact.study.rules import stickiness_run as rule
    from roughcontact.errors import ConvergenceError, IndentError

    def failing(z, depths, *, on_state, **kwargs):
        for i in range(2):
            on_state(i, np.zeros(z.shape, bool), np.zeros(z.shape, bool))
        raise ConvergenceError("stub")

    monkeypatch.setattr(run_module, "cohesive_path", failing)
    s = _settings(n=32, cutoff=4, hurst=[0.8], number=[0.5], steps=8)
    with pytest.raises(IndentError, match=r"stickiness H0.8_N0.5 seed 0: the cohesive solve did not converge at "
                                          r"approach 3/8 \(stub\); lower stickiness.area"):
        stickiness_run(s.job("H0.8_N0.5", 0))
