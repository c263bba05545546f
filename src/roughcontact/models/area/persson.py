"""Persson's real contact area under the sphere's nominal (Hertz) pressure (:func:`.laws.persson_area`)."""
from __future__ import annotations

from . import AreaModel, register, rms_slope
from .laws import persson_area


def persson(force, s):
    """``π a² ∫₀¹ erf(β √u) du``, ``β = √2 p0/(E* h′_rms)``, with the grid spectrum's ``h′_rms``;
    paraboloids only (Hertz's nominal pressure)."""
    if s.exponent != 2.0 or s.flat:
        return None
    return persson_area(force, radius=s.radius, e_star=s.e_star, rms_slope=rms_slope(s))


register(AreaModel("persson_area", "persson_area: Persson's A/A0 = erf(sqrt(2) p/(E* h'_rms)) under Hertz's nominal "
                                   "pressure, integrated over Hertz's contact (kappa = sqrt(8/pi) at small load)",
                   persson, "doi:10.1063/1.1388626; doi:10.1016/j.surfrep.2006.04.001"))
