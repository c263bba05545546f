"""Opt-in quantities of the gap and the pressure (``fields.quantities``): the mean gap over the grid
and over its non-contacting cells, and the mean pressure on the contact (the outputs a
tribologist reads beside the stiffness: sealing, the leak's channels, the load each contact spot
carries). The gap needs one convolution over the whole grid per load
(:meth:`roughcontact.bem.ContactState.gap`), counted once for both gap quantities."""
from __future__ import annotations

import numpy as np

from . import OPT_IN, Quantity, opted_in, register


def gap_field(state, load) -> np.ndarray:
    """The gap of *state* on the whole grid (length; :meth:`roughcontact.bem.ContactState.gap`),
    computed once per load for every quantity and histogram that needs it."""
    if __name__ not in load.cache:
        load.cache[__name__] = state.gap()
    return load.cache[__name__]


def mean_gap(state, load) -> float:
    """The gap ``g = (z − min z) − d + u`` averaged over every cell of the grid (0 in contact)."""
    return float(np.mean(gap_field(state, load)))


def mean_free_gap(state, load) -> float:
    """The gap averaged over the cells out of contact (``nan`` in full contact)."""
    free = ~state.contact
    return float(np.mean(gap_field(state, load)[free])) if free.any() else float("nan")


def mean_contact_pressure(state, load) -> float:
    """``F/A``: the force over the real contact area (``nan`` without contact)."""
    cells = int(np.count_nonzero(state.contact))
    return float(state.force / (cells * load.cell)) if cells else float("nan")


register(Quantity("mean_gap", "f8", "mean gap between the indenter and the deformed half-space over the grid "
                  "(0 in contact)", "length", compute=mean_gap, records=opted_in("mean_gap"), option=OPT_IN,
                  family="gap"))
register(Quantity("mean_free_gap", "f8", "mean gap over the cells out of contact", "length",
                  compute=mean_free_gap, records=opted_in("mean_free_gap"), option=OPT_IN, family="gap"))
register(Quantity("mean_contact_pressure", "f8", "mean pressure on the contact F/A (force over real contact area)",
                  "e_star", compute=mean_contact_pressure, records=opted_in("mean_contact_pressure"),
                  option=OPT_IN, family="gap"))
