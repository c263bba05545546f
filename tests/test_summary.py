"""The report's landing page (study.report.summary): the recommended model per combination, numbers
with four significant digits (synthetic tables, no run needed)."""
from __future__ import annotations

import pandas as pd

from roughcontact.study.analysis.grid_error import GridErrorStatement
from roughcontact.study.report import answer, summary


def _models(**extra):
    rows = []
    for combination in ("A", "B"):
        for rank, (model, dev) in enumerate((("eq16_paper", 0.123456789), ("persson", 0.5))):
            rows.append({"model": model, "combination": combination, "hurst": 0.7, "radius": 0.5, "h_rms": 0.009,
                         "max_rel_dev": dev, "rank": rank + 1, "systematic_low": 0.01, "systematic_low_ci_low": 0.0,
                         "systematic_low_ci_high": 0.02, "systematic_low_verdict": "consistent",
                         "systematic_high": float("nan"), "systematic_high_ci_low": float("nan"),
                         "systematic_high_ci_high": float("nan"), "systematic_high_verdict": "untested: no load"})
    table = pd.DataFrame(rows)
    for name, values in extra.items():
        table[name] = values
    return table


def test_rank_one_without_a_recommended_column():
    assert [r["model"] for r in summary.recommended_models(_models())] == ["eq16_paper", "eq16_paper"]


def test_the_recommended_column_decides():
    flags = [False, True, True, False]
    assert [r["model"] for r in summary.recommended_models(_models(recommended=flags))] == ["persson", "eq16_paper"]
    names = ["persson", "persson", "eq16_paper", "eq16_paper"]
    assert [r["model"] for r in summary.recommended_models(_models(recommended=names))] == ["persson", "eq16_paper"]


def test_four_significant_digits():
    assert summary.fmt(0.123456789) == "0.1235"
    assert summary.fmt(1.2345678e11) == "1.235e+11"
    assert summary.fmt(float("nan")) == "" and summary.fmt(float("inf")) == "inf"


def test_no_recommended_row_says_so():
    table = _models(recommended=[False, False, True, False])
    assert [r["model"] for r in summary.recommended_models(table)] == [summary.NO_RECOMMENDATION, "eq16_paper"]
    html = summary.summary_html(pd.DataFrame({"claim": ["a"], "statement": ["s"], "verdict": ["consistent"]}),
                                pd.DataFrame(), pd.DataFrame(columns=["hurst", "zeta", "zeta_ci_low", "zeta_ci_high",
                                                                      "zeta_estimate"]), table, None)
    assert summary.NO_RECOMMENDATION in html and "0.1235" in html


def _landing(models):
    return summary.summary_html(pd.DataFrame({"claim": ["a"], "statement": ["s"], "verdict": ["consistent"]}),
                                pd.DataFrame(), pd.DataFrame(columns=["hurst", "zeta", "zeta_ci_low", "zeta_ci_high",
                                                                      "zeta_estimate"]), models, None)


def test_the_landing_page_says_the_grid_error_is_not_measured():
    html = _landing(_models(grid_error_measured=[False] * 4))
    assert "grid error not measured" in html.lower(), "no statement that the grid error is not measured"


def test_the_landing_page_says_the_grid_error_is_measured():
    html = _landing(_models(grid_error_measured=[True] * 4))
    assert "grid error is measured" in html.lower(), "no statement that the grid error is measured"


# --- the answer first, and true (issue 40 item 3) ---

def _claims(rows):
    """A claims table of (claim, statement, verdict, untested_because) rows."""
    return pd.DataFrame(rows, columns=["claim", "statement", "verdict", "untested_because"])


_EMPTY = pd.DataFrame()


def test_an_empty_crossover_and_scorecard_read_not_measured_because():
    """A flat-only study: no crossover row and no scorecard row; the page says why, no crash."""
    size = answer.StudySize(n=97, seeds=3, spheres=0, flats=2)
    html = summary.summary_html(_claims([("c", "zeta(H) ~ 1.7/(H+1)", "consistent", "")]), _EMPTY, _EMPTY, _EMPTY,
                                None, size=size)
    assert html.count("Not measured, because the sweep has no sphere") == 2, html
    assert "Not measured, because the sweep has no nominally flat" not in html


def test_tallies_count_comparisons_not_claim_letters():
    """Claim e with two statements is two comparisons: each its own row and its own counts."""
    claims = _claims([("e", "slope = 1/3", "consistent", ""), ("e", "slope = 1/3", "differs", ""),
                      ("e", "prefactor = eq. 7", "differs", "")])
    found = answer.comparisons(claims)
    assert [(c.statement, c.counts["consistent"], c.counts["differs"]) for c in found] == [
        ("slope = 1/3", 1, 1), ("prefactor = eq. 7", 0, 1)]


def test_the_answer_names_the_comparisons_that_differ():
    claims = _claims([("a", "eq. 16 within 10 %", "consistent", ""), ("b", "F_tr of eq. 17", "differs", ""),
                      ("g", "F_tr ~ R", "untested", "not swept"), ("d", "low slope", "untested", "unresolved")])
    grid = GridErrorStatement(measured=True, coarse=193, largest=0.16, median=0.092)
    text = answer.answer_html(answer.comparisons(claims), answer.StudySize(n=385, seeds=6, spheres=12, flats=6,
                                                                           grid_error=grid))
    assert "In part" in text
    assert "1 differ wherever tested (claim <b>b</b>)" in text
    assert "The other 2 are untested here" in text
    assert "1 is unresolved" in text
    assert "1 needs an axis" in text
    assert "6 seeds each, on 385² (grid error measured against 193²: up to 16 % (median 9.2 %)" in text
    assert "presets/crossover.yaml" in text


def test_untested_counts_add_up_and_name_their_reason():
    """Nothing tested: the counts per reason add up to the comparisons, and a comparison off the
    paper's setting is not said to wait for a larger preset (issue 48)."""
    claims = _claims([("a", "s1", "untested", "off the paper's setting"), ("b", "s2", "untested", "off the paper's setting"),
                      ("g", "s3", "untested", "not swept")])
    text = answer.answer_html(answer.comparisons(claims))
    assert "none of the 3 comparisons with the paper is tested here: 2 are off the paper&#x27;s setting" in text
    assert "1 needs an axis" in text
    assert "larger" not in text.split("The README")[0]


def test_the_grid_error_sentence_is_its_statement():
    grid = GridErrorStatement(measured=False, coarse=65, reason="the sweep has 1 seed")
    size = answer.StudySize(n=129, seeds=1, spheres=1, flats=0, grid_error=grid)
    assert "(grid error not measured: the sweep has 1 seed)" in size.sentence()


def test_all_consistent_answers_yes():
    text = answer.answer_html(answer.comparisons(_claims([("a", "s", "consistent", "")])))
    assert "Yes, as far as this study resolves" in text


def test_each_crossover_prediction_has_its_own_verdict():
    """eq. 17 with ζ = 1.7/(H+1) shown next to verdict_estimate, with the fitted ζ next to verdict_fit."""
    crossover = pd.DataFrame([{"hurst": 0.5, "radius": 0.5, "h_rms": 0.02, "Ftr_measured": 1e-3, "Ftr_ci_low": 6.7e-4,
                               "Ftr_ci_high": 2.0e-3, "Ftr_pred_estimate": 8.24e-4, "verdict_estimate": "consistent",
                               "Ftr_pred_fit": 3.0e-4, "verdict_fit": "differs"}])
    html = summary.summary_html(_claims([("b", "s", "consistent", "")]), crossover, _EMPTY, _EMPTY, None)
    row = html[html.index("<td", html.index("F_tr measured")):]
    row = row[: row.index("</tr>")]
    assert row.index("0.000824") < row.index("consistent") < row.index("0.0003") < row.index("differs"), row


def test_holds_read_from_the_table_with_why_not():
    """The page shows the table's holds; where it is False for want of a branch, it says so."""
    table = _models(recommended=[True, False, True, False], holds=[False, False, True, True],
                    n_loads_low=[0, 0, 3, 3], n_loads_high=[5, 5, 4, 4])
    html = _landing(table)
    assert html.count("no: a branch has no resolved load") == 1
    assert html.count("<td style=\"border: 1px solid #bbb; padding: 2px 6px; text-align: left;\">yes</td>") == 1


def test_no_recommended_model_shows_no_holds():
    table = _models(recommended=[False, False, True, False], holds=[True] * 4)
    html = _landing(table)
    row = html[html.index(summary.NO_RECOMMENDATION):]
    row = row[: row.index("</tr>")]
    assert ">yes<" not in row and ">—<" in row, row


def test_combinations_off_the_paper_setting_are_named_by_the_axis_registry():
    """Two rows differing only in an optional axis (hardness) get different labels."""
    table = _models(hardness=[float("inf"), float("inf"), 0.5, 0.5])
    html = _landing(table)
    assert "hardness = 0.5" in html
