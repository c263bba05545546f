"""Reading instrument files with SurfaceTopography: the height channel, units, the raw grid.

The helpers behind :func:`roughcontact.surfaces.measured.from_topography`. SurfaceTopography
(ContactEngineering; the package's ``measured`` extra) is imported on first use, with a
one-line error naming the extra where it is missing; it takes seconds to import.
"""
from __future__ import annotations

import contextlib
import io
import logging
import numbers
import os
import warnings
from pathlib import Path

import numpy as np

from ..errors import InputFileError

__all__ = ["ascii_unit", "check_unit", "frozen", "heights_and_mask", "import_surface_topography", "is_height",
           "pick_channel", "quiet", "read_file", "source_name"]

#: characters of a reader's own error message shown in ours (the rest is cut: some readers put
#: whole headers of raw bytes in their messages)
_BRIEF_CHARS = 80


def frozen(a: np.ndarray) -> np.ndarray:
    a = np.ascontiguousarray(a, dtype=float)
    a.setflags(write=False)
    return a


def source_name(source) -> str:
    return os.fspath(source) if isinstance(source, (str, os.PathLike)) else "<topography>"


def import_surface_topography():
    try:
        import SurfaceTopography
        from SurfaceTopography import IO
        from SurfaceTopography.Support import UnitConversion
    except ImportError as err:  # pragma: no cover - exercised only without the extra
        raise ImportError("reading measured topographies needs SurfaceTopography: install the "
                          "'measured' extra (pip install 'roughcontact[measured]')") from err
    return SurfaceTopography, IO, UnitConversion


def check_unit(unit, units_module):
    if unit is None:
        return None
    if not isinstance(unit, str):
        raise TypeError(f"unit must be a length unit string, got {unit!r}")
    normal = units_module.mangle_length_unit_utf8(unit)
    if normal not in units_module.length_units:
        raise ValueError(f"unit must be one of {sorted(set(units_module.length_units))}, "
                         f"got {unit!r}")
    return normal


def ascii_unit(unit, units_module) -> str:
    """A unit for the record in ASCII (``"um"`` for µm), so NETCDF3 files can hold it."""
    return "" if not unit else units_module.mangle_length_unit_ascii(str(unit))


def is_height(channel, units_module) -> bool:
    """A channel holds heights: SurfaceTopography says so and its units are lengths."""
    if not channel.is_height_channel:
        return False
    for unit in (channel.unit, channel.data_unit):
        if unit is not None and (not isinstance(unit, str)
                                 or units_module.mangle_length_unit_utf8(unit)
                                 not in units_module.length_units):
            return False
    return True


def pick_channel(reader, channel, name, units_module):
    channels = reader.channels
    if channel is None:
        default = reader.default_channel
        if is_height(default, units_module):
            return default
        heights = [c for c in channels if is_height(c, units_module)]
        if not heights:
            found = ", ".join(f"{c.name!r}" for c in channels) or "none"
            raise InputFileError(f"{name}: no height channel (channels: {found})")
        return heights[0]
    if isinstance(channel, numbers.Integral) and not isinstance(channel, bool):
        if not 0 <= channel < len(channels):
            raise InputFileError(f"{name}: channel index {channel} out of range, the file has "
                                 f"{len(channels)} channel(s)")
        chosen = channels[channel]
    elif isinstance(channel, str):
        by_id = [c for c in channels if c.channel_id == channel]
        by_name = [c for c in channels if c.name == channel]
        if by_id:
            chosen = by_id[0]
        elif len(by_name) == 1:
            chosen = by_name[0]
        elif by_name:
            ids = ", ".join(repr(c.channel_id) for c in by_name)
            raise InputFileError(f"{name}: {len(by_name)} channels are named {channel!r}; "
                                 f"pick one by id ({ids}) or index")
        else:
            found = ", ".join(f"{c.channel_id!r}" for c in channels)
            raise InputFileError(f"{name}: no channel {channel!r} (channels: {found})")
    else:
        raise TypeError(f"channel must be an index, a name or None, got {channel!r}")
    if not is_height(chosen, units_module):
        what = (f"has no length unit (unit {chosen.data_unit!r})" if chosen.is_height_channel
                else f"holds {chosen.data_kind.value} data")
        raise InputFileError(f"{name}: channel {chosen.channel_id!r} {what}, not heights")
    return chosen


@contextlib.contextmanager
def quiet():
    """Silence what the file readers print on the way (stdout, stderr, warnings, log records):
    a bad file is reported once, by the error it raises."""
    previous = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()), \
                contextlib.redirect_stderr(io.StringIO()):
            warnings.simplefilter("ignore")
            yield
    finally:
        logging.disable(previous)


def _brief(err: BaseException) -> str:
    """A reader's exception in a few printable words: its type and the start of its first line."""
    text = str(err).strip().splitlines()[0] if str(err).strip() else ""
    text = "".join(c for c in text if c.isprintable())
    if len(text) > _BRIEF_CHARS:
        text = text[:_BRIEF_CHARS].rstrip() + "..."
    return f"{type(err).__name__}: {text}" if text else type(err).__name__


def _check_path(name: str) -> None:
    """A regular file that can be opened and is not empty, else one line saying which."""
    if not os.path.exists(name):
        raise InputFileError(f"{name}: no such file")
    if not os.path.isfile(name):
        raise InputFileError(f"{name}: not a file (a directory or a device)")
    try:
        with open(name, "rb") as fh:
            fh.read(1)
    except OSError as err:
        raise InputFileError(f"{name}: cannot open the file ({err.strerror or type(err).__name__})") from None
    if os.path.getsize(name) == 0:
        raise InputFileError(f"{name}: the file is empty")


def _check_format(name: str, reader, IO) -> None:
    """The format SurfaceTopography detected by the content agrees with the file's extension,
    where the extension is one some reader claims (a ``.opd`` read as a Bruker file is not the
    scan the user meant, or is cut short)."""
    extension = Path(name).suffix.lower().lstrip(".")
    expected = {r.format() for r in IO.readers if extension == r.format() or extension in r._file_extensions}
    detected = reader.format()
    if expected and detected not in expected:
        raise InputFileError(f"{name}: its content reads as a {reader.name()} file ({detected}), not as the "
                             f".{extension} its name says; the file is cut short, damaged or misnamed")


def read_file(path, channel, length, unit, ST, IO, units_module):
    """The topography of one channel of an instrument file and its record.

    Every way a file can be bad (missing, unreadable, empty, of unknown format, of a format
    other than its extension says, truncated or corrupt) is one :class:`InputFileError`
    naming the file; nothing the readers print gets through (:func:`quiet`).
    """
    name = os.fspath(path)
    _check_path(name)
    with quiet():
        try:
            reader = IO.open_topography(name)
        except IO.CannotDetectFileFormat:
            raise InputFileError(f"{name}: unknown or unreadable file format "
                                 f"(SurfaceTopography found no reader for it)") from None
        except Exception as err:  # corrupt files: the readers' own exceptions
            raise InputFileError(f"{name}: cannot read the file, it is cut short or damaged ({_brief(err)})") \
                from None
        _check_format(name, reader, IO)
        try:
            return _read_channel(name, reader, channel, length, unit, units_module)
        except InputFileError:
            raise
        except Exception as err:  # a header that reads, data that do not
            raise InputFileError(f"{name}: cannot read the file's data, it is cut short or damaged "
                                 f"({_brief(err)})") from None


def _read_channel(name, reader, channel, length, unit, units_module):
    chosen = pick_channel(reader, channel, name, units_module)
    if chosen.dim != 2:
        raise InputFileError(f"{name}: channel {chosen.channel_id!r} is a line scan "
                             f"({chosen.dim}-D), not an areal topography")
    kwargs = {}
    if chosen.physical_sizes is None:
        if length is None:
            raise InputFileError(f"{name}: the file gives no physical size; pass length= "
                                 f"(the scan's extent along x)", parameter="length")
        nx, ny = chosen.nb_grid_pts
        if chosen.unit is not None and unit is not None:   # length is given in `unit`
            length = length * units_module.get_unit_conversion_factor(unit, chosen.unit)
        kwargs["physical_sizes"] = (float(length), float(length) * ny / nx)
    elif length is not None:
        raise InputFileError(f"{name}: the file gives the physical size "
                             f"{tuple(float(s) for s in chosen.physical_sizes)} "
                             f"{chosen.unit}; length= cannot override it", parameter="length")
    file_unit = chosen.unit
    if file_unit is None and unit is not None:
        kwargs["unit"] = unit          # a file without unit: its numbers are in `unit`
    topography = chosen.topography(**kwargs)
    topography.heights()               # the data themselves: a truncated file fails here
    info = {"file": str(Path(name).resolve()), "format": reader.format(),
            "channel_index": int(chosen.index), "channel": str(chosen.channel_id),
            "file_unit": "" if file_unit is None else str(file_unit),
            "physical_size_source": "file" if "physical_sizes" not in kwargs else "argument"}
    return topography, info


def heights_and_mask(topography):
    h = topography.heights()
    mask = np.ma.getmaskarray(h) | ~np.isfinite(np.ma.getdata(h))
    return np.ma.getdata(h), mask
