"""Measured topographies as indenter height maps.

:func:`from_topography` reads an instrument's scan with SurfaceTopography
(ContactEngineering, ``pip install SurfaceTopography``, the package's
``measured`` extra) and turns it into the package's indenter map: an
``n × n`` grid of square cells of side ``Δ = length/n`` (module
:mod:`roughcontact.surfaces`).

Sign convention
---------------
An instrument measures the height ``h`` of the surface (up, out of the
material). The package presses a rigid indenter ``z``, measured from the
undeformed half-space *towards* the indenter, so contact starts where ``z`` is
lowest. The returned map is ``z = −(h − mean h)``: the measured **peaks** are
the lowest ``z`` and touch first, as when the measured surface is pressed onto
a flat elastic half-space (the rough body, its composite roughness, facing
down). ``mean z = 0`` over the returned grid.

The steps, in order (each recorded in :attr:`MeasuredSurface.record`):

1. pick the height channel (``channel``: index or name; default the file's
   default channel if it holds heights, else its first height channel);
2. convert to the length ``unit`` (SurfaceTopography ``to_unit``);
3. reject a scan with more than ``max_missing`` of its pixels undefined, then
   fill the undefined pixels with SurfaceTopography's harmonic interpolation
   (``interpolate_undefined_data('harmonic')``: the discrete Laplace equation
   with the defined pixels as boundary values);
4. optionally align scan lines (SurfaceTopography ``scan_line_align``);
5. level the whole scan (SurfaceTopography ``detrend``; the coefficients of
   the removed polynomial are recorded, in SurfaceTopography's normalised
   coordinates ``x/L_x``, ``y/L_y``);
6. cut a square window (centred, or ``window``) of whole pixels where pixels
   are square, else resample it (``interpolate=True``, bilinear, scipy
   ``RegularGridInterpolator``), and average ``coarsen × coarsen`` blocks;
7. negate and remove the mean.

A measured scan is not periodic: :func:`edge_jump` measures the jump across
its edges that a periodic solver would see as a step. :func:`tiles` cuts the
non-overlapping sub-windows (an ensemble of one measured surface).
"""

from __future__ import annotations

import dataclasses
import math
import numbers
import os

import numpy as np

from .._validate import check_grid_size, is_finite_number
from ..errors import InputFileError
from .instrument_files import (
    ascii_unit,
    check_unit,
    frozen,
    heights_and_mask,
    import_surface_topography,
    read_file,
    source_name,
)

__all__ = ["DETREND_MODES", "MeasuredSurface", "check_topography", "from_topography"]

#: Levelling modes that SurfaceTopography's ``detrend`` accepts (``None``: no levelling).
#: ``"height"`` (alias ``"rms-tilt"``) removes the plane of least rms height, ``"slope"`` the
#: plane of least rms slope, ``"curvature"`` (alias ``"rms-curvature"``) the quadratic of least
#: rms height, ``"center"`` (alias ``"mean"``) only the mean; ``"median"``, ``"mad-tilt"``,
#: ``"mad-curvature"`` are the robust (median) variants.
DETREND_MODES = ("height", "rms-tilt", "slope", "curvature", "rms-curvature", "center", "mean",
                 "median", "mad-tilt", "mad-curvature")

#: Relative tolerance within which pixels count as square.
_SQUARE_RTOL = 1e-6
#: Final rms height below this fraction of the raw height scale counts as constant.
_CONSTANT_RTOL = 1e-12


@dataclasses.dataclass(frozen=True, eq=False)
class MeasuredSurface:
    """A measured scan as an indenter map (module docstring for the sign).

    Attributes
    ----------
    heights : numpy.ndarray
        ``(n, n)`` indenter shape ``z = −(h − mean h)`` (``unit``), read-only, mean 0.
    length : float
        Side of the grid (``unit``); cells have side ``length/n``.
    unit : str or None
        Length unit of ``heights`` and ``length`` (``None``: the file gives none).
    record : dict
        What was done, as a flat ``{str: str | int | float}`` dictionary (NetCDF
        attributes): the file, the channel, the pixel counts and sizes, missing pixels and
        how they were filled, the levelling and its coefficients, the window, Sq before and
        after. Units in it are ASCII (``"um"`` for µm) so that NETCDF3 files can hold them.
    """

    heights: np.ndarray
    length: float
    unit: str | None
    record: dict

    @property
    def n(self) -> int:
        """Cells per side."""
        return self.heights.shape[0]

    @property
    def cell_size(self) -> float:
        """Cell side ``Δ = length/n``."""
        return self.length / self.n

    @property
    def sq(self) -> float:
        """Rms height of the grid (``unit``)."""
        return float(np.sqrt(np.mean(self.heights ** 2)))


def from_topography(source, *, n: int | None = None, length: float | None = None,
                    unit: str | None = None, detrend: str | None = "height",
                    fill: str | None = "harmonic", max_missing: float = 0.05,
                    channel: int | str | None = None, interpolate: bool = False,
                    coarsen: int = 1, window=None, align: str | None = None) -> MeasuredSurface:
    """A measured scan as an ``n × n`` indenter map of square cells (module docstring).

    Parameters
    ----------
    source : str or os.PathLike or SurfaceTopography topography
        A file in any format SurfaceTopography reads, or a 2-D uniform topography object.
    n : int, optional
        Cells per side (≥ 8). Default: as many as the window holds whole pixels
        (divided by ``coarsen``).
    length : float, optional
        For files that store no physical size only: the scan's extent along x (its first
        axis) in ``unit``; pixels are then taken square. A size stored in the file cannot
        be overridden.
    unit : str, optional
        Length unit of the result (``"m"``, ``"mm"``, ``"µm"`` or ``"um"``, ``"nm"``, …);
        default the file's. For a file without a unit, the unit its numbers are in.
    detrend : str or None
        Levelling of the whole scan, one of :data:`DETREND_MODES` (default ``"height"``:
        the plane of least rms height); ``None``: heights as stored (only the mean of the
        final grid is removed).
    fill : {"harmonic", None}
        How undefined pixels are filled; ``None`` rejects a scan that has any.
    max_missing : float
        Largest fraction of undefined pixels accepted (``0 ≤ max_missing ≤ 1``).
    channel : int or str, optional
        Channel index in the file, or its name or SurfaceTopography channel id
        (``"Height#2"``). Default: the file's default channel if it holds heights,
        else its first height channel.
    interpolate : bool
        Allow resampling (bilinear) where the window is not a whole number of square
        pixels per cell: non-square pixels, or a ``window``/``n`` that does not fit the
        pixel grid. ``False`` (default) raises instead.
    coarsen : int
        Average ``coarsen × coarsen`` blocks of pixels into one cell.
    window : tuple of 3 floats, optional
        ``(x0, y0, side)`` in ``unit``: the square taken, from the scan's first pixel
        (``x`` along the first axis). Rounded to whole pixels where pixels are square.
        Default: the largest centred square (of ``n·coarsen`` pixels if ``n`` is given).
    align : {"x", "y", None}
        Scan-line alignment before levelling (SurfaceTopography ``scan_line_align``,
        median offsets, degree 1) for scan lines along ``x`` or ``y``; ``None``: none.

    Returns
    -------
    MeasuredSurface

    Raises
    ------
    InputFileError
        For a file or scan that cannot be used (one line naming the file).
    ImportError
        If SurfaceTopography is not installed.
    """
    ST, IO, units_module = import_surface_topography()
    unit = check_unit(unit, units_module)
    if n is not None:
        check_grid_size(n)
    if isinstance(coarsen, bool) or not isinstance(coarsen, numbers.Integral) or coarsen < 1:
        raise ValueError(f"coarsen must be an integer >= 1, got {coarsen!r}")
    coarsen = int(coarsen)
    if detrend is not None and detrend not in DETREND_MODES:
        raise ValueError(f"detrend must be one of {DETREND_MODES} or None, got {detrend!r}")
    if fill not in ("harmonic", None):
        raise ValueError(f"fill must be 'harmonic' or None, got {fill!r}")
    if not is_finite_number(max_missing) or not 0 <= max_missing <= 1:
        raise ValueError(f"max_missing must be a number with 0 <= max_missing <= 1, "
                         f"got {max_missing!r}")
    if align not in ("x", "y", None):
        raise ValueError(f"align must be 'x', 'y' or None, got {align!r}")
    if length is not None and (not is_finite_number(length) or length <= 0):
        raise ValueError(f"length must be a finite number > 0, got {length!r}")
    if window is not None:
        try:
            window = tuple(float(v) for v in window)
        except (TypeError, ValueError):
            raise ValueError(f"window must be (x0, y0, side), got {window!r}") from None
        if len(window) != 3 or not all(math.isfinite(v) for v in window) \
                or window[0] < 0 or window[1] < 0 or window[2] <= 0:
            raise ValueError(f"window must be (x0, y0, side) with x0, y0 >= 0 and side > 0, "
                             f"got {window!r}")

    name = source_name(source)
    if isinstance(source, (str, os.PathLike)):
        topography, record = read_file(source, channel, length, unit, ST, IO, units_module)
    else:
        if channel is not None or length is not None:
            raise ValueError("channel= and length= apply to files, not to topography objects")
        if not hasattr(source, "heights") or not hasattr(source, "physical_sizes"):
            raise TypeError(f"source must be a path or a SurfaceTopography topography, got "
                            f"{type(source).__name__}")
        topography = source
        record = {"file": "", "format": "object", "channel_index": -1, "channel": "",
                  "file_unit": "" if source.unit is None else str(source.unit),
                  "physical_size_source": "object"}
    if topography.dim != 2:
        raise InputFileError(f"{name}: a line scan ({topography.dim}-D), not an areal topography")
    if not getattr(topography, "is_uniform", True):
        raise InputFileError(f"{name}: a nonuniform topography, not a grid")
    if unit is not None and topography.unit is not None and topography.unit != unit:
        topography = topography.to_unit(unit)
    out_unit = topography.unit if topography.unit is not None else unit

    # Missing pixels.
    raw, mask = heights_and_mask(topography)
    nx, ny = raw.shape
    missing = int(np.count_nonzero(mask))
    fraction = missing / raw.size
    if missing == raw.size:
        raise InputFileError(f"{name}: all {raw.size} pixels are undefined")
    if fraction > max_missing:
        raise InputFileError(f"{name}: {missing} of {raw.size} pixels ({100 * fraction:.2f} %) "
                             f"are undefined, more than max_missing = {max_missing:g}")
    if missing and fill is None:
        raise InputFileError(f"{name}: {missing} pixels are undefined; pass fill='harmonic' "
                             f"to fill them")
    if missing or topography.has_undefined_data:
        topography = topography.interpolate_undefined_data("harmonic")
    filled = np.asarray(topography.heights(), dtype=float)
    if not np.all(np.isfinite(filled)):
        raise InputFileError(f"{name}: heights are not finite after filling")
    scale = float(np.max(np.abs(filled)))
    sq_raw = float(np.std(filled))
    if sq_raw <= _CONSTANT_RTOL * scale or scale == 0.0:
        raise InputFileError(f"{name}: heights are constant")

    if align is not None:
        topography = topography.scan_line_align(direction=align)
    coeffs = ()
    polynomial = ""
    if detrend is not None:
        topography = topography.detrend(detrend_mode=detrend)
        coeffs = tuple(float(c) for c in np.ravel(topography.coeffs))
        try:
            polynomial = topography.stringify_plane()
        except Exception:  # pragma: no cover - informational only
            polynomial = ""
    levelled = np.asarray(topography.heights(), dtype=float)
    sq_levelled = float(np.std(levelled))

    sx, sy = (float(s) for s in topography.physical_sizes)
    dx, dy = sx / nx, sy / ny
    square = math.isclose(dx, dy, rel_tol=_SQUARE_RTOL)
    grid, window_record = _window(levelled, dx, dy, n, coarsen, window, square, interpolate,
                                  name, out_unit)
    grid = grid - grid.mean()
    sq = float(np.sqrt(np.mean(grid ** 2)))
    if sq <= _CONSTANT_RTOL * scale:
        raise InputFileError(f"{name}: heights are constant after levelling "
                             f"(detrend={detrend!r}; Sq = {sq:.3g})")
    heights = frozen(-grid)
    n_out = heights.shape[0]
    side = window_record["window_side"]

    record["file_unit"] = ascii_unit(record["file_unit"], units_module)
    record.update({
        "unit": ascii_unit(out_unit, units_module),
        "nb_grid_pts_x": int(nx), "nb_grid_pts_y": int(ny),
        "physical_size_x": sx, "physical_size_y": sy,
        "pixel_size_x": dx, "pixel_size_y": dy,
        "undefined_pixels": missing, "undefined_fraction": float(fraction),
        "fill": "harmonic" if missing else "none",
        "scan_line_alignment": "none" if align is None else f"{align}, median, degree 1",
        "detrend": "none" if detrend is None else detrend,
        "detrend_coefficients": len(coeffs),
    })
    for i, c in enumerate(coeffs):
        record[f"detrend_coefficient_{i}"] = c
    record["detrend_polynomial"] = polynomial
    record.update(window_record)
    record.update({
        "coarsen": coarsen, "n": int(n_out), "length": float(side), "cell_size": side / n_out,
        "sq_raw": sq_raw, "sq_levelled": sq_levelled, "sq": sq,
        "sign": "heights = -(measured - mean): measured peaks touch first",
        "reader": f"SurfaceTopography {ST.__version__}",
    })
    return MeasuredSurface(heights=heights, length=float(side), unit=out_unit, record=record)


def _window(h, dx, dy, n, coarsen, window, square, interpolate, name, unit):
    """Cut (or resample) the window and coarsen it: the ``(n, n)`` grid and its record."""
    nx, ny = h.shape
    u = "" if unit is None else f" {unit}"
    resample = not square
    if square:
        if window is not None:
            i0, j0, m = round(window[0] / dx), round(window[1] / dx), round(window[2] / dx)
            if m < 1:
                raise InputFileError(f"{name}: window side {window[2]:g}{u} is less than one "
                                     f"pixel ({dx:g}{u})")
            if n is not None and m != n * coarsen:
                resample = True
            elif m % coarsen:
                raise InputFileError(f"{name}: window of {m} pixels is not a multiple of "
                                     f"coarsen = {coarsen}")
        else:
            if n is None:
                m = min(nx, ny) // coarsen * coarsen
            else:
                m = n * coarsen
            i0, j0 = (nx - m) // 2, (ny - m) // 2
        if not resample:
            if m > nx or m > ny or i0 + m > nx or j0 + m > ny:
                raise InputFileError(f"{name}: the scan ({nx} x {ny} pixels) is smaller than the "
                                     f"requested window of {m} x {m} pixels at ({i0}, {j0})")
            if m // coarsen < 8:
                raise InputFileError(f"{name}: the window gives {m // coarsen} cells per side, "
                                     f"fewer than 8")
            block = h[i0:i0 + m, j0:j0 + m]
            grid = block.reshape(m // coarsen, coarsen, m // coarsen, coarsen).mean(axis=(1, 3))
            return grid, {"window_x0": i0 * dx, "window_y0": j0 * dy, "window_side": m * dx,
                          "window_i0": i0, "window_j0": j0, "window_pixels": m,
                          "interpolated": 0}
    if not interpolate:
        why = (f"pixels are not square ({dx:.6g}{u} x {dy:.6g}{u})" if not square else
               f"the window does not hold n*coarsen = {n * coarsen} whole pixels")
        raise InputFileError(f"{name}: {why}; pass interpolate=True to resample")
    lx, ly = nx * dx, ny * dy
    if window is not None:
        x0, y0, side = window
    else:
        side = min(lx, ly)
        x0, y0 = (lx - side) / 2, (ly - side) / 2
    if x0 + side > lx * (1 + 1e-12) or y0 + side > ly * (1 + 1e-12):
        raise InputFileError(f"{name}: the scan ({lx:g}{u} x {ly:g}{u}) is smaller than the "
                             f"requested window {side:g}{u} at ({x0:g}, {y0:g})")
    cells = n * coarsen if n is not None else int(side / max(dx, dy)) // coarsen * coarsen
    if cells > side / min(dx, dy) * (1 + 1e-9):
        raise InputFileError(f"{name}: the scan has {side / min(dx, dy):.0f} pixels across the "
                             f"window, fewer than the requested {cells} cells")
    if cells // coarsen < 8:
        raise InputFileError(f"{name}: the window gives {cells // coarsen} cells per side, "
                             f"fewer than 8")
    from scipy.interpolate import RegularGridInterpolator
    step = side / cells
    # Nodes x_i = i·Δ (the package's and SurfaceTopography's convention), clamped to the data.
    xs = np.clip(x0 + step * np.arange(cells), 0.0, (nx - 1) * dx)
    ys = np.clip(y0 + step * np.arange(cells), 0.0, (ny - 1) * dy)
    interp = RegularGridInterpolator((dx * np.arange(nx), dy * np.arange(ny)), h,
                                     method="linear")
    fine = interp(np.stack(np.meshgrid(xs, ys, indexing="ij"), axis=-1))
    m = cells // coarsen
    grid = fine.reshape(m, coarsen, m, coarsen).mean(axis=(1, 3))
    return grid, {"window_x0": float(x0), "window_y0": float(y0), "window_side": float(side),
                  "window_i0": -1, "window_j0": -1, "window_pixels": -1, "interpolated": 1}


def check_topography(path, *, channel=None, length: float | None = None, unit: str | None = None) -> dict:
    """Open an instrument file and read its height channel, as :func:`from_topography` would,
    without levelling or cutting it: what ``roughcontact check-config`` does for each scan.

    Returns the record of the file (format, channel, file unit, where the size comes from).
    Raises :class:`~roughcontact.errors.InputFileError`, one line naming the file, for a file
    that is missing, unreadable, empty, of unknown format, misnamed, cut short or damaged, or
    that gives no physical size when ``length`` is not given.
    """
    ST, IO, units_module = import_surface_topography()
    _, record = read_file(path, channel, length, check_unit(unit, units_module), ST, IO, units_module)
    return record
