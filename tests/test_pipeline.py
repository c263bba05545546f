"""End to end: presets/tiny.yaml through the real `snakemake` command in a
temporary directory (about a minute on 2 cores), then checks of the merged
data, the tables, the report, provenance, the CLI and failure handling."""
from __future__ import annotations

import dataclasses
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from browser import needs_chromium, report_page
from workflow_paths import LOG_PATTERN, RUN_PATTERN

from roughcontact import cli
from roughcontact import errors
from roughcontact.models import paper
from roughcontact.study.config import resolve as config
from roughcontact.study.runs import indent
from roughcontact.study.files import io as study_io
from roughcontact.study import quantities
from roughcontact.study.files import runfile
from roughcontact.models import scorecard as registry
from roughcontact.study.runs import naming as runs
from roughcontact.study.runs import jobs as settings
from roughcontact.study.report.summary import NO_RECOMMENDATION

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
TINY = ROOT / "presets/tiny.yaml"


def _snakemake(args, cwd, timeout=600):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    return subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), *args],
                          cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    work = tmp_path_factory.mktemp("tiny")
    proc = _snakemake(["--configfile", str(TINY), "--cores", "2"], work)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    (work / "console.log").write_text(proc.stdout + proc.stderr)  # what the user sees
    rep = _snakemake(["--configfile", str(TINY), "--report", "results/report.html"], work)
    assert rep.returncode == 0, rep.stderr[-3000:]
    cfg = config.resolve_config(config.load_config(TINY))
    return work, cfg



def test_the_crossover_job_writes_what_its_two_steps_compute(run, tmp_path):
    """Rule crossover (ζ(H) and the crossover table in one job, stiffness.nc read once) writes the
    numbers of its two steps computed here in process from the same stiffness.nc: ζ(H)
    (``fit_zeta``), then the crossover table from ζ as zeta.csv holds it (``crossover_table``);
    every column and the bootstrap replicates at rel 1e-12 (the same code on the same data: only
    a CSV round trip lies between)."""
    from roughcontact.study.analysis.crossover import crossover_table
    from roughcontact.study.analysis.zeta.fit import fit_zeta
    from roughcontact.study.config.settings import StudySettings

    work, cfg = run
    study = StudySettings.of(cfg)
    groups = study_io.read_groups(work / "results/stiffness.nc")
    zeta, zeta_replicates = fit_zeta(groups, study)
    zeta.to_csv(tmp_path / "zeta.csv", index=False)
    crossover, crossover_replicates = crossover_table(groups, pd.read_csv(tmp_path / "zeta.csv"), study)
    crossover.to_csv(tmp_path / "crossover.csv", index=False)
    for name in ("zeta.csv", "crossover.csv"):
        pd.testing.assert_frame_equal(pd.read_csv(work / "results" / name), pd.read_csv(tmp_path / name),
                                      check_exact=False, rtol=1e-12)
    for name, steps in (("zeta.nc", zeta_replicates), ("crossover.nc", crossover_replicates)):
        with xr.open_dataset(work / "results" / name) as job:
            for var in steps.data_vars:
                if steps[var].dtype.kind in "fiu":
                    np.testing.assert_allclose(job[var].values, steps[var].values, rtol=1e-12, err_msg=f"{name}:{var}")
                else:   # labels
                    np.testing.assert_array_equal(job[var].values, steps[var].values, err_msg=f"{name}:{var}")


def test_merged_file_has_a_group_per_kind_without_padding(run):
    """stiffness.nc: one group per surface kind with its own force grid: nothing NaN, counts integers."""
    work, cfg = run
    groups = study_io.read_groups(work / "results/stiffness.nc")
    assert sorted(groups) == ["flat", "sphere"], sorted(groups)
    for kind, ds in groups.items():
        assert tuple(ds["stiffness"].dims) == (*runs.AXES[kind], "seed", "force"), ds["stiffness"].dims
        assert ds["hurst"].values.tolist() == cfg["hurst"], kind
        assert ds["h_rms"].values.tolist() == cfg["h_rms"], kind
        assert ds["seed"].values.tolist() == cfg["seeds"], kind
        assert ds.sizes["force"] == cfg["forces"][kind]["count"], f"{kind}: its own load grid"
        for name in quantities.recorded(settings.job_settings(cfg, runs.runs(cfg)[0])):
            assert not ds[name].isnull().any(), f"{kind}/{name} is NaN somewhere"
        for name in ("contact_cells", "iterations", "converged"):
            assert np.issubdtype(ds[name].dtype, np.integer), f"{kind}/{name} is {ds[name].dtype}"
        assert int(ds["converged"].min()) == 1, f"{kind}: a run did not converge"
    assert groups["sphere"]["radius"].values.tolist() == [r for r in cfg["radius"] if math.isfinite(r)]


def test_merged_file_provenance(run):
    work, cfg = run
    import xarray as xr

    with xr.open_datatree(work / "results/stiffness.nc") as tree:
        attrs = tree.attrs
    for key in ("roughcontact_version", "git_commit", "config", "config_hash", "created_utc", "grid_n",
                "solver_tol", "stiffness_method"):
        assert key in attrs, key
    assert attrs["grid_n"] == cfg["grid"]["n"], attrs["grid_n"]


def test_stiffness_positive_and_increasing(run):
    work, _ = run
    for kind, ds in study_io.read_groups(work / "results/stiffness.nc").items():
        k = ds["stiffness"].transpose(..., "force").values.reshape(-1, ds.sizes["force"])
        assert (k > 0).all(), kind
        # k = dF/dd grows with the contact set; equal when the set did not change
        assert (np.diff(k, axis=1) >= -1e-6 * k[:, 1:]).all(), kind
        assert (k[:, -1] > k[:, 0]).all(), kind


def test_hertz_limit_at_the_largest_load(run):
    """At F/(E*L^2) = 1e-2 the tiny config is 13-400x above the crossover force
    (eq. 17), so eq. 16 is within 6 % of Hertz there; the 65^2 grid resolves the
    Hertz contact (radius 0.155 L = 10 cells) to a few per cent, and the seeds
    scatter by a few per cent: 15 % bounds all three."""
    work, cfg = run
    ens = study_io.read_groups(work / "results/ensemble.nc")["sphere"]
    for radius in ens["radius"].values:
        sub = ens.sel(radius=radius).isel(force=-1)
        k_hertz = paper.hertz_stiffness(float(sub["force"]), radius=radius, e_star=cfg["e_star"])
        ratio = sub["k_mean"].values / k_hertz
        assert np.all(np.abs(ratio - 1) < 0.15), ratio


def test_ensemble_and_tables(run):
    work, cfg = run
    ens = study_io.read_groups(work / "results/ensemble.nc")
    for kind, ds in ens.items():
        for name in ("k_mean", "k_std", "k_sem", "contact_cells_mean"):
            assert name in ds, f"{kind}/{name}"
        assert ds.attrs["n_seeds"] == len(cfg["seeds"]), kind
    zeta = pd.read_csv(work / "results/zeta.csv")
    assert {"hurst", "zeta", "zeta_ci_low", "zeta_ci_high", "zeta_estimate", "exponent", "exponent_theory",
            "n_points", "source", "window"} <= set(zeta.columns)
    assert zeta["hurst"].tolist() == cfg["hurst"]
    assert (zeta["source"] == "flat").all()
    # coarse grid and two seeds: zeta within a factor 1.6 of 1.7/(H+1), CI brackets the estimate
    assert np.all(np.abs(np.log(zeta["zeta"] / zeta["zeta_estimate"])) < np.log(1.6))
    assert np.all(zeta["zeta_ci_low"] <= zeta["zeta"]) and np.all(zeta["zeta"] <= zeta["zeta_ci_high"])
    with xr.open_dataset(work / "results/zeta.nc") as z:
        assert "config_hash" in z.attrs


def test_crossover_table_has_an_interval_or_a_reason(run):
    """Every sphere row: F_tr measured with a finite 95 % interval, or a verdict saying why not."""
    work, cfg = run
    cross = pd.read_csv(work / "results/crossover.csv", keep_default_na=False, na_values=[""])
    assert len(cross) == len(cfg["hurst"]) * len(cfg["h_rms"]), len(cross)  # one finite radius
    for _, row in cross.iterrows():
        if row["verdict_fit"] == "unresolved":
            assert "unresolved:" in row["note"], row["note"]
        else:
            assert row["Ftr_ci_low"] <= row["Ftr_measured"] <= row["Ftr_ci_high"], row
            assert row["verdict_fit"] in ("consistent", "differs"), row["verdict_fit"]
        assert row["slope_high_verdict"].split(":")[0] in ("consistent", "differs", "untested"), row
    assert np.all(cross["rms_log10_k_over_eq16"] < 0.2), cross["rms_log10_k_over_eq16"]


def test_claims_table(run):
    """claims.csv: every claim (a)-(h) has a row, a verdict from the fixed vocabulary, a reason when untested."""
    work, cfg = run
    claims = pd.read_csv(work / "results/claims.csv", keep_default_na=False, na_values=[""])
    assert set("abcdefgh") <= set(claims["claim"]), sorted(set(claims["claim"]))
    assert set(claims["verdict"]) <= {"consistent", "differs", "untested"}, set(claims["verdict"])
    untested = claims[claims["verdict"] == "untested"]
    assert (untested["reason"].str.len() > 0).all(), untested[["claim", "reason"]]
    h_rows = claims[claims["claim"] == "h"]
    assert (h_rows["verdict"] == "untested").all(), "tiny sweeps H >= 0.5 only: eq. 18 cannot be tested"
    radius_rows = claims[(claims["claim"] == "g") & claims["statement"].str.contains("R\\^")]
    assert (radius_rows["reason"] == "one radius value only").all(), radius_rows["reason"]


def test_claims_name_why_they_are_untested(run):
    """claims.csv of the tiny preset: untested_because is a word of the vocabulary exactly on the untested rows."""
    from roughcontact.study.analysis.statistics import UNTESTED_BECAUSE

    work, _ = run
    claims = pd.read_csv(work / "results/claims.csv", keep_default_na=False, na_values=[""])
    named = claims["untested_because"].isin(UNTESTED_BECAUSE)
    assert (named == (claims["verdict"] == "untested")).all(), claims[["claim", "verdict", "untested_because"]]


def test_claims_notes_state_no_other_verdict(run):
    """claims.csv of the tiny preset: no note states a verdict other than its row's (tests/test_verdict_reasons.py)."""
    from test_verdict_reasons import _stated_verdicts

    work, _ = run
    claims = pd.read_csv(work / "results/claims.csv", keep_default_na=False, na_values=[""])
    bad = [(r["claim"], r["verdict"], r["note"]) for _, r in claims.iterrows()
           if _stated_verdicts(r["note"]) - {r["verdict"]}]
    assert not bad, bad


def test_report_and_figures(run):
    work, cfg = run
    html = (work / "results/report.html").read_text(errors="replace")
    assert len(html) > 100_000
    for spec_path in (work / "results/figures").iterdir():
        assert spec_path.stat().st_size > 1000
    names = {p.name for p in (work / "results/figures").iterdir()}
    assert {"fig1_surface.png", "fig2_rough_sphere.png", "fig4_profiles.png", "zeta.png", "collapse.png"} <= names
    assert sum(n.startswith("fig3_") for n in names) == len(cfg["hurst"]) * len(cfg["h_rms"])


def test_model_scorecard(run):
    """models.csv: every model that applies to a sphere combination has a row with a deviation
    inside its interval's span, one rank-1 model per combination, and a figure per combination."""
    work, cfg = run
    table = pd.read_csv(work / "results/models.csv")
    spheres = [c for c in runs.combinations(cfg) if c["kind"] == "sphere"]
    assert set(table["model"]) == set(registry.models()), set(table["model"])
    assert len(table) == len(registry.models()) * len(spheres), f"{len(table)} rows for {len(spheres)} combinations"
    assert (table["max_rel_dev"] >= table["rms_rel_dev"]).all(), "rms deviation above the largest"
    assert (table.groupby("combination")["rank"].min() == 1).all(), "a combination without a best model"
    figures = sorted(p.name for p in (work / "results/models").iterdir())
    assert figures == sorted(f"{runs.combo_name(c)}.png" for c in spheres), figures


@needs_chromium
@pytest.mark.parametrize("link, table, cell", [
    ("claims table", "claims.csv", "td.verdict-consistent, td.verdict-differs, td.verdict-untested"),
    ("model scorecard", "models.csv", "table.rows tbody tr"),   # the decision matrix above is not counted
])
def test_report_shows_its_tables_on_the_page(run, link, table, cell):
    """In headless Chromium the landing page's link opens the table inside the report (not a
    download), one row (for the claims: one coloured verdict cell) per row of the CSV."""
    work, _ = run
    rows = len(pd.read_csv(work / "results" / table))
    with report_page(work / "results/report.html") as (page, _):
        page.get_by_text(link, exact=True).first.click()
        page.wait_for_function("document.querySelector('iframe') !== null", timeout=20_000)
        frame = page.frame_locator("iframe")
        cells = frame.locator(cell)
        cells.first.wait_for(timeout=20_000)
        count = cells.count()
        header = frame.locator("th").all_inner_texts()
    assert count == rows, f"{count} rows ({cell}) on the page for {rows} rows of {table}"
    assert header, f"the {table} page has no table header"


@needs_chromium
def test_report_landing_page_is_the_answer(run):
    """In headless Chromium the report's first page shows, without a click, the verdict words,
    the recommended model of every sphere combination and Fig. 3 (an image on screen), with no
    SEVERE console message; the report holds no CSV data link (every table is an HTML page)."""
    work, _ = run
    html = (work / "results/report.html").read_text(errors="replace")
    assert "data:text/csv" not in html, "a table is a CSV data link"
    models = pd.read_csv(work / "results/models.csv")
    best = set(models.loc[models["rank"] == 1, "model"])
    with report_page(work / "results/report.html", viewport={"width": 1400, "height": 1000}) as (page, severe):
        summary = page.locator(".rc-summary")
        summary.wait_for(timeout=20_000)
        text = summary.inner_text()
        # the verdicts on screen as the page opens (the report centres tall text: its top cut off)
        top = page.locator(".rc-summary table").first.evaluate("t => t.getBoundingClientRect().top")
        image = page.locator("img.rc-fig3")
        image.scroll_into_view_if_needed()
        visible = image.is_visible()
        width = image.evaluate("img => img.naturalWidth")
        shown_models = summary.locator("td.model").all_inner_texts()
    for word in ("consistent", "differs", "untested"):
        assert word in text, f"{word!r} is not on the first page"
    assert shown_models and set(shown_models) <= set(models["model"]) | {NO_RECOMMENDATION}, shown_models
    if "recommended" not in models.columns:
        assert set(shown_models) <= best, (shown_models, best)
    assert 0 <= top < 1000, f"the verdict table is not on screen as the page opens (top at {top} px)"
    assert visible and width > 100, "Fig. 3 is not shown on the first page"
    assert not severe, severe


def test_cli_help_is_plain_text(capsys):
    """`roughcontact --help` shows plain text: no reST markup (``literal``, :role:`...`)."""
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    out = capsys.readouterr().out
    assert "``" not in out and ":func:" not in out, out


def test_no_warning_reaches_the_console(run):
    """`snakemake --cores 2` on the tiny preset prints no Python warning (matplotlib's or other)."""
    work, _ = run
    console = (work / "console.log").read_text()
    assert "Warning:" not in console, [line for line in console.splitlines() if "Warning" in line]


def test_logs_and_run_provenance(run):
    work, cfg = run
    first = runs.runs(cfg)[0]
    path = runs.run_path(first, RUN_PATTERN)
    log = (work / runs.run_path(first, LOG_PATTERN)).read_text()
    n = cfg["forces"]["sphere"]["count"]
    assert f"load step {n}/{n}" in log and "iterations" in log and " s" in log
    with xr.open_dataset(work / path) as ds:
        assert ds.attrs["seed"] == cfg["seeds"][0]
        assert ds.attrs["grid_n"] == cfg["grid"]["n"]
        assert len(ds.attrs["config_hash"]) == 16
    assert not list((work / "results").rglob(".*.tmp-*"))  # atomic writes leave no temp files


def test_nothing_to_redo(run):
    work, _ = run
    proc = _snakemake(["--configfile", str(TINY), "-n"], work)
    assert proc.returncode == 0
    assert "Nothing to be done" in proc.stdout + proc.stderr


def test_cli_shares_code_with_the_rule(run, tmp_path):
    """`roughcontact indent` with the same settings writes the same numbers and hash."""
    work, cfg = run
    h, r, s, seed = cfg["hurst"][1], cfg["radius"][0], cfg["h_rms"][1], cfg["seeds"][1]
    run_file = work / runs.run_path({"hurst": h, "radius": r, "h_rms": s, "seed": seed}, RUN_PATTERN)
    out = tmp_path / "run.nc"
    assert cli.main(["indent", "--config", str(TINY), "--hurst", str(h), "--radius", str(r), "--h-rms", str(s),
                     "--seed", str(seed), "-o", str(out), "-q"]) == 0
    with xr.open_dataset(out) as a, xr.open_dataset(run_file) as b:
        assert a.attrs["config_hash"] == b.attrs["config_hash"]
        np.testing.assert_array_equal(a["stiffness"].values, b["stiffness"].values)
        np.testing.assert_array_equal(a["depth"].values, b["depth"].values)


def test_merge_names_a_truncated_or_foreign_file(run, tmp_path):
    work, cfg = run
    row = runs.runs(cfg)[0]
    good = work / runs.run_path(row, RUN_PATTERN)
    expected = settings.job_settings(cfg, row)
    bad = tmp_path / "truncated.nc"
    bad.write_bytes(good.read_bytes()[:300])
    with pytest.raises(errors.MergeError, match="truncated.nc"):
        study_io.read_run(bad, expected)
    foreign = tmp_path / "foreign.nc"
    xr.Dataset({"x": ("a", [1.0, 2.0])}).to_netcdf(foreign, engine="netcdf4")
    with pytest.raises(errors.MergeError, match="foreign.nc.*foreign"):
        study_io.read_run(foreign, expected)
    other = dataclasses.replace(expected, tol=1e-6)
    with pytest.raises(errors.MergeError, match="other settings"):
        study_io.read_run(good, other)


def test_failed_job_names_parameters_and_leaves_no_file(tmp_path):
    job = settings.JobSettings(hurst=0.7, radius=0.5, h_rms=9e-3, seed=3, n=33, length=1.0, e_star=1.0,
                               force_from=1e-3, force_to=0.3, force_count=4, tol=1e-8, stiffness_method="punch",
                               rel_step=1e-3)
    out = tmp_path / "run.nc"
    with pytest.raises(errors.IndentError) as info:
        indent.run_indent(job, out, log=tmp_path / "run.log")
    msg = str(info.value)
    assert "H = 0.7" in msg and "R = 0.5" in msg and "seed = 3" in msg and "n = 33" in msg
    assert "forces.sphere.to" in msg and "grid.n" in msg
    assert "FAILED" in (tmp_path / "run.log").read_text()
    # the output is not written; the loads solved before the failure are kept beside it
    assert sorted(p.name for p in tmp_path.glob("*.nc")) == ["run.partial.nc"]
    assert not any(tmp_path.glob(".*tmp*"))
    (tmp_path / "run.partial.nc").unlink()
    # non-convergence
    job = dataclasses.replace(job, force_from=1e-4, force_to=1e-3, force_count=2, maxiter=1)
    with pytest.raises(errors.IndentError, match="did not converge.*solver.maxiter"):
        indent.run_indent(job, out)
    assert not out.exists()


def test_failing_jobs_through_snakemake_keep_going(tmp_path):
    """maxiter = 1: every solve stops unconverged. Each job (a combination's seeds, jobs.batch)
    stops at its first run and fails in one console line naming the run, the remedy and its log,
    which has the traceback; --keep-going tries them all, nothing is written."""
    proc = _snakemake(["--configfile", str(TINY), "--config", "solver={tol: 1.0e-8, stiffness: punch, maxiter: 1}",
                       "--cores", "2", "--keep-going"], tmp_path)
    out = proc.stdout + proc.stderr
    assert proc.returncode != 0
    cfg = config.resolve_config(config.load_config(TINY))
    n_jobs = len(runs.combinations(cfg)) * len(runs.seed_blocks(cfg["seeds"], cfg["jobs"]["batch"]))
    failed = [line for line in out.splitlines() if line.startswith("Error in rule indent")]
    assert len(failed) == n_jobs, "one line per failed job:\n" + out[-3000:]
    line = next(line for line in failed if "H = 0.8, R = inf (flat, periodic), h_rms = 0.02, seed = 0, n = 65" in line)
    assert "did not converge" in line and "raise solver.maxiter" in line, line
    log = tmp_path / line.rsplit("(log: ", 1)[1].rstrip(")")
    assert "Traceback" in log.read_text() and "FAILED" in log.read_text(), "the details in the run's log"
    assert "CalledProcessError" not in out, "Snakemake's own lines on the exit status left out (quiet console)"
    # no run file and nothing half-written; the models' curves need no run (rule model_curves, from the config
    # alone) and may be complete
    written = [p for p in tmp_path.rglob("*.nc") if p.name != "model_curves.nc"]
    assert not written and not list(tmp_path.rglob(".*tmp*")), written
