"""Merge the run files of a study and their ensemble statistics over seeds.

Imports xarray and pandas (the ``pipeline`` extra); ``import roughcontact``
does not import this module.

All forces in the tables are normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import logging
import math
import os

import numpy as np

from ..errors import MergeError
from . import provenance, runfile, runs
from .settings import JobSettings, job_settings

__all__ = ["read_run", "merge_runs", "ensemble", "write_groups", "read_groups", "write_netcdf", "write_csv",
           "run_merge"]


log = logging.getLogger(__name__)


# --------------------------------------------------------------------------
# I/O
# --------------------------------------------------------------------------
def write_netcdf(ds, path) -> None:
    """Atomic NetCDF4 write (temp file, then rename)."""
    with provenance.atomic_path(path) as tmp:
        ds.to_netcdf(tmp, engine="netcdf4")


def write_csv(df, path) -> None:
    with provenance.atomic_path(path) as tmp:
        df.to_csv(tmp, index=False)  # shortest round-trip repr: values read back are the values written


def read_run(path, expected: JobSettings | None = None):
    """Open one run file, check it and return it loaded in memory.

    Raises :class:`~roughcontact.errors.MergeError` naming *path* for a truncated, foreign or
    stale file.  *expected* (the job settings of the current config) enables the stale check.
    """
    import xarray as xr

    path = str(path)
    hint = f"delete {path} and rerun snakemake to recompute it"
    if not os.path.exists(path):
        raise MergeError(f"{path}: run file is missing; rerun snakemake to compute it")
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except Exception as exc:
        raise MergeError(f"{path}: not a readable NetCDF file ({type(exc).__name__}: {exc}); "
                         f"it may be truncated; {hint}") from exc
    missing = [v for v in (*runfile.RUN_VARIABLES, "force", *runfile.SCALARS) if v not in ds.variables]
    if missing or ds.attrs.get("title") != runfile.TITLE:
        what = f"lacks {', '.join(missing)}" if missing else "is not a roughcontact indentation run"
        raise MergeError(f"{path}: foreign NetCDF file ({what}); {hint}")
    if list(ds.dims) != ["force"]:
        raise MergeError(f"{path}: foreign NetCDF file (dimensions {dict(ds.sizes)}, expected only 'force'); {hint}")
    if expected is not None:
        for key in runfile.SCALARS:
            got, want = float(ds[key]), float(getattr(expected, key))
            if not (got == want):
                raise MergeError(f"{path}: holds {key} = {got:g}, expected {want:g} from its name; {hint}")
        want = provenance.config_hash(expected.record())
        if ds.attrs.get("config_hash") != want:
            raise MergeError(f"{path}: was computed with other settings (config_hash {ds.attrs.get('config_hash')} "
                             f"!= {want} of the current config); {hint} or run snakemake with --rerun-triggers params")
        forces = expected.forces()
        if ds.sizes["force"] != len(forces) or not np.allclose(ds["force"].values, forces, rtol=1e-12, atol=0):
            raise MergeError(f"{path}: its force grid differs from the current config; {hint}")
    return ds


# --------------------------------------------------------------------------
# merge and ensemble: one group per surface kind
# --------------------------------------------------------------------------
def _force_coords(cfg: dict, kind: str) -> dict:
    L, E = cfg["grid"]["length"], cfg["e_star"]
    rng = cfg["forces"][kind]
    force = runs.force_grid(rng["from"], rng["to"], rng["count"]) * E * L**2
    return {
        "force": ("force", force, runfile.FORCE_ATTRS),
        "force_normalized": ("force", force / (E * L**2), {"long_name": "F/(E* L^2)", "units": "1"}),
    }


def merge_runs(cfg: dict, paths) -> dict:
    """Merge the run files *paths* (one per run of :func:`runs.runs`, in its order) of the
    resolved config *cfg*, one Dataset per surface kind.

    Returns ``{"sphere": ds, "flat": ds}`` (the kinds the sweep has): the sphere
    Dataset has dims (hurst, radius, h_rms, seed, force), the flat one (hurst,
    h_rms, seed, force) (:data:`runs.AXES`); each kind has its own force grid,
    so no variable is padded, and counts are integers.
    """
    import xarray as xr

    table = runs.runs(cfg)
    if len(paths) != len(table):
        raise MergeError(f"merge got {len(paths)} run files for {len(table)} runs of the config")
    groups = {}
    for kind in ("sphere", "flat"):
        rows = [(row, path) for row, path in zip(table, paths) if row["kind"] == kind]
        if not rows:
            continue
        axes = runs.AXES[kind]
        L = cfg["grid"]["length"]
        at = {id(row): {axis: runs.coordinate(axis, row[axis], L) for axis in axes} for row, _ in rows}
        coords = {axis: sorted({at[id(row)][axis] for row, _ in rows}) for axis in axes}
        coords["seed"] = list(cfg["seeds"])
        count = cfg["forces"][kind]["count"]
        shape = tuple(len(v) for v in coords.values()) + (count,)
        plastic = any(row["hardness"] is not None for row, _ in rows)
        names = runfile.RUN_VARIABLES + (runfile.PLASTIC_VARIABLES if plastic else ())
        data = {name: np.zeros(shape, dtype=runfile.VARIABLES[name].dtype) for name in names}
        attrs_of, commits = {}, set()
        for row, path in rows:
            ds = read_run(path, job_settings(cfg, row))
            idx = tuple(coords[axis].index(at[id(row)][axis]) for axis in axes) + (coords["seed"].index(row["seed"]),)
            for name in names:
                # an elastic run's loading tangent is its stiffness, and nothing flows
                values = ds[name] if name in ds else (ds["stiffness"] if name == "loading_stiffness" else 0)
                data[name][idx] = getattr(values, "values", values)
                if name in ds:
                    attrs_of.setdefault(name, {k: v for k, v in ds[name].attrs.items() if k != "coordinates"})
            commits.add(ds.attrs.get("git_commit", "unknown"))
        dims = (*axes, "seed", "force")
        ds = xr.Dataset(
            {name: (dims, data[name], attrs_of.get(name, {})) for name in names},
            coords={**{axis: (axis, coords[axis], runfile.AXIS_ATTRS[axis]) for axis in (*axes, "seed")},
                    **_force_coords(cfg, kind)},
            attrs={"surface_kind": kind, "half_space": "periodic" if kind == "flat" else "free (non-periodic)",
                   "run_git_commits": provenance.canonical_json(sorted(commits))},
        )
        groups[kind] = ds
    return groups


def ensemble(ds):
    """Mean, standard deviation and standard error of k over seeds (and means
    of depth, contact area and contact cells) of one kind's Dataset."""
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
    import xarray as xr

    return xr.Dataset({name: value.assign_attrs(attrs) for name, (value, attrs) in per_load.items()},
                      attrs={**ds.attrs, "n_seeds": n_seeds})


def write_groups(path, groups: dict, attrs: dict) -> None:
    """Write ``{kind: Dataset}`` as the groups of one NetCDF4 file (atomic);
    *attrs* become the root group's attributes (provenance)."""
    import xarray as xr

    tree = xr.DataTree.from_dict({"/": xr.Dataset(attrs=attrs), **groups})
    with provenance.atomic_path(path) as tmp:
        tree.to_netcdf(tmp, engine="netcdf4")


def read_groups(path) -> dict:
    """``{kind: Dataset}`` of a file written by :func:`write_groups`, loaded in memory."""
    import xarray as xr

    with xr.open_datatree(path, engine="netcdf4") as tree:
        return {name: node.to_dataset().load() for name, node in tree.children.items()}


# --------------------------------------------------------------------------
# entry points used by workflow/scripts
# --------------------------------------------------------------------------
def run_merge(cfg, run_files, out_stiffness, out_ensemble):
    """``merge`` rule: run files -> stiffness.nc and ensemble.nc (one group per kind)."""
    groups = merge_runs(cfg, list(run_files))
    attrs = provenance.provenance_attrs(
        config=cfg, title="roughcontact parameter study: all runs", layout="one group per surface kind (sphere, flat)",
        grid_n=cfg["grid"]["n"], grid_length=cfg["grid"]["length"], e_star=cfg["e_star"],
        solver_tol=cfg["solver"]["tol"], stiffness_method=cfg["solver"]["stiffness"], seeds=cfg["seeds"])
    write_groups(out_stiffness, groups, attrs)
    attrs["title"] = "roughcontact parameter study: ensemble statistics over seeds"
    write_groups(out_ensemble, {kind: ensemble(ds) for kind, ds in groups.items()}, attrs)
    log.info("merged %d runs (%s) into %s and %s", len(run_files), ", ".join(groups), out_stiffness, out_ensemble)
