"""The quantities of a run with a penetration hardness (axis ``hardness``): the loading tangent along
the plastic path and the cells that flowed. An elastic run has neither (its loading stiffness is its
stiffness, and no cell flows)."""
from __future__ import annotations

import numpy as np

from ...errors import ConvergenceError, IndentError
from . import Quantity, register


def _plastic(settings) -> bool:
    return getattr(settings, "hardness", None) is not None


def loading_stiffness(state, load) -> float:
    """The loading tangent ``dF/dd`` along the plastic path (:func:`roughcontact.bem.stiffness`,
    ``method="loading"``, a forward quotient of ``solver.rel_step``); an
    :class:`~roughcontact.errors.IndentError` where it fails or is not positive."""
    from ... import bem  # the solver, imported by the indent job only

    p = load.settings
    try:
        loading = bem.stiffness(state, method="loading", rel_step=p.rel_step)
    except (ConvergenceError, ValueError) as exc:
        raise IndentError(
            f"indent {p.name}: the loading stiffness failed at {load.where}): {exc}; use more cells (grid.n) "
            f"or a smaller load ({p.force_key})"
        ) from exc
    if not (np.isfinite(loading) and loading > 0):
        raise IndentError(
            f"indent {p.name}: non-positive loading stiffness {loading!r} at {load.where}); raise the smallest "
            "force or grid.n"
        )
    return loading


register(Quantity("loading_stiffness", "f8", "loading tangent dF/dd along the plastic path (forward quotient, "
                  "solver.rel_step); stiffness is the unloading one", "e_star * length", compute=loading_stiffness,
                  records=_plastic, option="hardness", family="plastic"))
register(Quantity("plastic_cells", "i8", "number of grid cells that flowed (pressure at the hardness)", "1",
                  compute=lambda state, load: int(np.count_nonzero(state.plastic)), records=_plastic,
                  option="hardness", family="plastic"))
