"""Electrical and thermal contact conductance from the normal stiffness (Barber's analogy).

J. R. Barber, *Bounds on the electrical resistance between contacting elastic rough bodies*,
Proc. R. Soc. A 459, 53–66 (2003), doi:10.1098/rspa.2002.1038: for the same contact set, the
electrical conductance between two half-spaces of resistivities ``ρ₁``, ``ρ₂`` is

    C = 2k / (E* (ρ₁ + ρ₂)),

``k`` the incremental normal stiffness; the thermal conductance is the same with ``1/K₁ + 1/K₂``
(``K`` the thermal conductivities) in place of ``ρ₁ + ρ₂``. For one circle of radius ``a``
(``k = 2E*a``) it is Holm's ``C = 4a/(ρ₁ + ρ₂)``. Units: with ``k`` in N/m and ``E*`` in Pa,
``k/E*`` is a length in m; with ``ρ`` in Ω·m, ``C`` is in S; with ``K`` in W/(m·K), in W/K.
"""
from __future__ import annotations

import numpy as np

from .._validate import check_finite_positive

__all__ = ["electrical_conductance", "thermal_conductance"]


def electrical_conductance(stiffness, *, e_star: float, resistivities) -> np.ndarray:
    """``C = 2k/(E*(ρ₁ + ρ₂))`` (module docstring).

    Parameters
    ----------
    stiffness : array_like
        Normal stiffness ``k`` (force/length).
    e_star : float, keyword-only
        Effective modulus ``E*`` (force/length², the unit of ``k`` per length).
    resistivities : pair of float, keyword-only
        ``(ρ₁, ρ₂)`` of the two bodies (resistance·length, in the length unit of ``k/E*``).
    """
    check_finite_positive("e_star", e_star)
    rho = np.asarray(resistivities, dtype=float)
    if rho.shape != (2,) or not np.all(np.isfinite(rho)) or np.any(rho < 0) or rho.sum() <= 0:
        raise ValueError(f"resistivities must be two finite non-negative numbers, not both 0; got {resistivities!r}")
    return 2.0 * np.asarray(stiffness, dtype=float) / (e_star * rho.sum())


def thermal_conductance(stiffness, *, e_star: float, conductivities) -> np.ndarray:
    """``C_th = 2k/(E*(1/K₁ + 1/K₂))`` (module docstring); *conductivities*: ``(K₁, K₂)``, each
    positive (power/(length·temperature), in the length unit of ``k/E*``)."""
    k = np.asarray(conductivities, dtype=float)
    if k.shape != (2,) or not np.all(np.isfinite(k)) or np.any(k <= 0):
        raise ValueError(f"conductivities must be two finite positive numbers; got {conductivities!r}")
    return electrical_conductance(stiffness, e_star=e_star, resistivities=1.0 / k)
