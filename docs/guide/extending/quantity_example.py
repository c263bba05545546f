# module: roughcontact.study.quantities.peak_pressure
"""Worked example: a per-load quantity, the peak pressure of each load.

Copy this file to ``src/roughcontact/study/quantities/peak_pressure.py`` (its first line says so)
and nothing else: ``roughcontact list quantities`` names it, the configuration accepts
``fields: {quantities: [peak_pressure]}``, every run of such a study keeps it at each load (its run
file, ``stiffness.nc`` and the ensemble) in units of ``E*``, and a study that does not name it keeps
every run's name, settings and file.
"""
from __future__ import annotations

import numpy as np

from roughcontact.study.quantities import OPT_IN, Quantity, opted_in, register


def peak_pressure(state, load) -> float:
    """The largest cell pressure of the solved *state* (pressure unit, ``E*``); *load* (a
    :class:`roughcontact.study.quantities.Load`) is not needed here."""
    return float(np.max(state.pressure))


register(Quantity("peak_pressure", "f8", "largest contact pressure of the load", "e_star", compute=peak_pressure,
                  records=opted_in("peak_pressure"), option=OPT_IN, family="peak_pressure"))
