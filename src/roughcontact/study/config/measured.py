"""The measured inputs of a configuration: scans (``topography``), spectra (``spectrum``), units.

:func:`resolve_inputs` turns the entries of ``topography`` and ``spectrum`` (a path, or a
mapping) into complete mappings with absolute paths, checks that the files exist and that
``units`` is given, and reads every spectrum table (:func:`roughcontact.surfaces.read_psd`,
numpy only: a table with non-positive or non-finite values stops the workflow before any job),
all as one-line :class:`~roughcontact.errors.ConfigError`\\ s naming the key.

Paths are relative to the directory of the config file that lists them (``base_dir``): the
workflow passes the directory of the last ``--configfile`` that names ``topography`` or
``spectrum`` (:func:`config_directory`), ``roughcontact check-config`` the directory of its
argument.
"""
from __future__ import annotations

import os
from pathlib import Path

from ...errors import ConfigError, InputFileError
from ...surfaces.psd import read_psd
from .units import FORCE_UNITS, LENGTH_UNITS, PRESSURE_UNITS, plain_unit, to_metres, to_newtons, to_pascals

__all__ = ["LENGTH_UNITS", "PRESSURE_UNITS", "FORCE_UNITS", "to_newtons", "config_directory", "has_measured", "resolve_inputs",
           "topography_names", "spectrum_names", "plain_unit", "to_metres", "to_pascals"]

_TOPOGRAPHY_DEFAULTS = {"name": None, "unit": None, "size": None, "detrend": "height", "interpolate": False}
_SPECTRUM_DEFAULTS = {"name": None, "convention": "c2d"}


def has_measured(cfg: dict) -> bool:
    """Whether a (raw or resolved) config lists a scan or a spectrum."""
    return bool(cfg.get("topography")) or bool(cfg.get("spectrum"))


def topography_names(cfg: dict) -> list[str]:
    """Names of the scans of a resolved config, in config order."""
    return [entry["name"] for entry in cfg.get("topography", [])]


def spectrum_names(cfg: dict) -> list[str]:
    """Names of the spectra of a resolved config, in config order."""
    return [entry["name"] for entry in cfg.get("spectrum", [])]


def config_directory(files) -> str | None:
    """Directory of the last of the config *files* (paths, in load order) that names
    ``topography`` or ``spectrum``; ``None`` if none does (or none can be read)."""
    import yaml

    for path in reversed([Path(f) for f in files]):
        try:
            data = yaml.safe_load(path.read_text(encoding="utf-8"))
        except (OSError, UnicodeError, yaml.YAMLError):
            continue
        if isinstance(data, dict) and ("topography" in data or "spectrum" in data):
            return str(path.resolve().parent)
    return None


def _entries(cfg: dict, key: str, defaults: dict, base: Path) -> list[dict]:
    out, names = [], {}
    for i, entry in enumerate(cfg.get(key) or []):
        entry = {"file": entry} if isinstance(entry, str) else dict(entry)
        entry = {**defaults, **entry}
        path = Path(os.path.expanduser(entry["file"]))
        path = (path if path.is_absolute() else base / path).resolve()
        if not path.is_file():
            raise ConfigError(f"config key '{key}[{i}].file' = '{entry['file']}': no such file ({path}); "
                              f"allowed: a file, relative to the config file's directory {base}",
                              key=f"{key}[{i}].file")
        entry["file"] = str(path)
        if entry["name"] is None:
            entry["name"] = path.name.split(".")[0] or "scan"
            entry["name"] = "".join(c if c.isalnum() or c in "._-" else "_" for c in entry["name"])
        if entry["name"] in names:
            raise ConfigError(f"config key '{key}[{i}]' has the name '{entry['name']}' of {key}[{names[entry['name']]}]; "
                              f"allowed: distinct names (set {key}[{i}].name)", key=f"{key}[{i}].name")
        names[entry["name"]] = i
        out.append(entry)
    return out


def _check_scans(cfg: dict) -> None:
    """Read every scan's height channel (:func:`roughcontact.surfaces.measured.check_topography`),
    so that a truncated, damaged or misnamed file stops the configuration, not a job."""
    from ...surfaces.measured import check_topography

    study_unit = (cfg.get("units") or {}).get("length")
    for i, entry in enumerate(cfg["topography"]):
        unit = plain_unit(entry["unit"] or study_unit)
        try:
            check_topography(entry["file"], length=entry["size"], unit=None if unit is None else unit)
        except InputFileError as err:
            if err.parameter == "length":   # the entry's size is missing, or given where the file has one
                key = f"topography[{i}].size"
                raise ConfigError(f"config key '{key}': {err.reworded({'length': 'the size'})}", key=key) from None
            raise ConfigError(f"config key 'topography[{i}].file': {err}", key=f"topography[{i}].file") from None
        except ValueError as err:   # a unit SurfaceTopography does not know
            raise ConfigError(f"config key 'topography[{i}].unit': {err}", key=f"topography[{i}].unit") from None


def resolve_inputs(cfg: dict, base_dir: str | os.PathLike | None = None) -> None:
    """Complete the ``topography`` and ``spectrum`` entries of *cfg* in place.

    Each entry becomes a mapping with every key of its schema (defaults filled), ``file``
    absolute and ``name`` set (default: the file name up to its first dot). Raises
    :class:`ConfigError` for a missing file, two entries of one name, or measured inputs
    without ``units.length`` and ``units.e_star``.
    """
    base = Path(base_dir if base_dir is not None else os.getcwd()).resolve()
    cfg["topography"] = _entries(cfg, "topography", _TOPOGRAPHY_DEFAULTS, base)
    cfg["spectrum"] = _entries(cfg, "spectrum", _SPECTRUM_DEFAULTS, base)
    if cfg["topography"]:
        _check_scans(cfg)
    for i, entry in enumerate(cfg["spectrum"]):  # a bad table stops the workflow before any job
        try:
            table = read_psd(entry["file"], convention=entry["convention"])
        except InputFileError as err:
            raise ConfigError(f"config key 'spectrum[{i}].file': {err}", key=f"spectrum[{i}].file") from None
        unit = None if table.unit is None else table.unit.replace("µ", "u").replace("μ", "u")
        if unit is not None and unit not in LENGTH_UNITS:
            raise ConfigError(f"config key 'spectrum[{i}].file': {table.source}: length unit {table.unit!r}; "
                              f"allowed: {', '.join(LENGTH_UNITS)} (or none: units.length)", key=f"spectrum[{i}].file")
    both = set(topography_names(cfg)) & set(spectrum_names(cfg))
    if both:
        raise ConfigError(f"config keys 'topography' and 'spectrum' both name '{min(both)}'; "
                          "allowed: distinct names", key="spectrum")
    band = cfg.get("fit", {}).get("spectrum", {}).get("band")
    if band is not None and not band[0] > band[1]:
        raise ConfigError(f"config key 'fit.spectrum.band' = {list(band)}: the first wavelength must be the "
                          "longer; allowed: [longest, shortest] wavelength, longest > shortest > 0",
                          key="fit.spectrum.band")
    if has_measured(cfg):
        units = cfg.get("units") or {}
        for key in ("length", "e_star"):
            if units.get(key) is None:
                allowed = LENGTH_UNITS if key == "length" else PRESSURE_UNITS
                raise ConfigError(f"missing config key 'units.{key}' (measured inputs are in physical units); "
                                  f"allowed: one of {', '.join(allowed)}", key=f"units.{key}")
