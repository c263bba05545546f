"""The measured stage of the study: scans and spectra pressed as indenters, in physical units.

Three jobs per measured surface (``workflow/rules/measured.smk``):

* :func:`prepare_surface`: a scan (``topography`` entry) read by
  :func:`roughcontact.surfaces.from_topography` (levelled, cut to its largest centred square),
  converted to ``units.length`` and written with its record, the SHA-256 of the file and the
  number of tiles (``tile``) to one NetCDF file;
* :func:`run_job`: one load path of one tile of a scan, or of one seed of a spectrum
  (:func:`roughcontact.surfaces.surface_from_psd` on the grid ``grid.n``, ``grid.length``), for
  one radius;
* :func:`roughcontact.study.analysis.measured_merge.merge_surface`: the runs of one surface, one group per kind (``sphere``: dims
  ``radius, tile|seed, force``; ``flat``: ``tile|seed, force``), with the bootstrap interval of
  the mean stiffness over the tiles (or seeds), CF ``units`` and provenance.

Half-spaces. A body (finite ``radius``: ``r²/2R`` superposed on the heights, apex at the node
``(n//2, n//2)``) is pressed on the free half-space, as for generated surfaces; its contact must
stay off the outer ring of cells of the tile, else the job stops with one line ("loads whose
contact would reach the scan's edge"). A nominally flat tile (``radius: .inf``) is not
periodic, so it is pressed as a finite rough punch of the tile's side on the free half-space
(contact at its edge cells allowed); see ``docs/guide/measured.md`` for the free-vs-periodic
numbers. A spectrum's surfaces are periodic by construction: flat ones on the periodic
half-space, as the generated ones.

Units. Lengths are in ``units.length``, ``e_star`` in ``units.e_star``; the forces of the
config are ``F/(E* L²)`` with ``L`` the side of the tile (or ``grid.length``). The files give
``force`` in N and ``stiffness`` in N/m beside ``force_normalized`` and
``stiffness_normalized = k/(E* L)``.
"""
from __future__ import annotations

import dataclasses
import hashlib
import logging
import os

import numpy as np

from ... import surfaces
from ...errors import IndentError, InputFileError
from ...surfaces.bodies import paraboloid
from .. import quantities
from ..files import provenance, runfile
from ..config.measured import LENGTH_UNITS, plain_unit, to_metres, to_newtons, to_pascals
from .naming import kind_of
from ..config.defaults import solver_maxiter
from ..config.records import ForcePathRecord
from ..config.settings import StudySettings, TopographyInput

__all__ = ["MeasuredJob", "prepare_surface", "read_surface", "tile_count", "job_of", "run_job", "run_order",
           "sha256"]

logger = logging.getLogger(__name__)

#: CF ``units`` of the per-load variables (``{L}``: the length unit)
_UNITS = {"depth": "{L}", "contact_area": "{L}2", "stiffness": "N m-1", "force": "N"}


def sha256(path) -> str:
    """Hex SHA-256 of a file."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _scale(unit, study_unit: str, name: str) -> float:
    """Study length units per ``unit`` (``unit`` None: the study's)."""
    unit = plain_unit(unit)
    if unit is None:
        return 1.0
    if unit not in LENGTH_UNITS:
        raise InputFileError(f"{name}: length unit {unit!r} is none of {', '.join(LENGTH_UNITS)}")
    return to_metres(unit) / to_metres(study_unit)


def prepare_surface(entry, output, *, length_unit: str, tile: int | None) -> None:
    """Read the scan of one ``topography`` entry and write it, in *length_unit*, to *output*.

    *entry*: a :class:`~roughcontact.study.config.settings.TopographyInput` (or a resolved
    ``topography`` entry); *length_unit*: ``units.length``; *tile*: the tile side in cells
    (``None``: the whole square). Only these: a change of another setting keeps the tiles' runs.

    Raises :class:`~roughcontact.errors.InputFileError` (one line, nothing written) for a scan
    that cannot be used, including one smaller than ``tile``.
    """
    import xarray as xr

    entry = TopographyInput.of(entry)
    study_unit = length_unit
    unit = entry.unit or study_unit
    detrend = None if entry.detrend == "none" else entry.detrend
    try:
        scan = surfaces.from_topography(entry.file, unit=unit, length=entry.size, detrend=detrend,
                                        interpolate=entry.interpolate)
    except InputFileError as err:   # the config's words for the reader's arguments
        raise InputFileError(err.reworded({"length": f"size (in the topography entry {entry.name})"})) from None
    factor = _scale(scan.unit, study_unit, entry.file)
    tile = tile or scan.n
    if tile > scan.n:
        raise InputFileError(f"{entry.file}: the scan's largest square has {scan.n} x {scan.n} pixels, "
                             f"fewer than a tile of tile = {tile}")
    record = {f"scan_{k}": v for k, v in scan.record.items()}
    attrs = provenance.provenance_attrs(
        title="roughcontact measured surface", name=entry.name, file=os.path.basename(entry.file),
        file_sha256=sha256(entry.file), length=scan.length * factor, units_length=study_unit,
        tile=int(tile), tile_count=(scan.n // tile) ** 2, tile_length=scan.length * factor * tile / scan.n,
        **record)
    n = scan.n
    x = np.arange(n) * scan.cell_size * factor
    ds = xr.Dataset({"heights": (("x", "y"), scan.heights * factor,
                                 {"long_name": "indenter shape z = -(h - mean h): measured peaks touch first",
                                  "units": study_unit})},
                    coords={"x": ("x", x, {"units": study_unit}), "y": ("y", x, {"units": study_unit})},
                    attrs=attrs)
    provenance.write_netcdf(ds, output)
    logger.info("%s: %d x %d cells of %g %s, %d tiles of %d", entry.name, n, n,
                scan.cell_size * factor, study_unit, (n // tile) ** 2, tile)


def read_surface(path) -> tuple[np.ndarray, float, dict]:
    """Heights, side length and attributes of a file of :func:`prepare_surface`."""
    import xarray as xr

    with xr.open_dataset(path, engine="netcdf4") as ds:
        return ds["heights"].values.copy(), float(ds.attrs["length"]), dict(ds.attrs)


def tile_count(path) -> int:
    """Number of tiles of a file of :func:`prepare_surface`."""
    return int(read_surface(path)[2]["tile_count"])


@dataclasses.dataclass(frozen=True, kw_only=True)
class MeasuredJob(ForcePathRecord):
    """Everything one measured load path depends on (:func:`job_of`): the job record
    (:class:`~roughcontact.study.config.records.RunRecord`) of a scan's tile or a spectrum's seed.

    The grid (``n``, ``length``: a spectrum's; ``None`` for a scan, whose tile sets them),
    ``e_star`` (``pressure_unit``), the load path ``F/(E* L²)`` with ``L`` the tile's (or grid's)
    side and the solver settings are the fields of
    :class:`~roughcontact.study.config.records.ForcePathRecord`; this kind adds its surface.

    Attributes
    ----------
    source, name, index :
        ``"topography"`` or ``"spectrum"``, the surface's name, and the tile (row by row) or
        the seed.
    radius : float
        Sphere radius (``length_unit``); ``inf``: nominally flat.
    length_unit, pressure_unit : str
        ``units.length`` and ``units.e_star``.
    tile : int or None
        Topography: the tile's side in cells (``None``: the whole square).
    convention : str
        Spectrum: the table's convention.
    force_unit : str
        Unit of the forces in progress lines and messages (:data:`~roughcontact.study.config.measured.FORCE_UNITS`).
    """

    source: str
    name: str
    index: int
    radius: float
    length_unit: str
    pressure_unit: str
    tile: int | None = None
    convention: str = "c2d"
    force_unit: str = "N"

    @property
    def kind(self) -> str:
        return kind_of(self.radius)

    @property
    def ensemble(self) -> str:
        """Name of the ensemble dimension: ``tile`` or ``seed``."""
        return "tile" if self.source == "topography" else "seed"

    def describe(self) -> str:
        return f"{self.source} {self.name}, {self.ensemble} {self.index}, R = {self.radius:g} {self.length_unit}"

    def file_spec(self) -> runfile.RunFileSpec:
        """What this run's file must be (:func:`roughcontact.study.files.io.read_run`): the run file's
        variables over ``force`` with ``force_normalized``, the ``config_hash`` of the job and
        its normalised force grid ``F/(E* L²)``."""
        return runfile.RunFileSpec(title=runfile.TITLE, variables=(*quantities.recorded(self), "force",
                                                                   "force_normalized"),
                                   dims=("force",), config=self.record(), force_variable="force_normalized",
                                   forces=self.forces_normalized())


def job_of(study, source: str, name: str, radius: float, index: int, *, force_unit: str = "N") -> MeasuredJob:
    """The :class:`MeasuredJob` of one (surface, radius, tile or seed) of the study
    (:class:`~roughcontact.study.config.settings.StudySettings` or a resolved configuration;
    *force_unit*: of progress lines and messages)."""
    study = StudySettings.of(study)
    rng = study.forces[kind_of(radius)]
    solver = study.solver
    extra = ({"tile": study.tile, "n": None, "length": None} if source == "topography" else
             {"n": study.grid.n, "length": study.grid.length,
              "convention": study.spectrum_entry(name).convention})
    return MeasuredJob(source=source, name=name, index=int(index), radius=float(radius),
                       e_star=study.e_star, length_unit=study.units.length,
                       pressure_unit=study.units.e_star, force_from=rng.start,
                       force_to=rng.stop, force_count=rng.count, tol=solver.tol,
                       maxiter=solver_maxiter(solver.maxiter),
                       stiffness_method=solver.stiffness, rel_step=solver.rel_step,
                       force_unit=plain_unit(force_unit), **extra)


def _spectrum_surface(job: MeasuredJob, path) -> np.ndarray:
    table = surfaces.read_psd(path, convention=job.convention)
    s = _scale(table.unit, job.length_unit, table.source)   # study lengths per table length
    try:
        return surfaces.surface_from_psd(table.q / s, table.c * s**4, job.n, length=job.length, seed=job.index)
    except ValueError as exc:
        raise InputFileError(f"{table.source}: {exc}") from None


def job_heights(job: MeasuredJob, source_file) -> tuple[np.ndarray, float, bool]:
    """``(z, L, periodic)`` of a job: the tile (or seeded surface) with its body."""
    if job.source == "topography":
        heights, length, _ = read_surface(source_file)
        n = heights.shape[0]
        tile = job.tile or n
        count = n // tile
        a, b = divmod(job.index, count)
        if not 0 <= job.index < count * count:
            raise IndentError(f"{job.describe()}: the scan has {count * count} tiles")
        z = heights[a * tile:(a + 1) * tile, b * tile:(b + 1) * tile]
        z = z - z.mean()
        size = length * tile / n
        periodic = False
    else:
        z = _spectrum_surface(job, source_file)
        size, tile = job.length, job.n
        periodic = job.kind == "flat"
    if job.kind == "sphere":
        z = z + paraboloid(tile, radius=job.radius, length=size)
    return z, size, periodic


def run_job(job: MeasuredJob, source_file, output) -> dict:
    """Solve one load path (:func:`roughcontact.study.runs.indent.solve_load_path`, the indent core)
    and write it to *output* (NetCDF, atomic); nothing is written on error.

    ``source_file``: the file of :func:`prepare_surface` (topography) or the spectrum table.
    Raises :class:`~roughcontact.errors.IndentError` when a body's contact reaches the outer
    ring of cells, or a solve does not converge.
    """
    from .indent import path_settings, solve_load_path

    z, length, periodic = job_heights(job, source_file)
    e = job.e_star
    normalized = job.forces_normalized()
    forces = normalized * e * length**2
    where = "the scan's edge" if job.source == "topography" else "the grid's edge"
    settings = path_settings(
        job, length=length, periodic=periodic,
        edge_hint=f"use a smaller radius or larger tiles (loads whose contact would reach {where})",
        edge_contact=job.kind == "flat" and not periodic)   # a flat free tile is a rough punch of side L
    scale_f, scale_k = _scales(job)
    out = solve_load_path(z, forces, settings, units=(scale_f / to_newtons(job.force_unit), job.force_unit,
                                                      scale_k, "N/m"))
    _write_run(job, output, out, normalized, length)
    return out


def _scales(job: MeasuredJob) -> tuple[float, float]:
    """N per (pressure unit * length unit²) and N/m per (pressure unit * length unit)."""
    return (to_pascals(job.pressure_unit) * to_metres(job.length_unit) ** 2,
            to_pascals(job.pressure_unit) * to_metres(job.length_unit))


def _write_run(job: MeasuredJob, output, out: dict, normalized, length: float) -> None:
    """The run file (:func:`roughcontact.study.files.runfile.write_run`) in physical units: force in N,
    stiffness in N/m, lengths in ``units.length``, with ``force_normalized``,
    ``stiffness_normalized`` and ``contact_area_fraction`` beside them."""
    scale_f, scale_k = _scales(job)
    unit = job.length_unit
    runfile.write_run(
        output, out, variables=quantities.variables(out), stiffness_method=job.stiffness_method,
        units={"force": (scale_f, "N"), "stiffness": (scale_k, "N m-1"), "depth": (1.0, unit),
               "contact_area": (1.0, f"{unit}2")},
        extra={"force_normalized": (normalized, {"long_name": "F/(E* L^2)", "units": "1"}),
               "stiffness_normalized": (out["stiffness"] / (job.e_star * length),
                                        {"long_name": "k/(E* L)", "units": "1", "coordinates": "force_normalized"}),
               "contact_area_fraction": (out["contact_area"] / length**2,
                                         {"long_name": "A/L^2", "units": "1", "coordinates": "force_normalized"})},
        coordinates=("force_normalized",),
        attrs=provenance.provenance_attrs(config=job.record(), kind="measured " + job.kind,
                                          length=length, e_star=job.e_star, e_star_units=job.pressure_unit,
                                          units_length=unit, half_space=_half_space(job)))


def _half_space(job: MeasuredJob) -> str:
    if job.source == "spectrum" and job.kind == "flat":
        return "periodic"
    return "free (non-periodic)" + (", rough punch of the tile's side" if job.kind == "flat" else "")


def run_order(study, source: str, name: str, count: int) -> list[tuple[float, int]]:
    """``(radius, tile or seed)`` of every run of one surface, in the order of its run files:
    radius by radius, then ``count`` tiles (topography) or the seeds (spectrum)."""
    study = StudySettings.of(study)
    members = range(count) if source == "topography" else study.seeds
    return [(float(r), int(i)) for r in study.radius for i in members]
