"""The effective modulus of two elastic bodies in contact.

Hertz's contact of two elastic bodies is that of a rigid body on a half-space of modulus ``E*``
(K. L. Johnson, *Contact Mechanics*, Cambridge University Press 1985, eq. 4.22,
doi:10.1017/CBO9781139171731)::

    1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂.

The package's forces and stiffnesses are in units of ``E*``; this is how to get it from the two
materials.
"""
from __future__ import annotations

import math
import numbers

__all__ = ["effective_modulus"]


def _check(name: str, value, *, modulus: bool) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} must be a number, got {value!r}")
    value = float(value)
    if modulus and not (value > 0 and not math.isnan(value)):
        raise ValueError(f"{name} must be a modulus > 0 (inf: a rigid body), got {value!r}")
    if not modulus and not -1.0 < value <= 0.5:
        raise ValueError(f"{name} must be a Poisson ratio with -1 < {name} <= 0.5, got {value!r}")
    return value


def effective_modulus(e1: float, nu1: float, e2: float = math.inf, nu2: float = 0.0) -> float:
    """``E* = 1/((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂)`` (Johnson 1985, eq. 4.22).

    Parameters
    ----------
    e1, nu1 : float
        Young's modulus (pressure) and Poisson ratio of the first body; ``E₁ > 0``,
        ``−1 < ν₁ ≤ 0.5``.
    e2, nu2 : float
        The same of the counter-body (same pressure unit); ``e2 = inf`` (default): a rigid
        counter-body, ``E* = E₁/(1 − ν₁²)``.

    Returns
    -------
    float
        ``E*`` in the unit of ``e1``. Both bodies rigid (``inf``) give ``inf``.

    Raises
    ------
    ValueError
        A modulus not > 0 or a Poisson ratio outside (−1, 0.5], naming the argument.
    """
    e1 = _check("e1", e1, modulus=True)
    nu1 = _check("nu1", nu1, modulus=False)
    e2 = _check("e2", e2, modulus=True)
    nu2 = _check("nu2", nu2, modulus=False)
    compliance = (1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2
    return math.inf if compliance == 0.0 else 1.0 / compliance
