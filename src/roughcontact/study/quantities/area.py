"""Opt-in areas of a run kind (``fields.quantities``): the relative contact area ``A/L²`` of the
nominally flat runs, the fraction of the periodic cell in contact (the quantity of a flat rough
contact, e.g. Persson's theory of the area). A sphere's contact has no nominal area on the grid,
so its runs do not keep it, and a sweep without a flat run is refused at the configuration check
(:attr:`roughcontact.study.quantities.Quantity.needs`)."""
from __future__ import annotations

import math

import numpy as np

from . import OPT_IN, Quantity, opted_in, register


def _flat_opted_in(settings) -> bool:
    return bool(getattr(settings, "periodic", False)) and opted_in("relative_contact_area")(settings)


def _needs_a_flat_run(cfg) -> str | None:
    radii = cfg.get("radius") or ()
    return None if any(not math.isfinite(r) for r in radii) else "a flat run (radius .inf: a nominal area L^2)"


register(Quantity("relative_contact_area", "f8", "relative contact area A/L^2 of the periodic cell", "1",
                  compute=lambda state, load: float(np.count_nonzero(state.contact)) / state.contact.size,
                  records=_flat_opted_in, option=OPT_IN, family="area", needs=_needs_a_flat_run))
