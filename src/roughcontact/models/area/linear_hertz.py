"""The linear law with κ = 2 joined to Hertz (:func:`.laws.joined_area`)."""
from __future__ import annotations

from . import AreaModel, register, rms_slope
from .laws import SIMULATION_KAPPA, joined_area


def linear_hertz(force, s):
    """``min(κ F/(E* h′_rms), π a²)`` with κ = 2 and the grid spectrum's ``h′_rms``; paraboloids only."""
    if s.exponent != 2.0 or s.flat:
        return None
    return joined_area(force, radius=s.radius, e_star=s.e_star, rms_slope=rms_slope(s), kappa=SIMULATION_KAPPA)


register(AreaModel("linear_hertz", f"linear_hertz: A = {SIMULATION_KAPPA:g} F/(E* h'_rms) below the crossover, "
                                   "Hertz's pi a^2 above (the smaller of the two)", linear_hertz,
                   "doi:10.1103/PhysRevE.70.026117; doi:10.1063/1.4950802"))
