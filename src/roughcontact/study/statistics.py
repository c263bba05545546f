"""Statistics of the study: bootstrap over seeds, percentile intervals and the verdict rules.

Every interval of the study is a percentile bootstrap over the seeds (Efron & Tibshirani,
An Introduction to the Bootstrap, Chapman & Hall 1993, doi 10.1201/9780429246593) with one
fixed random state, :data:`BOOTSTRAP_SEED`, so that every run of the analysis gives the same
numbers. A claim is ``consistent`` when its predicted value lies inside the measured interval,
``differs`` when it lies outside and ``untested`` when no interval could be formed.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["BOOTSTRAP_SEED", "bootstrap_indices", "interval", "verdict", "verdict_bound"]

#: random state of every bootstrap (the paper's acceptance date)
BOOTSTRAP_SEED = 20130702


def verdict(value: float, low: float, high: float) -> str:
    """``consistent`` if ``low ≤ value ≤ high``, ``differs`` otherwise (``untested`` for a NaN interval)."""
    if not (math.isfinite(low) and math.isfinite(high) and math.isfinite(value)):
        return "untested"
    return "consistent" if low <= value <= high else "differs"


def verdict_bound(bound: float, low: float, high: float, *, side: str) -> str:
    """Verdict on a one-sided claim ``value < bound`` (``side="below"``) from its interval:
    ``consistent`` if the whole interval lies on the claimed side, ``differs`` if it lies
    wholly on the other, ``untested`` (with the reason) if it contains the bound."""
    if not (math.isfinite(low) and math.isfinite(high)):
        return "untested: no interval"
    inside, outside = (high < bound, low > bound) if side == "below" else (low > bound, high < bound)
    if inside:
        return "consistent"
    return "differs" if outside else f"untested: the interval contains {bound:g}"


def bootstrap_indices(n_seeds: int, resamples: int, *, seed: int = BOOTSTRAP_SEED) -> np.ndarray:
    """``(resamples, n_seeds)`` seed indices drawn with replacement (fixed random state)."""
    return np.random.default_rng(seed).integers(0, n_seeds, size=(resamples, n_seeds))


def interval(samples: np.ndarray, level: float) -> tuple[float, float]:
    """Percentile interval of the finite *samples* (NaN, NaN if fewer than half are finite)."""
    finite = samples[np.isfinite(samples)]
    if finite.size < max(2, samples.size // 2):
        return math.nan, math.nan
    low, high = np.percentile(finite, [50 * (1 - level), 50 * (1 + level)])
    return float(low), float(high)
