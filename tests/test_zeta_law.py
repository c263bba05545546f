"""The ζ(H) law of claim (c'): the form chosen by AIC and its parameters, on synthetic ζ(H)."""
import numpy as np
import pytest

from roughcontact.study.analysis.zeta.law import fit_zeta_law

HURST = np.linspace(0.1, 1.9, 19)


def _replicates(zeta, rel_sigma, *, resamples=400, seed=3):
    """Bootstrap-like replicates: ζ times a seeded log-normal scatter of *rel_sigma*."""
    rng = np.random.default_rng(seed)
    return zeta[:, None] * np.exp(rel_sigma * rng.standard_normal((zeta.size, resamples)))


def _fit(zeta, rel_sigma=0.02):
    half = 1.959964 * rel_sigma
    return fit_zeta_law(HURST, zeta, zeta * np.exp(-half), zeta * np.exp(half), _replicates(zeta, rel_sigma))


def test_eq13_data_choose_eq13_form():
    law = _fit(1.7 / (HURST + 1))
    assert law.form == "a/(H+1)", f"one-parameter form of exact eq. 13 data, AIC {law.aic}"


def test_eq13_data_give_a_of_1p7():
    law = _fit(1.7 / (HURST + 1))
    assert law.parameters["a"] == pytest.approx(1.7, rel=1e-8), "a of exact eq. 13 data"


def test_eq13_deviation_of_eq13_data_is_zero():
    assert _fit(1.7 / (HURST + 1)).eq13_max_rel_dev == pytest.approx(0.0, abs=1e-12), "eq. 13 on its own data"


def test_two_parameter_law_chosen_and_recovered():
    law = _fit(2.1 / (HURST + 0.6))
    assert law.form == "a/(H+b)", f"form of exact 2.1/(H+0.6) data, AIC {law.aic}"
    assert law.parameters["b"] == pytest.approx(0.6, rel=1e-6), "b of exact 2.1/(H+0.6) data"


def test_parameter_interval_holds_the_true_value():
    # replicates scattered by 2 % per H: b's interval must contain the value the data were made with
    law = _fit(2.1 / (HURST + 0.6))
    assert law.ci_low["b"] <= 0.6 <= law.ci_high["b"], f"b interval {law.ci_low['b']}..{law.ci_high['b']}"


def test_power_law_data_choose_power_form():
    law = _fit(1.3 * (HURST + 1) ** -0.55)
    assert law.form == "a*(H+1)^-b", f"form of exact 1.3 (H+1)^-0.55 data, AIC {law.aic}"


def test_law_callable_reproduces_fit():
    law = _fit(2.1 / (HURST + 0.6))
    assert law(HURST) == pytest.approx(2.1 / (HURST + 0.6), rel=1e-6), "ZetaLaw(H) against the data"


def test_too_few_hurst_values_raise():
    with pytest.raises(ValueError, match="at least 4 Hurst"):
        fit_zeta_law(HURST[:3], np.ones(3), np.full(3, 0.9), np.full(3, 1.1), np.ones((3, 10)))


def test_inverse_h_term_chosen_and_recovered():
    law = _fit(1.55 / (HURST + 1) + 0.11 / HURST)
    assert law.form == "a/(H+1)+b/H", f"form of exact 1.55/(H+1) + 0.11/H data, AIC {law.aic}"
    assert law.parameters["b"] == pytest.approx(0.11, rel=1e-6), "b of exact 1.55/(H+1) + 0.11/H data"
