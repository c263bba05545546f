"""The contact conductance of a study's loads from their stiffness (config section ``conductance``):
Barber's ``C = 2k/(E*(ρ₁ + ρ₂))`` and its thermal twin (:mod:`roughcontact.models.conductance`), in
S and W/K, as variables of the merged files beside the stiffness they come from."""
from __future__ import annotations

from ...models.conductance import electrical_conductance, thermal_conductance
from ..config.settings import ConductanceSettings

__all__ = ["conductance_variables"]


def conductance_variables(stiffness, *, metres_per_unit: float, settings: ConductanceSettings) -> dict:
    """``{name: DataArray}`` of the conductances of *stiffness* (a DataArray of ``k/E*`` in a length
    unit, e.g. the generated study's ``k/(E* L)·L``), *metres_per_unit* metres per that unit; empty
    where *settings* gives neither resistivities nor conductivities."""
    k_over_e = stiffness * metres_per_unit   # k/E* in m: E* = 1 in its own unit
    out = {}
    if settings.resistivity is not None:
        out["electrical_conductance"] = k_over_e.copy(data=electrical_conductance(
            k_over_e.values, e_star=1.0, resistivities=settings.resistivity)).assign_attrs(
            long_name=f"electrical contact conductance 2k/(E*(rho1 + rho2)), rho = {list(settings.resistivity)} "
                      "ohm m (Barber 2003)", units="S")
    if settings.conductivity is not None:
        out["thermal_conductance"] = k_over_e.copy(data=thermal_conductance(
            k_over_e.values, e_star=1.0, conductivities=settings.conductivity)).assign_attrs(
            long_name=f"thermal contact conductance 2k/(E*(1/K1 + 1/K2)), K = {list(settings.conductivity)} "
                      "W/(m K) (Barber 2003)", units="W K-1")
    return out
