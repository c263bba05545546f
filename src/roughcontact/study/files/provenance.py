"""Provenance and safe-write helpers for the parameter study.

Every NetCDF file the pipeline writes carries :func:`provenance_attrs`: the
package version, the git commit of the checkout (when there is one), the
resolved configuration and its hash, and the creation time.  Files are written
through :func:`atomic_path`, so a failed or killed job never leaves a partial
file under the final name; every NetCDF file through :func:`write_netcdf`, the one
atomic NetCDF write.

Only the standard library is imported here.
"""
from __future__ import annotations

import contextlib
import datetime as _dt
import hashlib
import json
import math
from collections.abc import Mapping
import os
import subprocess
from pathlib import Path

__all__ = [
    "package_version",
    "git_commit",
    "canonical_json",
    "config_hash",
    "provenance_attrs",
    "atomic_path",
    "write_netcdf",
    "write_text",
]


def package_version() -> str:
    """Version of the installed (or checked-out) ``roughcontact``."""
    try:
        from importlib.metadata import version

        return version("roughcontact")
    except Exception:  # not installed: running from a checkout via PYTHONPATH
        try:
            import roughcontact

            return str(getattr(roughcontact, "__version__", "unknown"))
        except Exception:
            return "unknown"


def git_commit(path: str | os.PathLike | None = None) -> str:
    """``<sha>`` (``<sha>-dirty`` with local changes) of the git checkout holding
    *path* (default: this source file), or ``"unknown"`` outside git."""
    where = Path(path) if path is not None else Path(__file__).resolve().parent
    if where.is_file():
        where = where.parent
    try:
        sha = subprocess.run(
            ["git", "rev-parse", "HEAD"], cwd=where, capture_output=True,
            text=True, timeout=10, check=True,
        ).stdout.strip()
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no"], cwd=where,
            capture_output=True, text=True, timeout=10, check=True,
        ).stdout.strip()
    except Exception:
        return "unknown"
    return f"{sha}-dirty" if dirty else sha


def _jsonable(obj):
    if isinstance(obj, float) and not math.isfinite(obj):
        return "inf" if obj > 0 else ("-inf" if obj < 0 else "nan")
    if isinstance(obj, Mapping):   # a dict, or a read-only view of one (StudySettings.config)
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if hasattr(obj, "item") and not isinstance(obj, (str, bytes)):  # numpy scalar
        return _jsonable(obj.item())
    return obj


def canonical_json(obj) -> str:
    """Deterministic JSON (sorted keys, inf written as "inf")."""
    return json.dumps(_jsonable(obj), sort_keys=True, separators=(",", ":"))


def config_hash(obj) -> str:
    """First 16 hex digits of the SHA-256 of :func:`canonical_json`."""
    return hashlib.sha256(canonical_json(obj).encode()).hexdigest()[:16]


def provenance_attrs(config: Mapping | None = None, **extra) -> dict:
    """NetCDF-safe global attributes describing where a file came from."""
    attrs = {
        "roughcontact_version": package_version(),
        "git_commit": git_commit(),
        "created_utc": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="seconds"),
        "reference": "R. Pohrt and V. L. Popov, Adv. Tribol. 2013, 974178 (doi:10.1155/2013/974178)",
    }
    if config is not None:
        attrs["config"] = canonical_json(config)
        attrs["config_hash"] = config_hash(config)
    for key, value in extra.items():
        attrs[key] = _netcdf_attr(value)
    return attrs


def _netcdf_attr(value):
    if isinstance(value, bool):
        return int(value)
    if value is None:
        return "none"
    if isinstance(value, (dict, list, tuple)):
        return canonical_json(value)
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    return value


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike):
    """Yield a temporary path next to *path*; rename it to *path* only if the
    block finishes without an exception, otherwise delete it.

    >>> with atomic_path("out.nc") as tmp:   # doctest: +SKIP
    ...     write_something(tmp)
    """
    final = Path(path)
    final.parent.mkdir(parents=True, exist_ok=True)
    for stale in final.parent.glob(f".{final.name}.tmp-*"):  # left by a killed (SIGKILL) writer
        with contextlib.suppress(OSError):
            stale.unlink()
    tmp = final.with_name(f".{final.name}.tmp-{os.getpid()}")
    try:
        yield tmp
        os.replace(tmp, final)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            tmp.unlink()
        raise


def write_netcdf(data, path: str | os.PathLike) -> None:
    """Write one NetCDF4 file atomically (:func:`atomic_path`): the one NetCDF write of the study.

    Parameters
    ----------
    data : xarray.Dataset or xarray.DataTree or callable
        What to write: an xarray object (its ``to_netcdf``, engine ``netcdf4``), or a function
        ``fill(nc)`` that fills an open, writable ``netCDF4.Dataset`` (format ``NETCDF4``) when the
        file's variables are written one by one (:func:`roughcontact.study.files.runfile.write_run`).
    path : str or os.PathLike
        The final file; it appears only once the write has finished.
    """
    with atomic_path(path) as tmp:
        if hasattr(data, "to_netcdf"):
            data.to_netcdf(tmp, engine="netcdf4")
        else:
            import netCDF4

            with netCDF4.Dataset(tmp, "w", format="NETCDF4") as nc:
                data(nc)


def write_text(text: str, path: str | os.PathLike) -> None:
    """Write *text* (UTF-8) to *path* atomically (:func:`atomic_path`): the report's HTML pages."""
    with atomic_path(path) as tmp:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)
