"""Argument checks shared by the package: each raises ``ValueError`` naming the argument."""

from __future__ import annotations

import math
import numbers

MIN_GRID = 8


def check_finite_positive(name: str, value) -> None:
    """Raise ``ValueError`` unless ``value`` is a finite real number > 0."""
    if (isinstance(value, bool) or not isinstance(value, numbers.Real)
            or not math.isfinite(value) or value <= 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")


def check_hurst(hurst) -> None:
    """Raise ``ValueError`` unless ``0 < hurst < 2`` (the paper's range of validity)."""
    if (isinstance(hurst, bool) or not isinstance(hurst, numbers.Real)
            or not math.isfinite(hurst) or not 0 < hurst < 2):
        raise ValueError(f"hurst must be a number with 0 < hurst < 2, got {hurst!r}")


def check_grid_size(n) -> None:
    """Raise ``ValueError`` unless ``n`` is an integer ≥ 8."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < MIN_GRID:
        raise ValueError(f"n must be an integer >= {MIN_GRID}, got {n!r}")
