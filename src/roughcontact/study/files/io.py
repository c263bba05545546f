"""Reading and writing the study's files: run files, NetCDF groups, CSV tables.

Every write is atomic (a temporary file, then a rename: :func:`roughcontact.study.files.provenance.atomic_path`;
every NetCDF file through :func:`roughcontact.study.files.provenance.write_netcdf`), so a failed job
leaves no half-written output. Imports xarray where used (the ``pipeline``
extra). The run file's data model is :mod:`roughcontact.study.files.runfile`.
"""
from __future__ import annotations

import json
import os

import numpy as np

from ...errors import MergeError
from . import provenance, runfile
from .provenance import write_netcdf

__all__ = ["NO_ROW", "REASON", "empty_reason", "read_csv", "read_run", "reason_path", "read_groups", "write_csv",
           "write_groups", "write_netcdf"]


#: the column of an empty table's sidecar (:func:`reason_path`): why the table has no row
REASON = "reason"

#: why a table has no row when its writer gave no reason
NO_ROW = "no row to report"


def reason_path(path) -> str:
    """The sidecar of the table *path* that says why it has no row: ``results/crossover.csv`` ->
    ``results/crossover.reason.csv`` (a one-row CSV with the column :data:`REASON`; absent while
    the table has rows)."""
    root, _ = os.path.splitext(str(path))
    return f"{root}.reason.csv"


def write_csv(df, path, *, columns=(), reason: str | None = None) -> None:
    """Atomic CSV write of a DataFrame (no index), never a one-byte file.

    A table with rows is written as it is (and its reason sidecar, if any, removed). A table
    without a row is written as its header alone: the DataFrame's own columns, else *columns*
    (else the one column :data:`REASON`), so that ``pandas.read_csv`` gives an empty table with
    those columns; and why it is empty, *reason* (else :data:`NO_ROW`), is written to the sidecar
    :func:`reason_path` (one row, column :data:`REASON`), which :func:`read_csv` puts into the
    table's ``attrs["reason"]``: the landing page prints it as "not measured, because …".
    """
    import pandas as pd

    sidecar = reason_path(path)
    if len(df):
        with provenance.atomic_path(path) as tmp:
            df.to_csv(tmp, index=False)  # shortest round-trip repr: values read back are the values written
        if os.path.exists(sidecar):
            os.remove(sidecar)
        return
    header = list(df.columns) or list(columns) or [REASON]
    with provenance.atomic_path(path) as tmp:
        pd.DataFrame(columns=header).to_csv(tmp, index=False)
    with provenance.atomic_path(sidecar) as tmp:
        pd.DataFrame({REASON: [reason or NO_ROW]}).to_csv(tmp, index=False)


def read_csv(path, **kwargs):
    """A table written by :func:`write_csv` (or any CSV): an empty DataFrame for a missing, empty
    or one-byte file (an older study's empty table); where the table has no row, ``attrs["reason"]``
    holds why (:func:`reason_path`, or :data:`NO_ROW` without a sidecar). *kwargs* go to
    ``pandas.read_csv``."""
    import pandas as pd

    path = str(path)
    try:
        table = pd.read_csv(path, **kwargs) if os.path.getsize(path) > 1 else pd.DataFrame()
    except (FileNotFoundError, pd.errors.EmptyDataError):
        table = pd.DataFrame()
    if not len(table):
        table.attrs[REASON] = empty_reason(path) or NO_ROW
    return table


def empty_reason(path) -> str | None:
    """Why the table *path* has no row (its sidecar, :func:`reason_path`); ``None`` without one."""
    import pandas as pd

    sidecar = reason_path(path)
    if not os.path.exists(sidecar):
        return None
    try:
        rows = pd.read_csv(sidecar, keep_default_na=False)
    except (pd.errors.EmptyDataError, pd.errors.ParserError):
        return None
    return str(rows[REASON].iloc[0]) if REASON in rows and len(rows) else None


def read_run(path, expected=None):
    """Open one run file of any kind, check it and return it loaded in memory: the one reader.

    Parameters
    ----------
    path : str or os.PathLike
        The run file.
    expected : roughcontact.study.config.records.RunRecord, optional
        The job record of the current configuration (a generated or adhesive run's
        :class:`~roughcontact.study.runs.jobs.JobSettings`, a
        :class:`~roughcontact.study.config.stickiness.StickinessRun`, a
        :class:`~roughcontact.study.runs.measured.MeasuredJob`): its
        :class:`~roughcontact.study.files.runfile.RunFileSpec` gives the title, variables and
        dimensions, the scalars its path names, the ``config_hash`` and the force grid the file
        must have. ``None``: only that it is a generated or adhesive run file.

    Raises
    ------
    roughcontact.errors.MergeError
        Naming *path*, what is wrong and what to do: a missing, truncated or foreign file, or a
        stale one (computed with other settings: the differing settings are named).
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
    spec = expected.file_spec() if expected is not None else None
    title = spec.title if spec is not None else runfile.TITLE
    required = spec.variables if spec is not None else ("force", *runfile.SCALARS)
    missing = [v for v in required if v not in ds.variables]
    if ds.attrs.get("title") != title:
        what = f"lacks {', '.join(missing)}" if missing else f"is not a {title}"
        raise MergeError(f"{path}: foreign NetCDF file ({what}); {hint}")
    if spec is not None:   # a run of another name or of other settings (e.g. made before a quantity was added)
        _check_scalars(path, ds, spec, hint)
        _check_hash(path, ds, spec, hint, missing)
    if missing:
        raise MergeError(f"{path}: foreign NetCDF file (lacks {', '.join(missing)}); {hint}")
    dims = spec.dims if spec is not None else (("force", "retract") if "retract" in ds.dims else ("force",))
    if sorted(ds.dims) != sorted(dims):
        raise MergeError(f"{path}: foreign NetCDF file (dimensions {dict(ds.sizes)}, expected {', '.join(dims)}); "
                         f"{hint}")
    if spec is not None:
        _check_settings(path, ds, spec, hint)
    return ds


def _check_hash(path: str, ds, spec: runfile.RunFileSpec, hint: str, missing=()) -> None:
    """The file's ``config_hash`` is that of the current settings, else a :class:`MergeError` naming
    the settings that differ (and the variables it lacks: a quantity added since it was made)."""
    want = provenance.config_hash(spec.config)
    if ds.attrs.get("config_hash") != want:
        lacks = f"; it lacks {', '.join(missing)}" if missing else ""
        raise MergeError(f"{path}: was computed with other settings (config_hash {ds.attrs.get('config_hash')} "
                         f"!= {want} of the current config{_differences(ds.attrs.get('config'), spec.config)}"
                         f"{lacks}); {hint} or run snakemake with --rerun-triggers params")


def _check_scalars(path: str, ds, spec: runfile.RunFileSpec, hint: str) -> None:
    """The scalars the file's path names (H, R, h_rms, seed) are the file's (those it holds)."""
    for key, want in spec.scalars.items():
        got = float(ds[key]) if key in ds.variables else float(want)
        if not (got == float(want)):
            raise MergeError(f"{path}: holds {key} = {got:g}, expected {float(want):g} from its name; {hint}")


def _check_settings(path: str, ds, spec: runfile.RunFileSpec, hint: str) -> None:
    """The stale check of :func:`read_run` after its variables and dimensions: the force grid
    (the scalars: :func:`_check_scalars`, ``config_hash``: :func:`_check_hash`)."""
    if spec.force_variable is not None:
        forces = spec.forces
        got = ds[spec.force_variable].values
        if got.shape != forces.shape or not np.allclose(got, forces, rtol=1e-12, atol=0):
            raise MergeError(f"{path}: its force grid differs from the current config; {hint}")


def _differences(recorded, current: dict) -> str:
    """``"; differs in n: 64 in the file, 256 now"``: the settings a stale file was computed
    with that differ from *current* (its ``config`` attribute, JSON); empty where it has none."""
    try:
        recorded = json.loads(recorded) if recorded else None
    except ValueError:
        return ""
    if not isinstance(recorded, dict):
        return ""
    now = json.loads(provenance.canonical_json(current))
    keys = sorted(set(recorded) | set(now), key=str)
    diff = [f"{k}: {recorded.get(k, 'absent')} in the file, {now.get(k, 'absent')} now"
            for k in keys if recorded.get(k) != now.get(k)]
    return f"; differs in {'; '.join(diff)}" if diff else ""


def write_groups(path, groups: dict, attrs: dict) -> None:
    """Write ``{kind: Dataset}`` as the groups of one NetCDF4 file (atomic);
    *attrs* become the root group's attributes (provenance)."""
    import xarray as xr

    write_netcdf(xr.DataTree.from_dict({"/": xr.Dataset(attrs=attrs), **groups}), path)


def read_groups(path) -> dict:
    """``{kind: Dataset}`` of a file written by :func:`write_groups`, loaded in memory."""
    import xarray as xr

    with xr.open_datatree(path, engine="netcdf4") as tree:
        return {name: node.to_dataset().load() for name, node in tree.children.items()}


