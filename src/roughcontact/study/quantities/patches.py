"""The contact patches of each load (``fields.patches``): how many edge-connected clusters of contact
cells there are, and the cells of the largest (:func:`roughcontact.bem.contact_patches`); opt-in
(``fields.quantities``), the area of the largest, counted once with them where both are kept."""
from __future__ import annotations

from . import OPT_IN, Quantity, opted_in, register


def _counted(settings) -> bool:
    return bool(getattr(settings, "patches", False))


def _patches(state, load):
    """The patches of *state*, counted once per load for both quantities."""
    from ... import bem  # the solver, imported by the indent job only

    if __name__ not in load.cache:
        load.cache[__name__] = bem.contact_patches(state.contact, periodic=load.settings.periodic)
    return load.cache[__name__]


register(Quantity("contact_patches", "i8", "number of contact patches (edge-connected clusters of contact cells)",
                  "1", compute=lambda state, load: _patches(state, load).count, records=_counted,
                  option="fields.patches", family="patches"))
register(Quantity("largest_patch_cells", "i8", "number of grid cells of the largest contact patch", "1",
                  compute=lambda state, load: _patches(state, load).largest, records=_counted,
                  option="fields.patches", family="patches"))
register(Quantity("largest_patch_area", "f8", "area of the largest contact patch (its cells * (L/n)^2)", "length**2",
                  compute=lambda state, load: _patches(state, load).largest * load.cell,
                  records=opted_in("largest_patch_area"), option=OPT_IN, family="patches"))
