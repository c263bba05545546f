"""The companion studies of a study's grid error, as resolved configurations: the same sphere runs
and surfaces on a coarser grid (``grid.coarse``, :func:`coarse_config`) and their small loads on a
finer one (``grid.fine``, :func:`fine_config`). Both press the normal problem only (the tangential
axes at their paper setting); :mod:`roughcontact.study.analysis.grid_error` and
:mod:`roughcontact.study.analysis.fine_reference` compare them with the study."""
from __future__ import annotations

import math

from . import axes
from .records import force_grid

__all__ = ["MIN_COARSE", "coarse_config", "default_coarse", "fine_config"]

#: the smallest grid the schema accepts for ``grid.coarse`` (and every grid)
MIN_COARSE = 17


def default_coarse(n: int) -> int | None:
    """``grid.coarse`` where a configuration does not name it: ``(n + 1) // 2`` (a ratio of 2 in cell
    size, 193 for 385, 257 for 513), or ``None`` (no grid error) when that is below
    :data:`MIN_COARSE`. An explicit ``grid.coarse: null`` turns the companion off."""
    coarse = (int(n) + 1) // 2
    return coarse if coarse >= MIN_COARSE else None


def coarse_config(cfg) -> dict:
    """The resolved configuration of the companion study of the grid error of *cfg* (resolved,
    with ``grid.coarse``): ``grid.n`` = the coarse grid, ``grid.realization_of`` = the grid whose
    surfaces *cfg* presses, ``radius`` the finite radii only (the grid error is the spheres'; no
    flat run is pressed twice), the tangential axes at their paper setting, no opt-in quantity or
    histogram, everything else as in *cfg*. ``ValueError`` without
    ``grid.coarse`` or without a sphere."""
    grid = dict(cfg["grid"])
    grid.pop("fine", None), grid.pop("fine_to", None)   # the companions press on the study's grid only
    coarse = grid.pop("coarse", None)
    if coarse is None:
        raise ValueError("the study has no grid.coarse: there is no coarse companion study")
    spheres = [r for r in cfg.get("radius", []) if math.isfinite(r)]
    if not spheres:
        raise ValueError("the study has no sphere radius: its companion on grid.coarse would have no run")
    fine = grid["n"] if grid.get("realization_of") is None else grid["realization_of"]
    # the grid error is the normal stiffness's: the tangential axes at their paper setting
    tangential = {a.name: [a.paper] for a in axes.optional_axes(normal=False) if a.name in cfg}
    return {**cfg, **tangential, "radius": spheres,
            "grid": {**grid, "n": int(coarse), "coarse": None, "realization_of": int(fine)},
            "fields": _without_outputs(cfg)}


def _without_outputs(cfg, **fields) -> dict:
    """The ``fields`` of a companion of *cfg*: the study's, without the opt-in quantities and the
    histograms (outputs of the study's own runs, which the grid error does not read: adding one
    reruns no companion), with *fields* on top."""
    section = dict(cfg.get("fields") or {})
    histograms = {**(section.get("histograms") or {}), "at": []}
    return {**section, "quantities": [], "histograms": histograms, **fields}


def fine_config(cfg) -> dict:
    """The resolved configuration of the fine reference of *cfg* (resolved, with ``grid.fine``): the
    sphere runs on ``grid.n`` = ``grid.fine`` with the same surfaces (``grid.realization_of`` where
    it is finer still, else the fine grid's own), at the loads of the sphere load path up to
    ``grid.fine_to`` (the same loads: a log grid cut short), counting their contact patches (the
    single-asperity regime, :mod:`roughcontact.study.analysis.fine_reference`), without contact
    fields, opt-in quantities, histograms, grid-error companions or the tangential axes.
    ``ValueError`` without ``grid.fine``."""
    import numpy as np

    grid = dict(cfg["grid"])
    fine, to = grid.pop("fine", None), grid.pop("fine_to", None)
    if fine is None:
        raise ValueError("the study has no grid.fine: there is no fine reference")
    rng = dict(cfg["forces"]["sphere"])
    path = force_grid(rng["from"], rng["to"], rng["count"])
    last = max(1, int(np.searchsorted(path, to * (1 + 1e-12), side="right")) - 1)
    source = grid.get("realization_of")
    tangential = {a.name: [a.paper] for a in axes.optional_axes(normal=False) if a.name in cfg}
    return {**cfg, **tangential, "radius": [r for r in cfg["radius"] if math.isfinite(r)],
            "grid": {**grid, "n": int(fine), "coarse": None, "realization_of": source if source and source > fine else None},
            "forces": {"sphere": {**rng, "to": float(path[last]), "count": last + 1}},
            "fields": _without_outputs(cfg, patches=True, at=[])}
