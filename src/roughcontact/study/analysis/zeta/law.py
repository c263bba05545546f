"""A law ζ(H) over the swept Hurst exponents, its form chosen by the data (claim c′).

The paper gives ζ(H) ≈ 1.7/(H+1) (eq. 13) from flat surfaces with H ≤ 1 and claims its
model for 0 < H < 2. Here every candidate of :data:`LAWS` is fitted to the study's ζ(H)
(``zeta.csv``, flat runs) by weighted least squares in ln ζ,

    minimise  Σ_H ((ln ζ_H − ln law(H; θ)) / σ_H)²,   σ_H = (ln ζ_hi − ln ζ_lo)/(2 z),

σ_H the standard error of ln ζ from ζ's bootstrap interval at level α (z = Φ⁻¹((1+α)/2),
1.96 at 95 %). The form with the smallest
Akaike information criterion AIC = χ² + 2p (p parameters; Akaike, IEEE Trans. Autom. Control
19, 716 (1974), doi 10.1109/TAC.1974.1100705) is the one the data choose. Its parameters, and
its largest relative deviation from the measured ζ(H), get 95 % intervals by refitting the
chosen form to every bootstrap replicate of ζ(H) (``zeta.nc``: the same resampled seeds for
every H, so the replicates keep the correlation between the H values); the comparison with
eq. 13 is paired on the same replicates.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ....models import paper
from ....models.zeta_law import LAWS
from ..statistics import interval

__all__ = ["MIN_HURST", "ZetaLaw", "fit_law", "fit_zeta_law"]

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

    from scipy.optimize import least_squares  # (here: the ζ fit's job imports this module, not the law)

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
    difference_ci_low, difference_ci_high : float
        Interval of the law's largest deviation minus eq. 13's, both taken on the same
        bootstrap replicate (paired): below 0 throughout means the law describes ζ(H)
        better than eq. 13.
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
    difference_ci_low: float
    difference_ci_high: float
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
    from scipy.special import ndtri  # the normal quantile, as scipy.stats.norm.ppf (without scipy.stats)

    sigma = np.log(ci_high / ci_low) / (2 * ndtri(0.5 + level / 2))
    sigma = np.where(np.isfinite(sigma) & (sigma > 0), sigma, np.nanmax(sigma))
    aic, fitted = {}, {}
    for form, (_, names, _) in LAWS.items():
        theta = fit_law(form, hurst, zeta, sigma)
        fitted[form] = theta
        aic[form] = _chi2(form, hurst, zeta, sigma, theta) + 2 * len(names)
    form = min(aic, key=aic.get)
    names = LAWS[form][1]
    # every replicate refitted (NaN where a replicate lacks an H, so interval() counts it as missing)
    boot = np.full((replicates.shape[1], len(names)), np.nan)
    devs, differences = np.full(replicates.shape[1], np.nan), np.full(replicates.shape[1], np.nan)
    eq13 = paper.zeta_estimate(hurst)
    for j in np.flatnonzero(np.all(np.isfinite(replicates), axis=0)):
        boot[j] = fit_law(form, hurst, replicates[:, j], sigma)
        devs[j] = np.max(np.abs(LAWS[form][0](hurst, *boot[j]) / replicates[:, j] - 1))
        differences[j] = devs[j] - np.max(np.abs(eq13 / replicates[:, j] - 1))
    bounds = [interval(boot[:, i], level) for i in range(len(names))]
    dev_low, dev_high = interval(devs, level)
    diff_low, diff_high = interval(differences, level)
    law = LAWS[form][0](hurst, *fitted[form])
    return ZetaLaw(form=form, parameters=dict(zip(names, map(float, fitted[form]))),
                   ci_low={k: b[0] for k, b in zip(names, bounds)}, ci_high={k: b[1] for k, b in zip(names, bounds)},
                   max_rel_dev=float(np.max(np.abs(law / zeta - 1))), max_rel_dev_ci_low=dev_low,
                   max_rel_dev_ci_high=dev_high,
                   eq13_max_rel_dev=float(np.max(np.abs(eq13 / zeta - 1))),
                   difference_ci_low=diff_low, difference_ci_high=diff_high,
                   aic={k: float(v) for k, v in aic.items()}, hurst=tuple(map(float, hurst)))
