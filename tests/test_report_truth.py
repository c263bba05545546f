"""The truth checker of the workflow fuzzer (tests/report_truth.py) flags what it is meant to flag: a
study directory whose landing page is made by the real page code from consistent tables passes, and
each kind of contradiction (a verdict on a point interval, a tally or a count that is not the
table's, a grid error told otherwise) fails it."""
from __future__ import annotations

import math

import pandas as pd
import pytest

from report_truth import check_report_truth
from roughcontact.study.analysis.grid_error import statement
from roughcontact.study.files.io import write_csv
from roughcontact.study.report import answer, summary

NAN = math.nan
CLAIMS = pd.DataFrame([
    {"claim": "a", "statement": "eq. 16 within 10 %", "radius": 0.5, "measured": 0.05, "ci_low": 0.03,
     "ci_high": 0.07, "verdict": "consistent", "untested_because": "", "reason": ""},
    {"claim": "b", "statement": "F_tr of eq. 17", "radius": 0.5, "measured": 1e-4, "ci_low": 0.9e-4,
     "ci_high": 1.2e-4, "verdict": "differs", "untested_because": "", "reason": ""},
    {"claim": "d", "statement": "low slope", "radius": 0.5, "measured": NAN, "ci_low": NAN, "ci_high": NAN,
     "verdict": "untested", "untested_because": "unresolved", "reason": "too few loads"},
    {"claim": "g", "statement": "F_tr ~ R", "radius": 0.5, "measured": NAN, "ci_low": NAN, "ci_high": NAN,
     "verdict": "untested", "untested_because": "not swept", "reason": "one radius"},
])


def _study(tmp_path, claims=CLAIMS, edit=lambda page: page):
    """A results directory: the tables, and the landing page the real code makes of them (then *edit*ed)."""
    results = tmp_path / "results"
    results.mkdir()
    write_csv(claims, results / "claims.csv")
    for name in ("crossover", "models"):
        write_csv(pd.DataFrame(), results / f"{name}.csv", columns=("hurst",), reason="a test without it")
    size = answer.StudySize(n=65, seeds=2, spheres=1, flats=0, grid_error=statement(None, None))
    page = summary.summary_html(claims, pd.DataFrame(), pd.DataFrame(), pd.DataFrame(), None, size=size)
    (results / "summary.html").write_text(edit(page))
    return tmp_path


def test_a_consistent_study_passes(tmp_path):
    check_report_truth(_study(tmp_path))


def test_a_verdict_on_a_point_interval_fails(tmp_path):
    claims = CLAIMS.copy()
    claims.loc[1, ["ci_low", "ci_high"]] = 1e-4   # written past registry.row's rule
    with pytest.raises(AssertionError, match="claims.csv: verdict = differs"):
        check_report_truth(_study(tmp_path, claims))


def test_a_tally_that_is_not_the_table_fails(tmp_path):
    with pytest.raises(AssertionError, match="shows 2 differs"):
        check_report_truth(_study(tmp_path, edit=lambda page: page.replace("1 differs", "2 differs")))


def test_counts_that_do_not_add_up_fail(tmp_path):
    with pytest.raises(AssertionError, match="the other untested comparisons are not 2"):
        check_report_truth(_study(tmp_path, edit=lambda page: page.replace("The other 2 are", "The other 3 are")))


def test_a_grid_error_told_otherwise_fails(tmp_path):
    with pytest.raises(AssertionError, match="grid error is not stated"):
        check_report_truth(_study(tmp_path, edit=lambda page: page.replace(
            "grid error not measured: grid.coarse is null", "grid error measured against 33²: grid.coarse is null")))
