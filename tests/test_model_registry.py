"""A model registered in one module (roughcontact.models.scorecard) is scored by the generated
scorecard and predicted by the measured one; the registry holds the seven models in order."""
from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from examples import in_order, loaded, scoped_registry  # noqa: F401 -- scoped_registry: every test in its own registries
from test_scorecard import CFG, FORCE, HURST, ZETA, _groups

from roughcontact.models import paper
from roughcontact.models import scorecard as registry
from roughcontact.study.analysis import scorecard
from roughcontact.study.report import scorecard as report_scorecard
from roughcontact.study.analysis.measured_models import predict
from roughcontact.surfaces import self_affine
from roughcontact.surfaces.spectrum_fit import fit_spectrum


@pytest.fixture
def hertz_model():
    """The package guide's worked example (``docs/guide/extending/model_example.py``), the smooth
    body (eq. 9 for the paraboloid): loaded as its module in the test's own registry."""
    with loaded("model_example.py", registry.MODELS, "smooth_body"):
        yield registry.MODELS["smooth_body"]


def hertz(force, s: registry.Surface):
    """eq. 9, a model function for the registry's own checks."""
    return paper.hertz_stiffness(force, radius=s.radius, e_star=s.e_star)


#: the package's own models, in the order of the tables and figures
PACKAGE_MODELS = ("eq16_paper", "eq16_fitted", "eq16_law", "contact_scale", "contact_scale_h", "contact_scale_tail",
                  "greenwood_tripp", "mdr", "persson")


def test_registry_order():
    """The package's models lead, in order; a module added to the package follows them."""
    names = list(registry.models())
    assert names[:len(PACKAGE_MODELS)] == list(PACKAGE_MODELS), f"models: {names}"


def test_a_model_of_a_further_module_follows_the_package_models(hertz_model):
    names = list(registry.models())
    assert in_order(PACKAGE_MODELS + ("smooth_body",), names), f"models: {names}"


def test_the_model_example_loads_twice():
    for _ in range(2):
        with loaded("model_example.py", registry.MODELS, "smooth_body"):
            assert "smooth_body" in registry.models()


def test_second_registration_of_a_name_is_an_error():
    with pytest.raises(ValueError, match="eq16_paper"):
        registry.register(registry.Model("eq16_paper", "again", hertz))


def test_generated_scorecard_scores_a_registered_model(hertz_model):
    table, _ = scorecard.scorecard(_groups(np.ones(4)), pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    row = table[table["model"] == "smooth_body"]
    assert len(row) == 1, f"models scored: {sorted(set(table['model']))}"


def test_registered_model_deviation_is_its_closed_form(hertz_model):
    """The ensemble is eq. 16 (fitted ζ); the row's largest deviation is that of eq. 9 from it."""
    table, _ = scorecard.scorecard(_groups(np.ones(4)), pd.DataFrame({"hurst": [HURST], "zeta": [ZETA]}), CFG)
    k16 = paper.stiffness_from_force(FORCE, radius=0.5, hurst=HURST, h_rms=9e-3, length=1.0, e_star=1.0, zeta=ZETA)
    resolved = FORCE >= 1e-5
    expected = np.abs(paper.hertz_stiffness(FORCE, radius=0.5, e_star=1.0)[resolved] / k16[resolved] - 1).max()
    got = float(table[table["model"] == "smooth_body"]["max_rel_dev"].iloc[0])
    assert got == pytest.approx(expected, rel=1e-12), f"max_rel_dev {got} against {expected}"


def test_lead_paragraph_names_a_registered_model(hertz_model):
    assert "smooth_body: the smooth body of revolution, eq. 7 (eq. 9 for the paraboloid)" in report_scorecard.scorecard_lead(), "lead paragraph"


def test_measured_scorecard_predicts_a_registered_model(hertz_model):
    h = self_affine(64, hurst=0.8, h_rms=0.009, length=1.0, seed=1)
    fit = fit_spectrum(h, length=1.0, window=None, detrend="mean", resamples=10)
    out = predict(FORCE, fit, radius=0.5, e_star=1.0, length=1.0, n=64)
    np.testing.assert_allclose(out["smooth_body"], paper.hertz_stiffness(FORCE, radius=0.5, e_star=1.0), rtol=1e-14,
                               err_msg="measured prediction of the registered model")


def test_model_that_does_not_apply_is_left_out(hertz_model):
    h = self_affine(64, hurst=0.8, h_rms=0.009, length=1.0, seed=1)
    fit = fit_spectrum(h, length=1.0, window=None, detrend="mean", resamples=10)
    out = predict(FORCE, fit, radius=math.inf, e_star=1.0, length=1.0, n=64)
    assert "smooth_body" not in out, f"a flat surface got {sorted(out)}"
