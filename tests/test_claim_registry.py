"""A claim registered as one object (roughcontact.study.claims) gets its rows in the claims
table; the registry holds the claims (a)-(m) of the study."""
from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from test_scorecard import CFG, FORCE, _groups

from examples import in_order, loaded, scoped_registry  # noqa: F401 -- scoped_registry: every test in its own registries

from roughcontact.study import claims
from roughcontact.study.claims import Claim, register


@pytest.fixture
def stiffening_claim():
    """The package guide's worked example (``docs/guide/extending/claim_example.py``), claim (x):
    loaded as its module in the test's own registry."""
    with loaded("claim_example.py", claims.CLAIMS, "x"):
        yield claims.CLAIMS["x"]


def _table(groups):
    reps = xr.Dataset()
    zeta = pd.DataFrame(columns=["hurst", "zeta", "zeta_ci_low", "zeta_ci_high", "zeta_estimate", "source",
                                 "n_seeds", "n_points", "force_min", "force_max"])
    return claims.claims_table(pd.DataFrame(), reps, zeta, CFG, groups)


#: the claims of the study, in letter order (a module added to the package adds its own)
STUDY_CLAIMS = ("a", "b", "c", "c'", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m", "n", "o", "p", "q", "r", "s", "t")


def test_registry_holds_the_claims_of_the_study():
    assert in_order(STUDY_CLAIMS, claims.claims()), f"claims: {list(claims.claims())}"


def test_registry_is_in_letter_order():
    assert list(claims.claims()) == sorted(claims.claims()), f"claims: {list(claims.claims())}"


def test_registered_claim_has_its_row(stiffening_claim):
    table = _table(_groups(np.array([1.0, 1.02, 0.98, 1.01])))
    rows = table[table["claim"] == "x"]
    assert len(rows) == 1, f"claims in the table: {sorted(set(table['claim']))}"


def test_registered_claim_verdict_follows_its_rule(stiffening_claim):
    """The ensemble is eq. 16 times a constant per seed: k rises at every load, interval above 0."""
    table = _table(_groups(np.array([1.0, 1.02, 0.98, 1.01])))
    assert table[table["claim"] == "x"]["verdict"].iloc[0] == "consistent", table[table["claim"] == "x"].to_dict()


def test_registered_claim_value_is_its_estimate(stiffening_claim):
    """The smallest rise between neighbouring resolved loads (F >= 1e-5 in ``_groups``)."""
    groups = _groups(np.ones(4))
    k = groups["sphere"]["stiffness"].squeeze().values[0][FORCE >= 1e-5]
    expected = (np.diff(k) / k[:-1]).min()
    got = float(_table(groups).query("claim == 'x'")["measured"].iloc[0])
    assert got == pytest.approx(expected, rel=1e-12), f"measured {got}, expected {expected}"


def test_registered_claim_has_one_row_per_combination(stiffening_claim):
    """The guide's claim on a study of two radii (two sphere combinations): a row for each."""
    from test_claim_isolation import RADII, _groups as two_radii

    rows = _table(two_radii()).query("claim == 'x' and verdict != 'error'")
    assert rows["radius"].tolist() == list(RADII), rows[["radius", "verdict", "reason"]].to_dict("records")


def test_registered_claim_judges_the_resolved_loads(stiffening_claim):
    """k flat over the unresolved loads (one cell carries them all, F < 1e-5) and rising over the
    resolved ones: the guide's claim is decided, consistent; over every load it would be untested
    (its interval would hold 0)."""
    groups = _groups(np.array([1.0, 1.02, 0.98, 1.01]))
    k = groups["sphere"]["stiffness"]
    groups["sphere"]["stiffness"] = k.where(k["force"] >= 1e-5, k.sel(force=FORCE[FORCE >= 1e-5][0]))
    row = _table(groups).query("claim == 'x'").iloc[0]
    assert (row["verdict"], row["ci_low"] > 0) == ("consistent", True), row.to_dict()


def test_registered_claim_without_two_resolved_loads_is_unresolved(stiffening_claim):
    groups = _groups(np.ones(4))
    groups["sphere"]["contact_cells"] = groups["sphere"]["contact_cells"].where(groups["sphere"]["force"] >= 1e-2, 5)
    row = _table(groups).query("claim == 'x'").iloc[0]
    assert (row["verdict"], row["untested_because"]) == ("untested", "unresolved"), row.to_dict()


def test_the_claim_example_loads_twice():
    for _ in range(2):
        with loaded("claim_example.py", claims.CLAIMS, "x"):
            assert "x" in claims.CLAIMS


def test_claim_without_its_inputs_has_no_row(stiffening_claim):
    table = _table(None)
    assert "x" not in set(table["claim"]), "a claim ran without the inputs it needs"


def test_second_claim_of_a_letter_is_an_error():
    with pytest.raises(ValueError, match="'a'"):
        register(Claim("a", "again", estimate=lambda combination: []))


def test_rows_are_ordered_by_letter(stiffening_claim):
    letters = _table(_groups(np.ones(4)))["claim"].tolist()
    assert letters == sorted(letters), f"row order: {letters}"



def test_describe_names_a_flat_row_flat():
    """A row's sweep names the surface kind: a flat row has no sphere radius (R = inf)."""
    from roughcontact.study.claims.registry import describe

    assert describe({"hurst": 0.7, "radius": float("inf"), "h_rms": 9e-3}, 1.0, 65, 2).startswith("flat H = 0.7, h_rms")
    assert describe({"hurst": 0.7, "radius": 0.5, "h_rms": 9e-3}, 1.0, 65, 2).startswith("sphere H = 0.7, R = 0.5")
