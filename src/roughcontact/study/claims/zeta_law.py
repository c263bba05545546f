"""Claim (c'): a ζ(H) law whose form the data choose (:mod:`roughcontact.study.analysis.zeta.law`) beside eq. 13."""
from __future__ import annotations

import math

import numpy as np

from ..analysis.statistics import NO_PREDICTION, NOT_SWEPT, UNRESOLVED, judge, untested, verdict_bound
from .registry import Claim, flat_zeta_rows, register, row

#: the paper's values of the parameters of the candidate ζ(H) laws, where eq. 13 is of that form
EQ13_PARAMETERS = {"a/(H+1)": {"a": 1.7}, "a/(H+b)": {"a": 1.7, "b": 1.0}, "a*(H+1)^-b": {"a": 1.7, "b": 1.0},
                   "a/(H+1)+b/H": {"a": 1.7, "b": 0.0}}


def _c_prime(inputs):
    """From the flat runs: one row per parameter of the chosen law against eq. 13's value where
    eq. 13 has that form, and one row for the law's largest deviation from the measured ζ(H)
    against eq. 13's."""
    from ...models.zeta_law import LAWS
    from ..analysis.zeta.law import MIN_HURST, fit_zeta_law

    n = inputs.study.grid.n
    flat = flat_zeta_rows(inputs.zeta)
    swept = len(flat)
    flat = flat[np.isfinite(flat["zeta_ci_low"].to_numpy(float))] if len(flat) else flat
    statement = "zeta(H) follows a law whose form the data choose (eq. 13: 1.7/(H+1))"
    if len(flat) < MIN_HURST:
        # fewer H with flat runs than a law needs (not swept), or some without a zeta interval (unresolved)
        return [row("c'", statement, math.nan, math.nan, math.nan, math.nan,
                    untested(NOT_SWEPT if swept < MIN_HURST else UNRESOLVED,
                             f"{len(flat)} H value(s) with flat runs and a zeta interval (a law needs {MIN_HURST})"))]
    hurst = flat["hurst"].to_numpy(float)
    law = fit_zeta_law(hurst, flat["zeta"], flat["zeta_ci_low"], flat["zeta_ci_high"],
                       inputs.zeta_replicates.sel(hurst=hurst).values, level=inputs.study.fit.confidence)
    aic = ", ".join(f"{form} {value:.1f}" for form, value in sorted(law.aic.items(), key=lambda kv: kv[1]))
    sweep = (f"flat H = {hurst.min():g}...{hurst.max():g} ({hurst.size} values), "
             f"{int(flat['n_seeds'].iloc[0])} seeds, n = {n}")
    note = f"AIC of the {len(LAWS)} candidate forms (lower is better): {aic}"
    out = []
    for name, value in law.parameters.items():
        paper = EQ13_PARAMETERS.get(law.form, {}).get(name, math.nan)
        text = (judge(paper, law.ci_low[name], law.ci_high[name]) if math.isfinite(paper)
                else untested(NO_PREDICTION, "eq. 13 is not of this form"))
        out.append(row("c'", f"zeta(H) = {law.form} chosen by the data: parameter {name}", value,
                       law.ci_low[name], law.ci_high[name], paper, text, sweep=sweep, note=note))
    out.append(row(
        "c'", f"the law zeta = {law.form} deviates less from the measured zeta(H) than eq. 13",
        law.max_rel_dev, law.max_rel_dev_ci_low, law.max_rel_dev_ci_high, law.eq13_max_rel_dev,
        verdict_bound(0.0, law.difference_ci_low, law.difference_ci_high, side="below"), sweep=sweep,
        note=(f"measured: max over H of |law/zeta - 1|; paper value: the same for 1.7/(H+1); verdict on the "
              f"paired difference law - eq. 13, interval {law.difference_ci_low:.3g}...{law.difference_ci_high:.3g}")))
    return out


register(Claim("c'", "zeta(H) follows a law whose form the data choose (eq. 13: 1.7/(H+1))", _c_prime,
               needs=("zeta_replicates",)))
