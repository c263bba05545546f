"""The claims registry loops over the sweep's combinations and runs each claim in isolation
(roughcontact.study.claims.registry): a claim that raises on one combination gives an ``error``
row there and normal rows elsewhere, the other claims' rows are unchanged; an optional axis off
its paper value makes claims (a)-(f) untested, (g) leave it out and (l) not pool it."""
from __future__ import annotations

import logging
import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from examples import scoped_registry  # noqa: F401 -- every test in its own registries

from roughcontact.models import paper
from roughcontact.study.config import axes, schema
from roughcontact.study import claims
from roughcontact.study.report import tables
from roughcontact.study.claims import Claim, register, row
from roughcontact.study.claims.exponents import exponent_rows
from roughcontact.study.config.resolve import resolve_config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.analysis.crossover import crossover_table

HURST, H_RMS, ZETA, RADII = 0.7, 9e-3, 1.05, (0.5, 1.0)
FORCE = np.geomspace(1e-6, 1e-2, 9)
SCALES = np.array([1.0, 1.02, 0.98, 1.01])


def _study(**extra):
    return StudySettings.of(resolve_config({
        "grid": {"n": 129}, "hurst": [HURST], "radius": list(RADII), "h_rms": [H_RMS], "seeds": len(SCALES),
        "forces": {"sphere": {"from": 1e-6, "to": 1e-2, "count": 9}},
        "fit": {"resolved_cells": 20, "bootstrap": 200, "slopes": {"high_min_ratio": 3.0}}, **extra}))


def _groups(extra_axis=None) -> dict:
    """Merged sphere runs of two radii (two combinations; four with *extra_axis* ``(name, values)``):
    seed s has k = SCALES[s] x eq. 16 (fitted zeta), the same at every value of the extra axis."""
    coords = {"hurst": [HURST], "radius": list(RADII), "exponent": [2.0], "h_rms": [H_RMS], "rolloff": [1.0],
              "cutoff": [0.0], "hardness": [math.inf]}
    if extra_axis:
        coords[extra_axis[0]] = list(extra_axis[1])
    k16 = np.stack([paper.stiffness_from_force(FORCE, radius=r, hurst=HURST, h_rms=H_RMS, length=1.0, e_star=1.0,
                                               zeta=ZETA) for r in RADII])           # (radius, force)
    k = xr.DataArray(SCALES[None, :, None] * k16[:, None, :], dims=("radius", "seed", "force"),
                     coords={"radius": list(RADII), "seed": np.arange(len(SCALES)), "force": FORCE})
    k = k.expand_dims({a: v for a, v in coords.items() if a != "radius"}).transpose(*coords, "seed", "force")
    cells = xr.full_like(k, 100)                                       # every load resolved
    ds = xr.Dataset({"stiffness": k, "contact_cells": cells})
    return {"sphere": ds}


_ZETA = pd.DataFrame({"hurst": [HURST], "zeta": [ZETA], "zeta_ci_low": [1.0], "zeta_ci_high": [1.1],
                      "zeta_estimate": [float(paper.zeta_estimate(HURST))], "source": ["flat"], "n_seeds": [4],
                      "n_points": [5], "force_min": [1e-5], "force_max": [1e-3]})


def _table(groups, study):
    cross, reps = crossover_table(groups, _ZETA, study)
    return claims.claims_table(cross, reps, _ZETA, study, groups)


def _rise(combination):
    """Claim (x) of the package guide, per combination: the smallest relative rise of the
    ensemble-mean k between neighbouring loads; raises on R = 1 (the failure under test)."""
    if combination.axes["radius"] == 1.0:
        raise RuntimeError("no stiffness\nfor R = 1")
    k = combination.data["stiffness"].values
    rise = float((np.diff(k.mean(0)) / k.mean(0)[:-1]).min())
    return row("x", "k rises with F at every load", rise, rise, rise, 0.0, "consistent: test", **combination.axes)


@pytest.fixture
def failing_claim():
    """Claim (x) of :func:`_rise`, in the test's own registry: in place of any claim x of the package
    (the guide's example, copied in)."""
    claims.CLAIMS.pop("x", None)
    return register(Claim("x", "the ensemble-mean stiffness rises with the load", estimate=_rise))


def test_failing_combination_has_an_error_row(failing_claim):
    rows = _table(_groups(), _study()).query("claim == 'x'")
    assert rows.loc[rows["radius"] == 1.0, "verdict"].tolist() == ["error"], rows.to_dict("records")


def test_error_reason_is_the_exception_on_one_line(failing_claim):
    rows = _table(_groups(), _study()).query("claim == 'x' and radius == 1.0")
    assert rows["reason"].iloc[0] == "RuntimeError: no stiffness for R = 1", rows["reason"].iloc[0]


def test_other_combination_keeps_its_row(failing_claim):
    rows = _table(_groups(), _study()).query("claim == 'x' and radius == 0.5")
    k = _groups()["sphere"]["stiffness"].sel(radius=0.5).squeeze().values.mean(0)
    assert rows["measured"].iloc[0] == pytest.approx((np.diff(k) / k[:-1]).min(), rel=1e-12), rows.to_dict("records")


def test_other_claims_rows_are_unchanged(failing_claim):
    table = _table(_groups(), _study())
    del claims.CLAIMS["x"]
    without_x = _table(_groups(), _study())
    others = table[table["claim"] != "x"].reset_index(drop=True)
    pd.testing.assert_frame_equal(others, without_x, rtol=1e-12)


def test_failing_claim_is_logged_by_its_letter(failing_claim, caplog):
    with caplog.at_level(logging.WARNING, logger="roughcontact.study.claims.registry"):
        _table(_groups(), _study())
    assert any("claim x failed" in r.getMessage() for r in caplog.records), [r.getMessage() for r in caplog.records]


def test_whole_study_claim_that_raises_has_one_error_row():
    claims.CLAIMS.pop("y", None)
    register(Claim("y", "a claim that fails", lambda inputs: 1 / 0))
    table = _table(_groups(), _study())
    assert table.query("claim == 'y'")["verdict"].tolist() == ["error"], table.query("claim == 'y'").to_dict("records")


def test_failed_lists_the_letters(failing_claim):
    assert claims.failed(_table(_groups(), _study())) == ["x"]


def test_error_verdict_is_coloured_in_the_html_table(failing_claim):
    page = tables.html_table(_table(_groups(), _study()), title="claims", lead="")
    assert f'class="verdict-error" style="background:{tables.VERDICT_COLOURS["error"]}"' in page


def test_each_combination_is_estimated_on_its_own_seed_force_slice():
    """The guide's claim on a two-combination study: one row per radius (no transpose error)."""
    claims.CLAIMS.pop("z", None)
    register(Claim("z", "k rises", estimate=lambda c: row("z", "k", float(c.data["stiffness"].shape[0]), 0, 0, 0,
                                                          "consistent: shape", **c.axes)))
    rows = _table(_groups(), _study()).query("claim == 'z'")
    assert rows["measured"].tolist() == [len(SCALES)] * len(RADII), rows.to_dict("records")


# ---------------------------------------------------------------------------------------------
# a new optional axis off its paper value
# ---------------------------------------------------------------------------------------------
@pytest.fixture
def toy_axis():
    """An optional axis of the roughness with paper value 0 and no claim of its own, in the test's
    own registry."""
    spec = axes.register(axes.Axis(
        "rolloff_power", "rp", "power of the roll-off", "1", "power of the roll-off plateau (0: flat plateau)",
        {"type": "number", "minimum": 0, "maximum": 4}, "roughness", paper=0.0, flag_help="power"))
    schema._package_schema.cache_clear()
    return spec


@pytest.fixture
def toy_table(toy_axis):
    return _table(_groups(("rolloff_power", [0.0, 1.5])), _study(rolloff_power=[0.0, 1.5]))


@pytest.mark.parametrize("letter", ["a", "b", "d", "e", "f"])
def test_claims_a_to_f_are_untested_off_the_new_axis(toy_table, letter):
    rows = toy_table[(toy_table["claim"] == letter) & (toy_table["rolloff_power"] == 1.5)]
    assert set(rows["verdict"]) == {"untested"}, rows[["verdict", "reason"]].to_dict("records")


@pytest.mark.parametrize("letter", ["a", "b", "d", "e", "f"])
def test_untested_reason_names_the_new_axis(toy_table, letter):
    rows = toy_table[(toy_table["claim"] == letter) & (toy_table["rolloff_power"] == 1.5)]
    assert all("rolloff_power = 1.5" in reason for reason in rows["reason"]), rows["reason"].tolist()


def test_claims_a_to_f_are_judged_at_the_paper_value_of_the_new_axis(toy_table):
    rows = toy_table[toy_table["claim"].isin(list("abdef")) & (toy_table["rolloff_power"] == 0.0)]
    assert not any("rolloff_power" in str(reason) for reason in rows["reason"]), rows["reason"].tolist()


def test_claim_g_leaves_the_new_axis_out(toy_table):
    """Two radii at the paper's setting: (g) fits the R exponent on those two, not on four."""
    rows = toy_table[(toy_table["claim"] == "g") & toy_table["statement"].str.startswith("F_tr ~ R")]
    assert rows["sweep"].tolist() == [f"2 sphere combinations at H = {HURST:g}"], rows.to_dict("records")


def test_claim_l_does_not_pool_the_new_axis(toy_axis):
    """Flat local exponents with a roll-off: 0.5 at the paper's setting, 1 with the new axis off it;
    pooled, the interval of some load would hold 1."""
    study = _study(radius=[math.inf], rolloff=[None, 0.25], rolloff_power=[0.0, 1.5])
    exponents = pd.DataFrame({"kind": "flat", "hurst": HURST, "rolloff": 0.25, "rolloff_power": [0.0, 0.0, 1.5, 1.5],
                              "force": [1e-4, 1e-3, 1e-4, 1e-3], "local_exponent": [0.5, 0.5, 1.0, 1.0],
                              "ci_low": [0.45, 0.45, 0.95, 0.95], "ci_high": [0.55, 0.55, 1.05, 1.05]})
    rows = [r for r in exponent_rows(exponents, _ZETA.iloc[:0], study) if r["claim"] == "l"]
    assert [r["verdict"] for r in rows] == ["differs"], rows


def test_claim_c_is_untested_where_the_zeta_fit_lacks_the_paper_setting(toy_axis):
    """Every run has the new axis off its paper value: the zeta fit takes it (zeta.csv's source says
    'with rolloff_power = 1.5'), and (c)'s row of zeta.csv names the axis instead of a verdict."""
    table = _table(_groups(("rolloff_power", [1.5])), _study(rolloff_power=[1.5]))
    rows = table[(table["claim"] == "c") & table["radius"].isna()]
    assert rows["reason"].tolist() == ["eqs. 11-17 are for an elastic, purely self-affine surface; here "
                                       "rolloff_power = 1.5"], rows[["verdict", "reason"]].to_dict("records")


def test_claim_c_is_judged_where_the_zeta_fit_has_the_paper_setting(toy_table):
    rows = toy_table[(toy_table["claim"] == "c") & toy_table["radius"].isna()]
    assert rows["verdict"].tolist() == ["consistent"], rows[["verdict", "reason"]].to_dict("records")


# ---------------------------------------------------------------------------------------------
# the rules of Claim.applies and the combinations the registry passes
# ---------------------------------------------------------------------------------------------
def _combinations(groups, study):
    from roughcontact.study.claims.registry import ClaimInputs, combinations

    cross, reps = crossover_table(groups, _ZETA, study)
    return list(combinations(ClaimInputs(cross=cross, replicates=reps, zeta=_ZETA, study=study, groups=groups)))


def test_paper_setting_rule_skips_a_combination_off_the_paper_setting(toy_axis):
    from roughcontact.study.claims.registry import paper_setting

    combos = _combinations(_groups(("rolloff_power", [0.0, 1.5])), _study(rolloff_power=[0.0, 1.5]))
    assert [paper_setting(c) for c in combos] == ["", None, "", None], [c.axes for c in combos]


def test_all_of_gives_the_untested_reason_of_its_rules(toy_axis):
    from roughcontact.study.claims.registry import all_of, at_theory, with_crossover

    combos = _combinations(_groups(("rolloff_power", [1.5])), _study(rolloff_power=[1.5]))
    reason = all_of(with_crossover, at_theory)(combos[0])
    assert reason == ("untested: off the paper's setting: eqs. 11-17 are for an elastic, purely self-affine surface; "
                      "here rolloff_power = 1.5")


def test_combination_carries_its_crossover_row():
    combos = _combinations(_groups(), _study())
    assert [float(c.crossover["radius"]) for c in combos] == list(RADII)


def test_with_axes_gives_the_paired_combination(toy_axis):
    combos = _combinations(_groups(("rolloff_power", [0.0, 1.5])), _study(rolloff_power=[0.0, 1.5]))
    paired = combos[1].with_axes(rolloff_power=0.0)
    assert paired.axes == combos[0].axes, (paired.axes, combos[0].axes)


def test_with_axes_of_a_value_not_swept_is_none():
    assert _combinations(_groups(), _study())[0].with_axes(radius=7.0) is None


def test_the_claims_import_nothing_of_the_report():
    """The claims estimate and judge; the report writes their files (:mod:`roughcontact.study.report.claims`):
    no module the claims import, however indirectly, is one of the report's."""
    from roughcontact.study import registries

    report = registries.PACKAGE / "study" / "report"
    reached = sorted(str(p.relative_to(registries.PACKAGE)) for p in registries._closure(("roughcontact.study.claims",))
                     if report in p.parents)
    assert not reached, f"the claims import the report's {reached}"
