"""One indentation job: the surface of a run, its warm-started load path, one NetCDF file.

What the ``indent`` rule (:mod:`roughcontact.study.rules.indent`: the runs of one combination and
block of seeds, ``jobs.batch``) and ``roughcontact indent`` call, :func:`run_indent`, with
:class:`~roughcontact.study.runs.jobs.JobSettings`. Imports numpy and the core at import time;
``netCDF4`` and ``tqdm`` where they are used, so the job starts quickly.
"""
from __future__ import annotations

import dataclasses
import logging

import numpy as np

from ... import bem, surfaces
from ...errors import DomainTooSmallError, IndentError
from .. import quantities
from ..files import provenance, runfile
from ..quantities.histograms import load_histograms
from . import tangential
from .path import LoadPath
from .jobs import JobSettings

__all__ = ["PathSettings", "solve_load_path", "solved_loads", "path_settings", "make_surface", "compute_run",
           "partial_path", "write_run", "run_indent"]

logger = logging.getLogger(__name__)


def make_surface(s: JobSettings) -> np.ndarray:
    """Heights of one run: a rough body of revolution, or a nominally flat surface; the axes
    act through their role (:meth:`JobSettings.arguments`), and an axis with a transform on the
    roughness heights before the body is added (:meth:`JobSettings.transforms`; without one,
    :func:`roughcontact.surfaces.rough_sphere` itself: the same bytes)."""
    roughness = {**s.arguments("roughness"), "realization_of": s.realization_of}
    transforms = s.transforms()
    if s.kind == "sphere" and not transforms:
        return surfaces.rough_sphere(s.n, radius=s.radius, length=s.length, seed=s.seed, **roughness,
                                     **s.arguments("body"))
    heights = surfaces.self_affine(s.n, length=s.length, seed=s.seed, **roughness)
    for transform, value in transforms:
        heights = np.asarray(transform(heights, value, s), dtype=float)
    if s.kind == "sphere":   # the body added as rough_sphere adds it (the sum is the same bytes)
        heights = heights + surfaces.body_of_revolution(s.n, radius=s.radius, length=s.length,
                                                        **{"exponent": 2.0, **s.arguments("body")})
    return heights


@dataclasses.dataclass(frozen=True)
class PathSettings:
    """How one load path is solved: what the generated and the measured jobs share.

    Attributes
    ----------
    length, e_star : float
        Side ``L`` of the heights' square and effective modulus ``E*`` (forces are reported as
        ``F/(E* L²)``, stiffnesses as ``k/(E* L)``).
    periodic, edge_contact : bool
        The half-space (:func:`roughcontact.bem.iter_load_path`); ``edge_contact``: a finite
        rough punch may touch its outer ring of cells.
    tol, maxiter, stiffness_method, rel_step :
        Solver and stiffness settings (:func:`roughcontact.bem.solve`, :func:`~roughcontact.bem.stiffness`).
    hardness : float or None
        Penetration hardness as a pressure (``None``: elastic): adds the loading tangent and the
        plastic cells (:mod:`roughcontact.study.quantities.plastic`).
    name : str
        The run, as error messages and progress lines name it.
    force_key : str
        The config key (or flag) of the largest force, named by error messages.
    edge_hint : str
        What to change when the contact reaches the edge of a free grid (after "lower
        <force_key> to <last good load> or below").
    patches : bool
        Count each load's contact patches (:mod:`roughcontact.study.quantities.patches`).
    quantities : tuple of str
        The opt-in per-load quantities kept (``fields.quantities``, :mod:`roughcontact.study.quantities`).
    field_loads : tuple of int
        Loads (0-based) whose contact fields are kept (:data:`~roughcontact.study.files.runfile.FIELD_VARIABLES`).
    histogram_loads : tuple of int
        Loads (0-based) whose pressure and gap histograms are kept, in *histogram_bins* bins
        (``fields.histograms``, :mod:`roughcontact.study.quantities.histograms`).
    histogram_bins : int
        Bins of each histogram (0 without histograms).
    poisson : float or None
        ``ν`` of the half-space (axis ``poisson``): every load also gets its full-stick tangential
        stiffness (:mod:`roughcontact.study.runs.tangential`); ``None``: none.
    friction : float
        Coulomb ``μ`` (axis ``friction``); ``> 0``: the loads *slip_loads* (0-based) also follow a
        partial-slip path of *slip_steps* tangential loads.
    """

    length: float
    e_star: float
    periodic: bool
    tol: float
    maxiter: int
    stiffness_method: str
    rel_step: float
    name: str
    force_key: str
    edge_hint: str = "use more cells (grid.n) on a larger grid.length"
    hardness: float | None = None
    edge_contact: bool = False
    patches: bool = False
    quantities: tuple = ()
    field_loads: tuple = ()
    histogram_loads: tuple = ()
    histogram_bins: int = 0
    poisson: float | None = None
    friction: float = 0.0
    slip_loads: tuple = ()
    slip_steps: int = 0


def solve_load_path(z: np.ndarray, forces: np.ndarray, p: PathSettings, progress=None, *,
                    units: tuple[float, str, float, str] | None = None) -> dict:
    """Solve the warm-started load path of heights *z* at *forces* (force units); return
    the per-load arrays of the quantities the run keeps (:func:`roughcontact.study.quantities.recorded`)
    and ``force``.

    The force-controlled path kind of :class:`~roughcontact.study.runs.path.LoadPath`: generated
    surfaces (:func:`compute_run`) and measured ones (:func:`roughcontact.study.runs.measured.run_job`)
    differ only in how they make ``z``. Each state is reduced to its numbers as soon as it is
    solved, so only two states are alive at a time. *progress*, if given, is called as
    ``progress(i, total, text)`` after each load; the same line goes to the log. *units*: ``(force scale, force unit,
    stiffness scale, stiffness unit)`` to add the load and stiffness in physical units to the
    progress lines (e.g. N and N/m).

    Raises :class:`~roughcontact.errors.IndentError` (naming the run, the load and what to
    change) when a solve does not converge, a stiffness is not positive or the contact
    reaches the edge of a free grid.
    """
    L, E = p.length, p.e_star
    total = len(forces)
    cell = L**2 / z.size
    out = {name: np.zeros(total, dtype=quantities.QUANTITIES[name].dtype) for name in quantities.recorded(p)}
    out["force"] = np.asarray(forces, dtype=float)
    if p.field_loads:
        out["fields"] = {}
    if p.histogram_loads:
        out["histograms"] = {}
    tangential.allocate(out, p, total)

    def record(i, state) -> str:
        _record(p, out, i, state, cell)
        words = (f"F/(E*L^2) = {forces[i] / (E * L**2):.3e}, iterations = {state.iterations}, "
                 f"contact cells = {out['contact_cells'][i]}, k/(E*L) = {out['stiffness'][i] / (E * L):.4e}")
        if units is not None:
            f_scale, f_unit, k_scale, k_unit = units
            words += f", F = {forces[i] * f_scale:.4g} {f_unit}, k = {out['stiffness'][i] * k_scale:.4g} {k_unit}"
        return words

    def edge(exc) -> str:   # the generator raises while solving load i = follow.done
        i = follow.done
        last = f"{forces[i - 1] / (E * L**2):.3g}" if i else "the first load"
        if i and units is not None:   # the last good load in the user's units too
            last += f" (F = {forces[i - 1] * units[0]:.4g} {units[1]})"
        return (f"indent {p.name}: the contact reached the edge of the free-space grid at {follow.where} "
                f"(F/(E*L^2) = {forces[i] / (E * L**2):.3g}); lower {p.force_key} to {last} or below or {p.edge_hint}")

    follow = LoadPath(p.name, total, record, progress=progress)
    path = bem.iter_load_path(z, forces, length=L, e_star=E, periodic=p.periodic, tol=p.tol, maxiter=p.maxiter,
                              hardness=p.hardness, edge_contact=p.edge_contact)
    try:
        with follow.failing(DomainTooSmallError, edge):
            for i, state in enumerate(path):
                follow(i, state)
    except IndentError as exc:   # the loads solved before travel with the error (run_indent keeps them)
        exc.solved = solved_loads(out, follow.done, total)
        raise
    return out


def solved_loads(out: dict, done: int, total: int) -> dict:
    """The per-load arrays of *out* (a path of *total* loads) cut to the first *done* loads: what a
    failed path keeps (the fields, histograms and partial-slip arrays, which need the whole path's
    layout, are left out)."""
    slip = {*runfile.SLIP_VARIABLES, "slip_load", "slip_step"}
    return {name: values[:done] for name, values in out.items()
            if name not in slip and isinstance(values, np.ndarray) and values.ndim == 1
            and values.shape[0] == total}


def compute_run(s: JobSettings, progress=None) -> dict:
    """Solve the load path of one generated run (:func:`make_surface`, :func:`solve_load_path`; an
    adhesive run, ``work_of_adhesion > 0``: :func:`roughcontact.study.runs.adhesive.adhesive_run`)."""
    logger.info("indent %s: %d loads F/(E*L^2) = %g ... %g, tol = %g, stiffness = %s", s.describe(), s.force_count,
                s.force_from, s.force_to, s.tol, s.stiffness_method)
    if s.work_of_adhesion > 0:   # adhesive: loaded to the forces, then retracted to pull-off
        from .adhesive import adhesive_run

        return adhesive_run(make_surface(s), s, name=s.describe(), progress=progress)
    return solve_load_path(make_surface(s), s.forces(), path_settings(s), progress)


def path_settings(s, **where) -> PathSettings:
    """The :class:`PathSettings` of a job record *s*, derived here once for every kind: its solver
    (``tol``, ``maxiter``, ``stiffness_method``, ``rel_step``), ``e_star``, name (``describe()``) and
    force key (``forces.<kind>.to``); a generated run's
    (:class:`~roughcontact.study.runs.jobs.JobSettings`) length, half-space and solver axes
    (:meth:`~roughcontact.study.runs.jobs.JobSettings.arguments`, e.g. the hardness). *where*: the
    fields a job record does not hold (a measured run's tile ``length``, ``periodic``,
    ``edge_hint``, ``edge_contact``)."""
    own = ({"length": s.length, "periodic": s.periodic, "patches": s.patches, "quantities": s.quantities,
            "field_loads": s.field_loads, "histogram_loads": s.histogram_loads, "histogram_bins": s.histogram_bins,
            "poisson": s.poisson, "friction": s.friction, "slip_loads": s.slip_loads, "slip_steps": s.slip_steps,
            **s.arguments("solver")} if isinstance(s, JobSettings) else {})
    return PathSettings(e_star=s.e_star, tol=s.tol, maxiter=s.maxiter, stiffness_method=s.stiffness_method,
                        rel_step=s.rel_step, name=s.describe(), force_key=f"forces.{s.kind}.to", **{**own, **where})


def _record(p: PathSettings, out: dict, i: int, state, cell: float) -> None:
    """Check one solved state and store its quantities (:data:`roughcontact.study.quantities.QUANTITIES`
    that the run keeps) at load *i* of *out*."""
    total = len(out["force"])
    fnorm = state.force / (p.e_star * p.length**2)
    where = f"load step {i + 1}/{total} (F/(E*L^2) = {fnorm:.3g}"
    if not state.converged:
        raise IndentError(
            f"indent {p.name}: the contact solver did not converge at {where}, {state.iterations} iterations, "
            f"tol = {p.tol:g}): {state.diagnosis or 'no diagnosis'}; raise solver.maxiter, loosen solver.tol, "
            f"use more cells (grid.n) or a smaller load ({p.force_key})"
        )
    load = quantities.Load(settings=p, index=i, total=total, where=where, cell=cell)
    for name in quantities.recorded(p):
        out[name][i] = quantities.QUANTITIES[name].compute(state, load)
    if i in p.histogram_loads:
        out["histograms"][i] = load_histograms(state, load, p.histogram_bins)
    if i in p.field_loads:
        out["fields"][i] = _fields(state, cell)
    tangential.record(p, out, i, state, where)


def _fields(state, cell: float) -> dict:
    """The pressure, gap and contact of *state* on the contact's window
    (:func:`roughcontact.bem.patches.contact_window`), with where the window starts."""
    from ...bem.patches import contact_window

    rows, cols = contact_window(state.contact)
    return {"pressure": state.pressure[rows, cols].copy(), "gap": state.gap()[rows, cols],
            "contact": state.contact[rows, cols].copy(), "row_start": rows.start, "column_start": cols.start,
            "cell_size": float(np.sqrt(cell)), "force": float(state.force)}


def partial_path(output) -> str:
    """Where a failed run keeps its solved loads: ``<output without .nc>.partial.nc`` (not an output
    of the rule, so a workflow neither deletes it nor takes it for the run)."""
    text = str(output)
    return (text[:-3] if text.endswith(".nc") else text) + ".partial.nc"


def write_run(path, s: JobSettings, out: dict, *, failure: str | None = None) -> None:
    """Write one generated run (:func:`roughcontact.study.files.runfile.write_run`) with provenance;
    *failure*: the loads of a run that failed at the next one, with the reason as the ``failure``
    attribute."""
    extra = {} if failure is None else {"failure": failure, "loads_solved": len(out["force"])}
    runfile.write_run(path, out, variables=quantities.variables(out), stiffness_method=s.stiffness_method,
                      scalars={name: getattr(s, name) for name in runfile.SCALARS},
                      attrs=provenance.provenance_attrs(
                          config=s.record(), kind=s.kind, seed=s.seed, grid_n=s.n, grid_length=s.length,
                          e_star=s.e_star, periodic=s.periodic, solver_tol=s.tol, solver_maxiter=s.maxiter,
                          stiffness_method=s.stiffness_method, stiffness_rel_step=s.rel_step,
                          force_normalized_from=s.force_from, force_normalized_to=s.force_to,
                          force_count=s.force_count, **s.axes(), **extra))


def run_indent(settings: JobSettings, output, log=None, progress=False) -> dict:
    """Compute one run and write it to *output* (NetCDF, atomic).

    *log*: a file that receives the ``roughcontact`` log lines (one per
    load step). *progress*: also draw a ``tqdm`` bar on stderr; or a function
    ``progress(total=..., desc=...)`` that builds the bar (the command line's,
    :func:`roughcontact.cli.progress.progress_bar`), which is given each load
    step's words as its postfix. Errors are logged before they propagate.
    """
    from ..files.logs import log_to

    desc = f"H={settings.hurst:g} R={settings.radius:g} seed={settings.seed}"
    if callable(progress):
        made = progress(total=settings.force_count, desc=desc)
    else:
        from tqdm.auto import tqdm

        made = tqdm(total=settings.force_count, disable=not progress, unit="load", desc=desc, dynamic_ncols=True)
    with log_to(log), made as bar:
        def advance(i, total, text):
            bar.set_postfix_str(text.split(": ", 1)[1], refresh=False)   # the bar fits it to its line
            bar.update(1)

        try:
            out = compute_run(settings, progress=advance)
            write_run(output, settings, out)
        except IndentError as exc:   # keep the loads solved before the failure beside the output
            logger.error("indent %s failed", settings.describe(), exc_info=True)
            solved = getattr(exc, "solved", None)
            if solved and len(solved["force"]):
                kept = partial_path(output)
                write_run(kept, settings, solved, failure=str(exc))
                exc.args = (f"{exc} (the {len(solved['force'])} loads solved before it: {kept})",)
            raise
        except Exception:   # the details for the log; the caller words the failure
            logger.error("indent %s failed", settings.describe(), exc_info=True)
            raise
        logger.info("wrote %s", output)
    return out
