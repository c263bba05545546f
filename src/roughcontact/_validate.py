"""Argument checks shared by the package: each raises ``ValueError`` naming the argument.

:func:`is_finite_number` is the package's one rule for numbers: a real number
(not a bool) that is finite -- or ``+inf`` where the caller allows it, which
only the sphere radius does (``radius = inf`` is a nominally flat surface).
NaN is never a value.  The configuration checks (:mod:`roughcontact.study.config.resolve`),
the command line and the argument checks below all use it.
"""

from __future__ import annotations

import math
import numbers

MIN_GRID = 8


def is_finite_number(value, allow_inf: bool = False) -> bool:
    """True for a real number (not a bool) that is finite, also as a float
    (an integer too large for a float is not); with *allow_inf* also for ``+inf``.
    NaN and ``-inf`` are never allowed."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return False
    try:
        as_float = float(value)
    except OverflowError:
        return False
    if math.isnan(as_float):
        return False
    return math.isfinite(as_float) or (allow_inf and as_float > 0)


def finite_rule(allow_inf: bool = False) -> str:
    """What :func:`is_finite_number` allows, in words (for error messages)."""
    return "a finite number or inf" if allow_inf else "a finite number"


def check_finite(name: str, value, allow_inf: bool = False) -> None:
    """Raise ``ValueError`` unless :func:`is_finite_number` holds."""
    if not is_finite_number(value, allow_inf):
        raise ValueError(f"{name} must be {finite_rule(allow_inf)}, got {value!r}")


def check_finite_positive(name: str, value) -> None:
    """Raise ``ValueError`` unless ``value`` is a finite real number > 0."""
    if not is_finite_number(value) or value <= 0:
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")


def check_radius(radius) -> None:
    """Raise ``ValueError`` unless ``radius`` is a finite number > 0 or ``inf``
    (a nominally flat surface)."""
    if not is_finite_number(radius, allow_inf=True) or radius <= 0:
        raise ValueError(f"radius must be a finite number > 0 or inf (flat), got {radius!r}")


def check_hurst(hurst) -> None:
    """Raise ``ValueError`` unless ``0 < hurst < 2`` (the paper's range of validity)."""
    if not is_finite_number(hurst) or not 0 < hurst < 2:
        raise ValueError(f"hurst must be a number with 0 < hurst < 2, got {hurst!r}")


def check_grid_size(n) -> None:
    """Raise ``ValueError`` unless ``n`` is an integer ≥ 8."""
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < MIN_GRID:
        raise ValueError(f"n must be an integer >= {MIN_GRID}, got {n!r}")
