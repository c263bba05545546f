"""The tangential path kind: what a load of a sphere run adds with the tangential axes given.

Called by the force-controlled load path of :mod:`roughcontact.study.runs.indent` for each solved
normal state (the normal–tangential coupling neglected, :mod:`roughcontact.bem.cerruti`: the normal
path is the one without them):

* with ``poisson`` (``ν``): the full-stick tangential stiffness ``k_t`` of every load
  (:func:`roughcontact.bem.tangential_stiffness`; Mindlin: ``k_t/k_n = 2(1 − ν)/(2 − ν)``);
* with ``friction > 0`` (``μ``), at the loads ``slip_loads``: the Cattaneo–Mindlin partial-slip
  path ``Q/(μP) = 1/(steps+1) … steps/(steps+1)`` at fixed normal load
  (:func:`roughcontact.bem.partial_slip`, two traction components, warm-started): ``Q``, ``δ_x``, ``k_t(Q)`` and the
  stick cells of every tangential load, and the largest micro-slip ``δ_max`` at ``Q → μP``
  (:func:`roughcontact.bem.micro_slip.gross_slip_displacement`).

The run-file variables are :data:`roughcontact.study.files.runfile.TANGENTIAL_VARIABLES` and
:data:`~roughcontact.study.files.runfile.SLIP_VARIABLES`.
"""
from __future__ import annotations

import numpy as np

from ... import bem
from ...bem.micro_slip import gross_slip_displacement
from ...errors import ConvergenceError, IndentError
from ..files import runfile
from .jobs import SLIP_COMPONENTS

__all__ = ["allocate", "record"]


def allocate(out: dict, p, total: int) -> None:
    """Add the tangential arrays of a path of *total* loads with the settings *p*
    (:class:`~roughcontact.study.runs.indent.PathSettings`) to *out*."""
    if p.poisson is None:
        return
    out["tangential_stiffness"] = np.zeros(total, dtype=runfile.TANGENTIAL_VARIABLES["tangential_stiffness"].dtype)
    if p.friction > 0:
        shape = {(): (len(p.slip_loads),), ("slip_step",): (len(p.slip_loads), p.slip_steps)}
        for name, meta in runfile.SLIP_VARIABLES.items():
            out[name] = np.zeros(shape[meta.dims[1:]], dtype=meta.dtype)
        out["slip_load"] = np.asarray(p.slip_loads, dtype="i8")
        out["slip_step"] = runfile.slip_fractions(p.slip_steps)


def record(p, out: dict, i: int, state, where: str) -> None:
    """The tangential numbers of load *i* (state *state*, described by *where* in messages)."""
    if p.poisson is None:
        return
    try:
        k_t = bem.tangential_stiffness(state, poisson=p.poisson)
    except (ConvergenceError, ValueError) as exc:
        raise IndentError(f"indent {p.name}: the tangential stiffness failed at {where}): {exc}; use more cells "
                          f"(grid.n) or another poisson") from exc
    out["tangential_stiffness"][i] = k_t
    if p.friction <= 0 or i not in p.slip_loads:
        return
    j = p.slip_loads.index(i)
    try:
        path = bem.partial_slip(state, out["slip_step"], friction=p.friction, poisson=p.poisson, maxiter=p.maxiter,
                                components=SLIP_COMPONENTS)
    except (ConvergenceError, ValueError) as exc:
        raise IndentError(f"indent {p.name}: the partial-slip path failed at {where}): {exc}; raise solver.maxiter, "
                          "lower tangential.steps or leave this load out of tangential.at") from exc
    out["slip_force"][j] = path.forces
    out["slip_displacement"][j] = path.displacements
    out["slip_stiffness"][j] = path.stiffnesses
    out["stick_cells"][j] = [int(np.count_nonzero(s.stick)) for s in path.states]
    out["slip_iterations"][j] = [s.iterations for s in path.states]
    out["gross_slip_displacement"][j] = gross_slip_displacement(state, friction=p.friction, poisson=p.poisson)
    out["slip_normal_force"][j] = state.force
    out["slip_depth"][j] = state.depth
