"""A law ζ(H) over the swept Hurst exponents, its form chosen by the data (claim c′).

The paper gives ζ(H) ≈ 1.7/(H+1) (eq. 13) from flat surfaces with H ≤ 1 and claims its
model for 0 < H < 2. Here every candidate of :data:`LAWS` is fitted to the study's ζ(H)
(``zeta.csv``, flat runs) by weighted least squares in ln ζ,

    minimise  Σ_H ((ln ζ_H − ln law(H; θ)) / σ_H)²,   σ_H = (ln ζ_hi − ln ζ_lo)/(2 · 1.96),

σ_H the half-width of ζ's 95 % bootstrap interval in ln ζ. The form with the smallest
Akaike information criterion AIC = χ² + 2p (p parameters; Akaike, IEEE Trans. Autom. Control
19, 716 (1974), doi 10.1109/TAC.1974.1100705) is the one the data choose. Its parameters, and
its largest relative deviation from the measured ζ(H), get 95 % intervals by refitting the
chosen form to every bootstrap replicate of ζ(H) (``zeta.nc``: the same resampled seeds for
every H, so the replicates keep the correlation between the H values).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from .statistics import interval

__all__ = ["LAWS", "ZetaLaw", "fit_law", "fit_zeta_law"]

#: candidate forms: name -> (function of (H, parameters), parameter names, start values);
#: "a/(H+1)" is eq. 13's form (a = 1.7 in the paper)
LAWS = {
    "a/(H+1)": (lambda h, a: a / (h + 1.0), ("a",), (1.7,)),
    "a/(H+b)": (lambda h, a, b: a / (h + b), ("a", "b"), (1.7, 1.0)),
    "a*(H+1)^-b": (lambda h, a, b: a * (h + 1.0) ** -b, ("a", "b"), (1.7, 1.0)),
    "a*exp(-b*H)": (lambda h, a, b: a * np.exp(-b * h), ("a", "b"), (1.7, 0.5)),
    "a+b*H": (lambda h, a, b: a + b * h, ("a", "b"), (1.7, -0.5)),
}

#: fewest H values for a law with two parameters to be chosen and tested
MIN_HURST = 4


def fit_law(form: str, hurst, zeta, sigma) -> np.ndarray:
    """Parameters of the law *form* minimising the weighted squared residuals of ln ζ
    (module docstring); *sigma* is the standard error of ln ζ per H."""
    function, _, start = LAWS[form]
    hurst, zeta, sigma = (np.asarray(v, dtype=float) for v in (hurst, zeta, sigma))

    def residual(theta):
        with np.errstate(all="ignore"):
            value = function(hurst, *theta)
        return np.where(value > 0, (np.log(zeta) - np.log(np.abs(value) + 1e-300)) / sigma, 1e6)

    return least_squares(residual, start, method="lm").x


def _chi2(form, hurst, zeta, sigma, theta) -> float:
    return float(np.sum(((np.log(zeta) - np.log(LAWS[form][0](hurst, *theta))) / sigma) ** 2))


@dataclass(frozen=True)
class ZetaLaw:
    """The chosen law and what decides it.

    Attributes
    ----------
    form : str
        The chosen key of :data:`LAWS`.
    parameters, ci_low, ci_high : dict[str, float]
        Its parameters with their 95 % bootstrap intervals.
    max_rel_dev, max_rel_dev_ci_low, max_rel_dev_ci_high : float
        ``max_H |law(H)/ζ(H) − 1|`` over the swept H, with its interval.
    eq13_max_rel_dev : float
        The same for 1.7/(H+1) (eq. 13).
    aic : dict[str, float]
        AIC of every candidate (lower is better).
    hurst : tuple of float
        The H values the law rests on.
    """

    form: str
    parameters: dict
    ci_low: dict
    ci_high: dict
    max_rel_dev: float
    max_rel_dev_ci_low: float
    max_rel_dev_ci_high: float
    eq13_max_rel_dev: float
    aic: dict
    hurst: tuple

    def __call__(self, hurst):
        """ζ(H) of the law."""
        return LAWS[self.form][0](np.asarray(hurst, dtype=float), *self.parameters.values())


def fit_zeta_law(hurst, zeta, ci_low, ci_high, replicates, *, level: float = 0.95) -> ZetaLaw:
    """Choose and fit the law (module docstring).

    Parameters
    ----------
    hurst, zeta, ci_low, ci_high : array_like
        ζ(H) and its interval per H (``zeta.csv``), at least :data:`MIN_HURST` values.
    replicates : array_like
        ``(H, replicate)`` bootstrap replicates of ζ (``zeta.nc``'s ``zeta_replicates``).
    level : float
        Confidence level of the intervals.
    """
    hurst, zeta, ci_low, ci_high = (np.asarray(v, dtype=float) for v in (hurst, zeta, ci_low, ci_high))
    replicates = np.asarray(replicates, dtype=float)
    if hurst.size < MIN_HURST:
        raise ValueError(f"a zeta(H) law needs at least {MIN_HURST} Hurst exponents, got {hurst.size}")
    sigma = np.log(ci_high / ci_low) / (2 * 1.959964)
    sigma = np.where(np.isfinite(sigma) & (sigma > 0), sigma, np.nanmax(sigma))
    aic, fitted = {}, {}
    for form, (_, names, _) in LAWS.items():
        theta = fit_law(form, hurst, zeta, sigma)
        fitted[form] = theta
        aic[form] = _chi2(form, hurst, zeta, sigma, theta) + 2 * len(names)
    form = min(aic, key=aic.get)
    names = LAWS[form][1]
    boot = np.array([fit_law(form, hurst, replicates[:, j], sigma) for j in range(replicates.shape[1])
                     if np.all(np.isfinite(replicates[:, j]))])
    devs = np.array([np.max(np.abs(LAWS[form][0](hurst, *theta) / replicates[:, j] - 1))
                     for j, theta in zip(np.flatnonzero(np.all(np.isfinite(replicates), axis=0)), boot)])
    bounds = [interval(boot[:, i], level) for i in range(len(names))]
    dev_low, dev_high = interval(devs, level)
    law = LAWS[form][0](hurst, *fitted[form])
    return ZetaLaw(form=form, parameters=dict(zip(names, map(float, fitted[form]))),
                   ci_low={k: b[0] for k, b in zip(names, bounds)}, ci_high={k: b[1] for k, b in zip(names, bounds)},
                   max_rel_dev=float(np.max(np.abs(law / zeta - 1))), max_rel_dev_ci_low=dev_low,
                   max_rel_dev_ci_high=dev_high,
                   eq13_max_rel_dev=float(np.max(np.abs(1.7 / (hurst + 1) / zeta - 1))),
                   aic={k: float(v) for k, v in aic.items()}, hurst=tuple(map(float, hurst)))
