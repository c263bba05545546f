"""ζ(H), the prefactor of eq. 11, as a law over 0 < H < 2: the candidate forms and the law
calibrated on the flat-surface presets.

Eq. 13 gives ζ ≈ 1.7/(H+1) for H ≤ 1. :data:`LAWS` are the forms the study chooses from by
AIC (:mod:`roughcontact.study.zeta_law`, claim c′ of the claims table); :data:`CALIBRATED`
is the law that study chose on ``presets/zeta-law.yaml`` and the value :func:`zeta_law`
returns, so that eq. 16 can use it (the scorecard's ``eq16_law``).
"""
from __future__ import annotations

import numpy as np

__all__ = ["LAWS", "CALIBRATED", "zeta_law"]

#: candidate forms: name -> (function of (H, *parameters), parameter names, start values of a fit);
#: "a/(H+1)" is eq. 13's form (a = 1.7 in the paper)
LAWS = {
    "a/(H+1)": (lambda h, a: a / (h + 1.0), ("a",), (1.7,)),
    "a/(H+b)": (lambda h, a, b: a / (h + b), ("a", "b"), (1.7, 1.0)),
    "a*(H+1)^-b": (lambda h, a, b: a * (h + 1.0) ** -b, ("a", "b"), (1.7, 1.0)),
    "a*exp(-b*H)": (lambda h, a, b: a * np.exp(-b * h), ("a", "b"), (1.7, 0.5)),
    "a+b*H": (lambda h, a, b: a + b * h, ("a", "b"), (1.7, -0.5)),
    "a/(H+1)+b/H": (lambda h, a, b: a / (h + 1.0) + b / h, ("a", "b"), (1.7, 0.1)),
}


def zeta_law(hurst):
    """ζ(H) of the law :data:`CALIBRATED` (eq. 11's prefactor for flat surfaces)."""
    function = LAWS[CALIBRATED["form"]][0]
    return function(np.asarray(hurst, dtype=float), *CALIBRATED["parameters"].values())
