"""Verdict words that explain themselves (roughcontact.study.analysis.statistics, the claims registry): every
untested row of the claims table names why in the closed vocabulary ``UNTESTED_BECAUSE`` (the
``untested_because`` column; empty on every other row), an untested verdict without a named reason
is an ``error`` row, and no note states a verdict other than its row's. Checked over every
registered claim on one synthetic study with an optional axis (a cutoff) off its paper value, plus
adhesive, stickiness and exponent inputs, so that every claim has rows."""
from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from test_adhesion_study import _pair, _table as _adhesion
from test_claim_isolation import _ZETA, _groups, _study
from test_tangential_study import _synthetic

from roughcontact.study import claims
from roughcontact.study.claims import Claim, register, row
from roughcontact.study.analysis.statistics import (UNTESTED_BECAUSE, VERDICTS, judge, split_verdict, untested,
                                                    verdict_bound)
from roughcontact.study.analysis.crossover import crossover_table

#: a stickiness row of claim (q) (as in tests/test_stickiness.py), before the per-row values
_STICKY = {"hurst": 0.8, "sticky_fraction": 0.5, "range_ratio": 0.05, "rms_slope": 0.1, "n": 512, "n_seeds": 4,
           "threshold": math.nan, "threshold_ci_low": math.nan, "threshold_ci_high": math.nan}


def _stickiness():
    """Slopes at N = 0.5 (sticky), 1 (the threshold itself) and 3 (an interval holding 0)."""
    return pd.DataFrame([{**_STICKY, "number": n, "loading_slope": s, "loading_slope_ci_low": s - 0.05,
                          "loading_slope_ci_high": s + 0.05} for n, s in ((0.5, -0.1), (1.0, -0.1), (3.0, 0.01))])


@pytest.fixture(scope="module")
def table():
    """The claims table of a two-radius sphere study with a cutoff of 0 (the paper's) and 0.05, and
    adhesive, stickiness, (empty) exponent and tangential inputs (a synthetic Hertzian ensemble
    with no row of crossover.csv: its rows say why they are untested): every registered claim has rows."""
    groups, study = _groups(("cutoff", [0.0, 0.05])), _study(cutoff=[None, 0.05])
    zeta = _ZETA.assign(exponent=0.6, exponent_ci_low=0.55, exponent_ci_high=0.65, window="5 loads")
    cross, reps = crossover_table(groups, zeta, study)
    adhesion = _adhesion(_pair(1e-3) + _pair(3e-3) + [{**_pair(1e-3)[0], "johnson_parameter": 0.01,
                                                        "preload_radius_ratio": 0.5}])
    return claims.claims_table(cross, reps, zeta, study, groups, exponents=pd.DataFrame(),
                               zeta_replicates=xr.DataArray(np.zeros((0, 1))), adhesion=adhesion,
                               stickiness=_stickiness(), tangential=_synthetic())


def test_every_registered_claim_has_rows(table):
    """Every claim whose inputs the table was given (a claim that reads a table of its own, an
    InputTable such as the guide's (y), is run by its own test)."""
    own = set(claims.input_tables())
    expected = {letter for letter, claim in claims.claims().items() if not own & set(claim.needed)}
    assert expected <= set(table["claim"]), sorted(expected - set(table["claim"]))


def test_no_claim_fails(table):
    errors = table[table["verdict"] == "error"]
    assert errors.empty, errors[["claim", "reason"]].to_dict("records")


def test_verdicts_are_words_of_the_vocabulary(table):
    assert set(table["verdict"]) <= set(VERDICTS), set(table["verdict"])


def test_every_untested_row_names_its_reason(table):
    rows = table[table["verdict"] == "untested"]
    assert rows["untested_because"].isin(UNTESTED_BECAUSE).all(), rows[["claim", "untested_because"]].to_dict("records")


def test_only_untested_rows_name_a_reason(table):
    rows = table[table["verdict"] != "untested"]
    assert (rows["untested_because"] == "").all(), rows[["claim", "verdict", "untested_because"]].to_dict("records")


def test_untested_rows_keep_their_free_text_reason(table):
    rows = table[table["verdict"] == "untested"]
    assert (rows["reason"].str.len() > 0).all(), rows[["claim", "untested_because", "reason"]].to_dict("records")


@pytest.mark.parametrize("letter, because", [
    ("a", "off the paper's setting"), ("g", "not swept"), ("h", "not swept"), ("j", "not swept"),
    ("n", "not swept"), ("q", "no prediction"), ("q", "interval holds the threshold")])
def test_reason_of_a_known_untested_row(table, letter, because):
    rows = table[(table["claim"] == letter) & (table["verdict"] == "untested")]
    assert because in set(rows["untested_because"]), rows[["untested_because", "reason"]].to_dict("records")


def _stated_verdicts(text) -> set:
    """The verdict words (and the crossover's ``unresolved``) a free text states; ``error`` is left
    out, being also a common noun ("the method's error")."""
    if not isinstance(text, str):
        return set()
    return set(re.findall(r"\b(consistent|differs|untested|unresolved)\b", text))


def test_no_note_states_another_verdict(table):
    """A note says what the measured or paper value is; a second comparison is a row of its own."""
    bad = [r for _, r in table.iterrows() if _stated_verdicts(r["note"]) - {r["verdict"]}]
    assert not bad, [(r["claim"], r["verdict"], r["note"]) for r in bad]


def test_claim_b_with_the_fitted_zeta_is_a_row_of_its_own(table):
    rows = table[(table["claim"] == "b") & table["statement"].str.contains("fitted zeta") & (table["cutoff"] == 0.0)]
    assert len(rows) == 2, rows[["statement", "verdict"]].to_dict("records")


@pytest.mark.parametrize("because", UNTESTED_BECAUSE)
def test_untested_text_reads_back(because):
    assert split_verdict(untested(because, "why: here")) == ("untested", because, "why: here")


def test_untested_with_an_unnamed_reason_is_refused():
    with pytest.raises(ValueError, match="not one of"):
        untested("too hard", "why")


def test_bare_untested_text_is_refused():
    with pytest.raises(ValueError, match="names no reason"):
        split_verdict("untested: no interval")


def test_judge_without_an_interval_is_unresolved():
    assert split_verdict(judge(1.0, math.nan, math.nan))[1] == "unresolved"


def test_bound_inside_the_interval_holds_the_threshold():
    assert split_verdict(verdict_bound(1.0, 0.9, 1.1, side="below"))[1] == "interval holds the threshold"


def test_claim_with_an_unnamed_untested_reason_gets_an_error_row():
    claims.claims()
    register(Claim("z", "a claim that invents its own untested reason",
                   lambda inputs: [row("z", "invented", math.nan, math.nan, math.nan, 1.0, "untested: too hard")]))
    try:
        rows = claims.claims_table(pd.DataFrame(), xr.Dataset(), _ZETA.iloc[:0], _study(), None)
    finally:
        del claims.CLAIMS["z"]
    assert rows.loc[rows["claim"] == "z", "verdict"].tolist() == ["error"], rows.to_dict("records")
