"""Surfaces from a measured power spectrum (a table of ``q`` and ``C``).

Normalisation (SurfaceTopography's and contact.engineering's)
-------------------------------------------------------------
``q`` is the angular wavenumber ``2π/λ`` (rad per length unit). ``C`` is the isotropic
two-dimensional power spectral density ``C²ᴰ(q)`` (length⁴) of SurfaceTopography's
``power_spectrum_from_area``::

    C²ᴰ(q) = |h̃(q)|² / (L_x L_y),   h̃(q) = Δx Δy Σ h_ij exp(−i q·x_ij),

so that ``h_rms² = Σ_q C²ᴰ(q) / (L_x L_y)`` over the modes of a grid, i.e.
``h_rms² = (2π)⁻² ∫ C²ᴰ d²q`` in the continuum. Other conventions (``convention=``):

* ``"q/pi*c2d"``: contact.engineering's plotted and exported 2D series, ``q/π × C²ᴰ``
  (length³, comparable with a 1D PSD): ``C²ᴰ = π y / q``;
* ``"persson"``: Persson's ``C(q) = C²ᴰ/(2π)²`` with ``h_rms² = ∫ C d²q``.

contact.engineering's export
----------------------------
The "Power spectrum" analysis of contact.engineering downloads as CSV (topobank,
``download_plot_analyses_to_csv``): ``;``-separated, one long table with the columns
``Subject type; Subject name; Creator; Instrument name; Instrument type; Instrument
parameters; Function name; Data series; Wavevector (1/m); PSD (m³); standard error of PSD
(m³); comment``, SI units (``q`` in ``1/m``), one block of rows per data series:
``1D PSD along x``, ``1D PSD along y``, ``q/π × 2D PSD`` and each again ``(incl.
unreliable data)``. :func:`read_psd` takes the ``q/π × 2D PSD`` rows and returns
``C²ᴰ = π·PSD/q`` in ``m⁴``.

A plain table is two columns ``q, C`` (``,``, ``;``, tab or spaces), ``#`` comments, an
optional header line of names, optionally with units in brackets (``q (1/um), C (um^4)``).
"""

from __future__ import annotations

import csv
import dataclasses
import math
import numbers
import os
import re

import numpy as np

from .._validate import check_finite_positive, check_grid_size
from ..errors import InputFileError

__all__ = ["CE_SERIES", "CONVENTIONS", "PsdTable", "read_psd", "surface_from_psd"]

#: Accepted conventions of ``C`` (module docstring).
CONVENTIONS = ("c2d", "q/pi*c2d", "persson")
#: contact.engineering's data series of the 2D PSD, as ``q/π × C²ᴰ``.
CE_SERIES = "q/π × 2D PSD"
#: Relative slack with which a grid mode counts as inside the table's range.
_SLACK = 1e-9

_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")


@dataclasses.dataclass(frozen=True, eq=False)
class PsdTable:
    """A spectrum read by :func:`read_psd`, always as ``C²ᴰ`` (module docstring).

    Attributes
    ----------
    q : numpy.ndarray
        Angular wavenumbers, strictly increasing, > 0 (rad per ``unit``).
    c : numpy.ndarray
        ``C²ᴰ(q) > 0`` (``unit`` to the fourth power).
    unit : str or None
        Length unit of the table (``None``: the file names none).
    source : str
        The file.
    series : str
        contact.engineering's data series read, or ``""`` for a plain table.
    """

    q: np.ndarray
    c: np.ndarray
    unit: str | None
    source: str
    series: str = ""


def _to_c2d(q, c, convention):
    if convention == "c2d":
        return c
    if convention == "q/pi*c2d":
        return np.pi * c / q
    if convention == "persson":
        return (2.0 * np.pi) ** 2 * c
    raise ValueError(f"convention must be one of {CONVENTIONS}, got {convention!r}")


def _unit_of(column: str, power: int):
    """Length unit in ``name (unit)`` for ``1/u`` (power −1) or ``u^k`` (power k), else None."""
    match = re.search(r"\(([^()]*)\)\s*$", column)
    if not match:
        return None
    text = match.group(1).strip().translate(_SUPERSCRIPTS).replace("**", "^").replace(" ", "")
    if power == -1:
        m = re.fullmatch(r"1/(\w+)|(\w+)\^?-1", text)
        return None if m is None else (m.group(1) or m.group(2))
    m = re.fullmatch(r"(\w+)\^?(\d)", text)
    return m.group(1) if m and int(m.group(2)) == power else None


def _number(text, path, line, what):
    try:
        return float(text)
    except ValueError:
        raise InputFileError(f"{path}: row {line}: {what} {text.strip()!r} is not a number") from None


def _check_rows(path, lines, qs, cs):
    q_prev = None
    for line, q, c in zip(lines, qs, cs):
        if not math.isfinite(q):
            raise InputFileError(f"{path}: row {line}: q = {q} is not finite")
        if not math.isfinite(c):
            raise InputFileError(f"{path}: row {line}: C = {c} is not finite")
        if q <= 0:
            raise InputFileError(f"{path}: row {line}: q = {q:g} is not > 0")
        if c <= 0:
            raise InputFileError(f"{path}: row {line}: C = {c:g} is not > 0")
        if q_prev is not None and q <= q_prev:
            raise InputFileError(f"{path}: row {line}: q = {q:g} is not greater than the previous "
                             f"q = {q_prev:g} (q must increase strictly)")
        q_prev = q


def read_psd(path, *, convention: str = "c2d", series: str = CE_SERIES) -> PsdTable:
    """Read a spectrum table: contact.engineering's CSV export or a plain ``q, C`` table.

    Parameters
    ----------
    path : str or os.PathLike
        The file (UTF-8).
    convention : str
        Convention of ``C`` in a plain table, one of :data:`CONVENTIONS` (module
        docstring); contact.engineering's export is always ``"q/pi*c2d"``.
    series : str
        contact.engineering's data series to read (default :data:`CE_SERIES`; its
        ``"… (incl. unreliable data)"`` twin also works). The 1D series are rejected.

    Returns
    -------
    PsdTable
        ``C²ᴰ`` on strictly increasing ``q``.

    Raises
    ------
    InputFileError
        One line naming the file (and the row, 1-based line number) for a missing or
        empty file, a row that is not a number, non-finite or non-positive ``q`` or ``C``,
        or ``q`` that does not increase strictly.
    """
    if convention not in CONVENTIONS:
        raise ValueError(f"convention must be one of {CONVENTIONS}, got {convention!r}")
    name = os.fspath(path)
    if not os.path.isfile(name):
        raise InputFileError(f"{name}: no such file")
    with open(name, encoding="utf-8-sig", newline="") as f:
        text = f.read().splitlines()
    rows = [(i + 1, line) for i, line in enumerate(text)
            if line.strip() and not line.lstrip().startswith("#")]
    if not rows:
        raise InputFileError(f"{name}: no data rows")
    first = rows[0][1]
    delimiter = ";" if ";" in first else "," if "," in first else "\t" if "\t" in first else None

    def split(line):
        if delimiter is None:
            return line.split()
        return next(csv.reader([line], delimiter=delimiter))

    header = [h.strip() for h in split(first)]
    try:
        [float(h) for h in header[:2]]
        has_header = False
    except ValueError:
        has_header = True
    if has_header and "Data series" in header:       # contact.engineering's export
        try:
            i_series = header.index("Data series")
            i_q = next(i for i, h in enumerate(header) if h.startswith("Wavevector"))
            i_c = next(i for i, h in enumerate(header) if h.startswith("PSD"))
        except StopIteration:
            raise InputFileError(f"{name}: row {rows[0][0]}: contact.engineering header without "
                             f"'Wavevector' and 'PSD' columns") from None
        if "1D PSD" in series:
            raise InputFileError(f"{name}: series {series!r} is a 1D PSD; a surface needs the 2D "
                             f"one ({CE_SERIES!r})")
        unit = _unit_of(header[i_q], -1)
        lines, qs, cs, found = [], [], [], set()
        for line, raw in rows[1:]:
            fields = split(raw)
            if len(fields) <= max(i_series, i_q, i_c):
                raise InputFileError(f"{name}: row {line}: {len(fields)} columns, expected "
                                 f"{len(header)}")
            found.add(fields[i_series])
            if fields[i_series] != series:
                continue
            lines.append(line)
            qs.append(_number(fields[i_q], name, line, "q"))
            cs.append(_number(fields[i_c], name, line, "C"))
        if not lines:
            raise InputFileError(f"{name}: no rows of series {series!r} (series: "
                             f"{', '.join(sorted(found)) or 'none'})")
        used_convention, used_series = "q/pi*c2d", series
    else:
        data = rows[1:] if has_header else rows
        if has_header and len(header) < 2:
            raise InputFileError(f"{name}: row {rows[0][0]}: expected two columns q and C")
        unit = None
        if has_header:
            unit_q, unit_c = _unit_of(header[0], -1), _unit_of(header[1], 4) or \
                _unit_of(header[1], 3)
            unit = unit_q or unit_c
        lines, qs, cs = [], [], []
        for line, raw in data:
            fields = split(raw)
            if len(fields) < 2:
                raise InputFileError(f"{name}: row {line}: expected two columns q and C, got "
                                 f"{len(fields)}")
            lines.append(line)
            qs.append(_number(fields[0], name, line, "q"))
            cs.append(_number(fields[1], name, line, "C"))
        if not lines:
            raise InputFileError(f"{name}: no data rows")
        used_convention, used_series = convention, ""
    _check_rows(name, lines, qs, cs)
    if len(qs) < 2:
        raise InputFileError(f"{name}: one row only; a spectrum table needs at least two")
    q = np.array(qs)
    c = _to_c2d(q, np.array(cs), used_convention)
    q.setflags(write=False)
    c.setflags(write=False)
    return PsdTable(q=q, c=c, unit=unit, source=name, series=used_series)


def check_table(q, c, *, zero_c: bool = False):
    """``(q, c)`` as float arrays, checked: 1-D of one length >= 2, finite, ``q > 0`` strictly
    increasing, ``c > 0`` (``c >= 0`` with *zero_c*); ``ValueError`` naming what is wrong. The one
    check of a tabulated spectrum (:func:`grid_spectrum`, :func:`roughcontact.surfaces.spectra.from_psd`)."""
    q = np.asarray(q, dtype=float)
    c = np.asarray(c, dtype=float)
    if q.ndim != 1 or q.shape != c.shape or q.size < 2:
        raise ValueError(f"q and c must be 1-D arrays of one length >= 2, got shapes "
                         f"{q.shape} and {c.shape}")
    if not (np.all(np.isfinite(q)) and np.all(np.isfinite(c))):
        raise ValueError("q and c must be finite")
    if np.any(q <= 0):
        raise ValueError("q must be > 0")
    if np.any(c < 0) if zero_c else np.any(c <= 0):
        raise ValueError("c must be >= 0" if zero_c else "c must be > 0")
    if np.any(np.diff(q) <= 0):
        raise ValueError("q must increase strictly (be strictly ascending)")
    return q, c


def grid_spectrum(q, c, n: int, *, length: float, convention: str = "c2d") -> np.ndarray:
    """``C²ᴰ`` of the table on the ``n × n`` FFT grid's ``|q|`` (numpy's index order).

    Log-log linear interpolation between the table's rows; **zero** outside the table's
    range ``[q_min, q_max]`` (no extrapolation; a grid mode within a relative ``1e-9`` of
    an end counts as inside) and at ``q = 0``.
    """
    q, c = check_table(q, c)
    c = _to_c2d(q, c, convention)
    q1 = 2.0 * np.pi * np.fft.fftfreq(n, d=length / n)
    qq = np.hypot(q1[:, None], q1[None, :])
    inside = (qq >= q[0] * (1 - _SLACK)) & (qq <= q[-1] * (1 + _SLACK)) & (qq > 0)
    out = np.zeros_like(qq)
    lq = np.log(np.clip(qq[inside], q[0], q[-1]))
    out[inside] = np.exp(np.interp(lq, np.log(q), np.log(c)))
    return out


def surface_from_psd(q, c, n: int, *, length: float, seed: int | None = 0,
                     convention: str = "c2d") -> np.ndarray:
    """Seeded random-phase periodic ``n × n`` surface whose spectrum is the table's.

    ``h(x) = Σ_q a_q exp(i q·x)`` over the grid's modes with ``|a_q| = √C²ᴰ(|q|) / L``
    (:func:`grid_spectrum`: log-log interpolation, zero outside the table's range and at
    ``q = 0``), so that exactly ``h_rms² = Σ_q C²ᴰ(|q|) / L²`` and
    ``⟨|∇h|²⟩ = Σ_q |q|² C²ᴰ(|q|) / L²`` (the spectral slope; the normalisation of
    SurfaceTopography's ``power_spectrum_from_area``, module docstring). The amplitudes
    are deterministic, the phases random: ``φ(q) = φ₀(q) − φ₀(−q)`` with ``φ₀`` one
    ``(n, n)`` draw of ``uniform(0, 2π)`` from ``numpy.random.default_rng(seed)``, as in
    :func:`roughcontact.surfaces.self_affine` (eq. 3), so that ``a_(−q) = conj(a_q)`` and
    the surface is real. For a table of ``C ∝ q^(−2H−2)`` covering the grid, the result is
    ``surfaces.self_affine(n, hurst=H, seed=seed, length=L, h_rms=…)`` up to its scale.

    Parameters
    ----------
    q, c : array_like
        The table (e.g. :class:`PsdTable` ``.q``, ``.c``): strictly increasing ``q > 0``
        (rad per length unit), ``c > 0`` in ``convention``.
    n : int
        Grid points per side (≥ 8).
    length : float
        Period ``L`` (the table's length unit).
    seed : int or None
        Seed of the phases.
    convention : str
        One of :data:`CONVENTIONS` (default ``"c2d"``, what :func:`read_psd` returns).

    Returns
    -------
    numpy.ndarray
        ``(n, n)`` real heights (length unit), mean 0 (to round-off).
    """
    check_grid_size(n)
    check_finite_positive("length", length)
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, numbers.Integral)):
        raise ValueError(f"seed must be an integer or None, got {seed!r}")
    if convention not in CONVENTIONS:
        raise ValueError(f"convention must be one of {CONVENTIONS}, got {convention!r}")
    c2d = grid_spectrum(q, c, n, length=length, convention=convention)
    if not np.any(c2d > 0):
        raise ValueError(f"the table's range of q holds no mode of the grid "
                         f"(2π/L = {2 * np.pi / length:g} to Nyquist "
                         f"{np.pi * n / length * np.sqrt(2):g} at the corners)")
    phase0 = np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, size=(n, n))
    flip = -np.arange(n) % n
    phase = phase0 - phase0[flip][:, flip]
    spectrum = (n * n / length) * np.sqrt(c2d) * np.exp(1j * phase)
    return np.fft.ifft2(spectrum).real
