"""Reading and writing the study's files: run files, NetCDF groups, CSV tables.

Every write is atomic (a temporary file, then a rename: :func:`roughcontact.study.provenance.atomic_path`),
so a failed job leaves no half-written output. Imports xarray where used (the ``pipeline``
extra). The run file's data model is :mod:`roughcontact.study.runfile`.
"""
from __future__ import annotations

import os

import numpy as np

from ..errors import MergeError
from . import provenance, runfile
from .settings import JobSettings

__all__ = ["read_run", "write_groups", "read_groups", "write_netcdf", "write_csv"]


def write_netcdf(ds, path) -> None:
    """Atomic NetCDF4 write (temp file, then rename)."""
    with provenance.atomic_path(path) as tmp:
        ds.to_netcdf(tmp, engine="netcdf4")


def write_csv(df, path) -> None:
    """Atomic CSV write of a DataFrame (no index)."""
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
    adhesive = expected.work_of_adhesion > 0 if expected is not None else "retract" in ds.dims
    dims = ["force", "retract"] if adhesive else ["force"]   # an adhesive run has its retract path too
    if sorted(ds.dims) != sorted(dims):
        raise MergeError(f"{path}: foreign NetCDF file (dimensions {dict(ds.sizes)}, expected {', '.join(dims)}); "
                         f"{hint}")
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


