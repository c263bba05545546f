"""The quantities every force-controlled run keeps at each load: the depth, the incremental normal
stiffness ``k = dF/dd``, the contact area and cells, and the solver's iterations and convergence."""
from __future__ import annotations

import numpy as np

from ...errors import ConvergenceError, IndentError
from . import Quantity, register


def stiffness(state, load) -> float:
    """``dF/dd`` of *state* by the run's method (:func:`roughcontact.bem.stiffness`): the exact
    unloading tangent (``punch``) or a difference quotient; a failure or a value that is not
    positive (e.g. a periodic surface pressed into full contact) is an
    :class:`~roughcontact.errors.IndentError` naming the load and what to change."""
    from ... import bem  # the solver, imported by the indent job only

    p = load.settings
    try:
        k = bem.stiffness(state, method=p.stiffness_method, rel_step=p.rel_step)
    except (ConvergenceError, ValueError) as exc:
        other = "punch" if p.stiffness_method == "difference" else "difference"
        raise IndentError(
            f"indent {p.name}: the stiffness ({p.stiffness_method}) failed at {load.where}): {exc}; try "
            f"solver.stiffness = {other} or more cells (grid.n)"
        ) from exc
    if not (np.isfinite(k) and k > 0):
        cells = int(np.count_nonzero(state.contact))
        raise IndentError(
            f"indent {p.name}: non-positive stiffness k = {k!r} at {load.where}, {cells} of {state.contact.size} "
            f"cells in contact); lower {p.force_key} or raise the smallest force or grid.n"
        )
    return k


register(Quantity("depth", "f8", "indentation depth from first touch", "length",
                  compute=lambda state, load: state.depth, family="normal"))
register(Quantity("stiffness", "f8", "normal contact stiffness dF/dd", "e_star * length", compute=stiffness,
                  family="normal"))
register(Quantity("contact_area", "f8", "contact area (contact cells * (L/n)^2)", "length**2",
                  compute=lambda state, load: int(np.count_nonzero(state.contact)) * load.cell, family="normal"))
register(Quantity("contact_cells", "i8", "number of grid cells in contact", "1",
                  compute=lambda state, load: int(np.count_nonzero(state.contact)), family="normal"))
register(Quantity("iterations", "i8", "solver iterations (warm-started from the previous load)", "1",
                  compute=lambda state, load: state.iterations, family="normal"))
register(Quantity("converged", "i1", "solver converged (1) or not (0)", "1",
                  compute=lambda state, load: int(bool(state.converged)), family="normal"))
