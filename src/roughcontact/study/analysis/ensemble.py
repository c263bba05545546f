"""Ensemble statistics over seeds, and the rule that says which loads are resolved.

Forces in the merged files are in force units (``force``) and normalised (``force_normalized``,
F/(E* L²)); stiffnesses in ``e_star * length``.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["ensemble", "resolved", "combinations"]


def resolved(contact_cells, min_cells: int):
    """Whether each load is resolved: its (ensemble-mean) number of contact cells is at least
    ``fit.resolved_cells`` (*min_cells*). The one rule every fit, verdict, figure and score
    applies before trusting a load; *contact_cells* an array or DataArray of mean cells."""
    return contact_cells >= min_cells


def combinations(ds, variable: str = "stiffness", inner: tuple = ("seed", "force")):
    """Every combination of the sweep axes of one kind's merged Dataset *ds*, in the order of its
    dimensions (C order: the last axis fastest, as ``crossover.csv``): ``(where, sub)``, *where*
    ``{axis: coordinate}`` (floats) and *sub* its slice with the dimensions *inner* first, in that
    order, whatever the number of combinations. The sweep axes are the dimensions of *variable*
    other than *inner* (the adhesive runs' pull-off: ``"pull_off_force"``, ``("seed",)``)."""
    import itertools

    dims = [d for d in ds[variable].dims if d not in inner]
    for position in itertools.product(*(range(ds.sizes[d]) for d in dims)):
        yield ({d: float(ds[d].values[i]) for d, i in zip(dims, position)},
               ds.isel(dict(zip(dims, position))).transpose(*inner, ...))


def ensemble(ds):
    """Mean, standard deviation and standard error of k over seeds (and means of depth, contact
    area and contact cells, and of every opt-in quantity the runs kept: ``<name>_mean``) of one
    kind's Dataset."""
    k = ds["stiffness"]
    n_seeds = ds.sizes["seed"]
    std = k.std("seed", ddof=1) if n_seeds > 1 else k.isel(seed=0) * np.nan
    per_load = {
        "k_mean": (k.mean("seed"), {"long_name": "ensemble mean stiffness", "units": "e_star * length"}),
        "k_std": (std, {"long_name": "standard deviation of k over seeds (ddof=1)", "units": "e_star * length"}),
        "k_sem": (std / math.sqrt(n_seeds), {"long_name": "standard error of the mean k", "units": "e_star * length"}),
        "depth_mean": (ds["depth"].mean("seed"), {"long_name": "mean indentation depth", "units": "length"}),
        "contact_area_mean": (ds["contact_area"].mean("seed"), {"long_name": "mean contact area", "units": "length**2"}),
        "contact_cells_mean": (ds["contact_cells"].mean("seed"), {"long_name": "mean contact cells", "units": "1"}),
    }
    if "loading_stiffness" in ds:
        per_load["loading_k_mean"] = (ds["loading_stiffness"].mean("seed"), {
            "long_name": "ensemble mean loading tangent along the plastic path", "units": "e_star * length"})
        per_load["plastic_cells_mean"] = (ds["plastic_cells"].mean("seed"), {"long_name": "mean plastic cells",
                                                                                "units": "1"})
    from .. import quantities

    for name in quantities.optional():   # the opt-in quantities the runs kept (fields.quantities)
        if name in ds:
            q = quantities.QUANTITIES[name]
            per_load[f"{name}_mean"] = (ds[name].mean("seed"), {"long_name": f"ensemble mean of the {q.long_name}",
                                                                 "units": q.units})
    import xarray as xr

    return xr.Dataset({name: value.assign_attrs(attrs) for name, (value, attrs) in per_load.items()},
                      attrs={**ds.attrs, "n_seeds": n_seeds})
