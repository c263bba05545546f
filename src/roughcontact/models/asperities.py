"""Greenwood–Williamson summit statistics from the spectral moments of a surface.

Summit statistics from the spectral moments ``m0, m2, m4`` of an isotropic
Gaussian surface (profile moments: ``m0`` the height variance, ``m2`` the
mean-square slope and ``m4`` the mean-square curvature of a profile) follow
Nayak, J. Lubr. Technol. 93, 398 (1971), in the closed forms of McCool,
Wear 107, 37 (1986):

* summit density ``η = m4 / (6π√3 m2)``,
* mean summit radius ``β = (3/8) √(π/m4)``,
* standard deviation of the summit heights ``σ_s = √(1 − 0.8968/α) √m0``,
  with the bandwidth parameter ``α = m0 m4 / m2²`` (``α ≥ 1.5``),
* mean summit height ``4 √m0 / √(π α)`` above the mean plane.

They feed Greenwood & Tripp's ``μ = (8/3) η σ √(2Bβ)``
(:mod:`roughcontact.models.greenwood_tripp`).
"""

from __future__ import annotations

import dataclasses
import math

from .._validate import check_finite_positive
from ..surfaces.moments import SpectralMoments

__all__ = ["AsperityParameters", "asperity_parameters", "mu_parameter"]


@dataclasses.dataclass(frozen=True)
class AsperityParameters:
    """Greenwood–Williamson summit statistics of an isotropic Gaussian surface (McCool 1986).

    Attributes
    ----------
    density : float
        Summit density ``η = m4/(6π√3 m2)`` (1/length²).
    summit_radius : float
        Mean summit radius of curvature ``β = (3/8)√(π/m4)`` (length).
    summit_sigma : float
        Standard deviation of the summit heights ``σ_s = √(1 − 0.8968/α) √m0``
        (length): GT's ``σ``.
    summit_mean_height : float
        Mean summit height above the mean plane, ``4√m0/√(πα)`` (length).
    bandwidth : float
        Nayak's bandwidth parameter ``α = m0 m4/m2²`` (≥ 1.5).
    """

    density: float
    summit_radius: float
    summit_sigma: float
    summit_mean_height: float
    bandwidth: float


def asperity_parameters(moments: SpectralMoments) -> AsperityParameters:
    """Summit density, radius and height spread from the spectral moments (module docstring)."""
    for name in ("m0", "m2", "m4"):
        check_finite_positive(name, getattr(moments, name))
    m0, m2, m4 = moments.m0, moments.m2, moments.m4
    bandwidth = m0 * m4 / m2**2
    if bandwidth < 1.5 * (1 - 1e-12):
        raise ValueError(f"bandwidth m0 m4/m2^2 = {bandwidth:g} < 1.5: not the moments of "
                         f"an isotropic surface")
    return AsperityParameters(
        density=m4 / (6.0 * math.pi * math.sqrt(3.0) * m2),
        summit_radius=0.375 * math.sqrt(math.pi / m4),
        summit_sigma=math.sqrt(1.0 - 0.8968 / bandwidth) * math.sqrt(m0),
        summit_mean_height=4.0 * math.sqrt(m0) / math.sqrt(math.pi * bandwidth),
        bandwidth=bandwidth)


def mu_parameter(asperities: AsperityParameters, *, radius: float) -> float:
    """GT's ``μ = (8/3) η σ √(2Bβ)`` for a sphere of radius ``B = radius``."""
    check_finite_positive("radius", radius)
    return (8.0 / 3.0 * asperities.density * asperities.summit_sigma
            * math.sqrt(2.0 * radius * asperities.summit_radius))
