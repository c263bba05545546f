"""Statistics of the study: bootstrap over seeds, percentile intervals, the verdict rules and
the least-squares log-log slope.

Every interval of the study is a percentile bootstrap over the seeds (Efron & Tibshirani,
An Introduction to the Bootstrap, Chapman & Hall 1993, doi 10.1201/9780429246593) with one
fixed random state, :data:`BOOTSTRAP_SEED`, so that every run of the analysis gives the same
numbers. A claim is ``consistent`` when its predicted value lies inside the measured interval,
``differs`` when it lies outside and ``untested`` when it cannot be decided; an interval that is a
point (one seed, one load, no scatter) decides nothing (:func:`untested_if_degenerate`).

An untested verdict of the claims table always names why, in one word of the closed vocabulary
:data:`UNTESTED_BECAUSE` (the ``untested_because`` column of ``claims.csv``), beside its free-text
reason: a verdict text is ``"<verdict>: <reason>"`` and an untested one is made by :func:`untested`,
``"untested: <because>: <reason>"``; :func:`split_verdict` reads it back and refuses an untested text
without a named reason (so a claim cannot invent one).
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["BOOTSTRAP_SEED", "bootstrap_indices", "interval", "weighted_deviation", "verdict", "verdict_bound", "judge", "untested",
           "untested_if_degenerate", "DEGENERATE",
           "split_verdict", "log_log_slope", "inverse_variance_weights", "UNTESTED_BECAUSE", "VERDICTS", "CONSISTENT", "DIFFERS", "NOT_SWEPT", "OFF_PAPER", "HOLDS_THRESHOLD", "UNRESOLVED",
           "OUT_OF_RANGE", "NO_PREDICTION"]

#: random state of every bootstrap (the paper's acceptance date)
BOOTSTRAP_SEED = 20130702

#: the verdict words of the claims table
VERDICTS = ("consistent", "differs", "untested", "error")
#: the two verdicts of a tested value: inside its interval, or excluded by it
CONSISTENT, DIFFERS = VERDICTS[:2]

#: why a claim is untested (the ``untested_because`` column): the sweep lacks what the claim needs
#: (a second radius, flat runs, a run to pair with, a preload, overlapping ranges)
NOT_SWEPT = "not swept"
#: the combination is off the paper's setting of an optional axis (the registry's ``at_theory``)
OFF_PAPER = "off the paper's setting"
#: a bound claim whose interval contains the bound (:func:`verdict_bound`)
HOLDS_THRESHOLD = "interval holds the threshold"
#: too few resolved loads or contact cells, no load in the window, no interval (the data, not the sweep)
UNRESOLVED = "unresolved"
#: the combination lies outside the range the claim's model is stated for
OUT_OF_RANGE = "outside the model's range"
#: the claim predicts no value to compare with here (a threshold itself, a law of another form)
NO_PREDICTION = "no prediction"
#: the closed vocabulary of ``untested_because``, in this order
UNTESTED_BECAUSE = (NOT_SWEPT, OFF_PAPER, HOLDS_THRESHOLD, UNRESOLVED, OUT_OF_RANGE, NO_PREDICTION)


def untested(because: str, reason: str) -> str:
    """The verdict text of an untested claim, ``"untested: <because>: <reason>"``.

    Parameters
    ----------
    because : str
        One of :data:`UNTESTED_BECAUSE`.
    reason : str
        The free-text reason (the ``reason`` column).

    Raises
    ------
    ValueError
        If *because* is not in :data:`UNTESTED_BECAUSE`.
    """
    if because not in UNTESTED_BECAUSE:
        raise ValueError(f"untested because {because!r}: not one of {', '.join(UNTESTED_BECAUSE)}")
    return f"untested: {because}: {reason}"


def split_verdict(text: str) -> tuple[str, str, str]:
    """``(verdict, untested_because, reason)`` of a verdict text (``"<verdict>: <reason>"``, an
    untested one from :func:`untested`); *untested_because* is ``""`` unless the verdict is ``untested``.

    Raises
    ------
    ValueError
        For an ``untested`` text without a reason of :data:`UNTESTED_BECAUSE`.
    """
    word, _, rest = text.partition(": ")
    word = word.split(":")[0]
    if word != "untested":
        return word, "", rest
    because = next((b for b in UNTESTED_BECAUSE if rest == b or rest.startswith(b + ": ")), None)
    if because is None:
        raise ValueError(f"untested verdict {text!r} names no reason of {', '.join(UNTESTED_BECAUSE)} "
                         "(make it with roughcontact.study.analysis.statistics.untested)")
    return word, because, rest[len(because) + 2:]


#: why a verdict whose interval is a point is no verdict (:func:`untested_if_degenerate`)
DEGENERATE = ("the interval is a point ([{low:.4g}, {high:.4g}]): it rests on one seed, one load or no scatter "
              "between seeds, and a verdict needs a sampling interval (at least 2 seeds)")


def untested_if_degenerate(text: str, low: float, high: float) -> str:
    """*text* (a verdict text), or :func:`untested` (:data:`UNRESOLVED`, :data:`DEGENERATE`) when it
    is ``consistent`` or ``differs`` and its interval ``[low, high]`` is missing or has no width: a
    percentile bootstrap over one seed, or over seeds that agree exactly, is a point and decides
    nothing. The one rule every row of the claims table passes
    (:func:`roughcontact.study.claims.registry.row`)."""
    word = text.partition(":")[0]
    if word not in (CONSISTENT, DIFFERS):
        return text
    try:
        low, high = float(low), float(high)
    except (TypeError, ValueError):
        low = high = math.nan
    if math.isfinite(low) and math.isfinite(high) and high > low:
        return text
    if not (math.isfinite(low) and math.isfinite(high)):
        return untested(UNRESOLVED, "no interval")
    return untested(UNRESOLVED, DEGENERATE.format(low=low, high=high))


def verdict(value: float, low: float, high: float) -> str:
    """``consistent`` if ``low ≤ value ≤ high``, ``differs`` otherwise (``untested`` for a NaN interval
    or one that is a point, :func:`untested_if_degenerate`)."""
    if not (math.isfinite(low) and math.isfinite(high) and math.isfinite(value)) or not high > low:
        return "untested"
    return CONSISTENT if low <= value <= high else DIFFERS


def judge(value: float, low: float, high: float) -> str:
    """The verdict text of a two-sided claim: :func:`verdict`, and where it is ``untested`` the
    named reason (:data:`UNRESOLVED`, no interval; :data:`NO_PREDICTION`, no finite *value*)."""
    if not math.isfinite(value):
        return untested(NO_PREDICTION, "no finite paper value")
    if not (math.isfinite(low) and math.isfinite(high)):
        return untested(UNRESOLVED, "no interval")
    if not high > low:
        return untested(UNRESOLVED, DEGENERATE.format(low=low, high=high))
    return verdict(value, low, high)


def verdict_bound(bound: float, low: float, high: float, *, side: str) -> str:
    """Verdict on a one-sided claim ``value < bound`` (``side="below"``) from its interval:
    ``consistent`` if the whole interval lies on the claimed side, ``differs`` if it lies
    wholly on the other, ``untested`` (:data:`HOLDS_THRESHOLD`, with the reason) if it contains the
    bound, or (:data:`UNRESOLVED`) if there is no interval."""
    if not (math.isfinite(low) and math.isfinite(high)):
        return untested(UNRESOLVED, "no interval")
    if not high > low:
        return untested(UNRESOLVED, DEGENERATE.format(low=low, high=high))
    inside, outside = (high < bound, low > bound) if side == "below" else (low > bound, high < bound)
    if inside:
        return CONSISTENT
    return DIFFERS if outside else untested(HOLDS_THRESHOLD, f"the interval contains {bound:g}")


def bootstrap_indices(n_seeds: int, resamples: int, *, seed: int = BOOTSTRAP_SEED) -> np.ndarray:
    """``(resamples, n_seeds)`` seed indices drawn with replacement (fixed random state)."""
    return np.random.default_rng(seed).integers(0, n_seeds, size=(resamples, n_seeds))


def inverse_variance_weights(boot: np.ndarray, mean: np.ndarray, use) -> np.ndarray:
    """The weight of each load *use* in a branch's mean deviation (the stiffness and area
    scorecards' systematic deviation): the inverse variance of the ensemble mean there, relative,
    from its bootstrap *boot* ``(resample, load)`` over the ensemble mean *mean* ``(load,)``; loads
    without scatter weigh equally (their variance is floored at ``eps²``)."""
    relative = boot[:, use] / mean[use]
    return 1.0 / np.maximum(relative.var(axis=0, ddof=1), np.finfo(float).eps ** 2)


def weighted_deviation(model: np.ndarray, mean: np.ndarray, boot: np.ndarray, use, level: float) -> tuple:
    """A model's systematic deviation on a branch (the stiffness and area scorecards'): the mean of
    ``model/mean − 1`` over the loads *use*, each weighted by :func:`inverse_variance_weights`, and
    the *level* interval of the same weighted mean over the bootstrap's ensembles *boot*
    ``(resample, load)``: ``(value, low, high)``. *use* must hold a load."""
    weight = inverse_variance_weights(boot, mean, use)
    value = float(np.sum(weight * (model[use] / mean[use] - 1)) / weight.sum())
    low, high = interval((model[use] / boot[:, use] - 1) @ weight / weight.sum(), level)
    return value, low, high


def interval(samples: np.ndarray, level: float) -> tuple[float, float]:
    """Percentile interval of the finite *samples* (NaN, NaN if fewer than half are finite)."""
    finite = samples[np.isfinite(samples)]
    if finite.size < max(2, samples.size // 2):
        return math.nan, math.nan
    low, high = np.percentile(finite, [50 * (1 - level), 50 * (1 + level)])
    return float(low), float(high)


def log_log_slope(log_x, log_y, *, covariates=None):
    """The least-squares slope of ``ln y`` against ``ln x``: the exponent ``a`` of ``y = c x^a``.

    The one log-log slope of the study: the asymptotic slopes of eq. 16 (the crossover table),
    the change of the low-force slope by a roll-off (claim (j)), the free exponent of the ζ fit and
    the exponents of ``F_tr`` in R and h_rms (claim (g), with the other as a covariate).

    Parameters
    ----------
    log_x : array_like, shape (m,)
        The logarithms ``ln x`` of the abscissae (any unit: a unit shifts ``ln x`` only).
    log_y : array_like, shape (..., m)
        The logarithms ``ln y``, one curve per leading index (e.g. bootstrap replicates).
    covariates : array_like, shape (p, m), optional
        Further regressors (logarithms of other swept quantities) fitted beside ``ln x``: the slope
        is then the partial coefficient of ``ln x`` in ``ln y = b + a ln x + Σ c_j z_j``.

    Returns
    -------
    ndarray or float
        The slope ``a``, shape ``(...)``; NaN where ``ln x`` does not vary (with covariates: where
        they explain all but ``1e-10`` of its variance).

    Notes
    -----
    ``a = Σ x̃_i ln y_i / Σ x̃_i²`` with ``x̃`` the residual of ``ln x`` after the least-squares fit
    of a constant (and the covariates) to it: ``x̃ = ln x − mean(ln x)`` without covariates
    (Frisch & Waugh, Econometrica 1, 387 (1933), doi:10.2307/1907330: the same coefficient as the
    full least-squares fit).
    """
    log_x = np.asarray(log_x, dtype=float)
    log_y = np.asarray(log_y, dtype=float)
    centred = log_x - log_x.mean()
    if covariates is None or np.size(covariates) == 0:
        xm, floor = centred, 0.0
    else:   # ln x explained by the covariates (a sweep that is no product) leaves no slope to fit
        design = np.column_stack([np.ones(log_x.size), *np.atleast_2d(np.asarray(covariates, dtype=float))])
        xm, floor = log_x - design @ np.linalg.lstsq(design, log_x, rcond=None)[0], 1e-10 * (centred @ centred)
    norm = xm @ xm
    if not norm > floor:
        return np.full(log_y.shape[:-1], math.nan) if log_y.ndim > 1 else math.nan
    return (log_y * xm).sum(-1) / norm
