"""The report's landing page (study.report.summary): the recommended model per combination, numbers
with four significant digits (synthetic tables, no run needed)."""
from __future__ import annotations

import pandas as pd

from roughcontact.study.report import summary


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
