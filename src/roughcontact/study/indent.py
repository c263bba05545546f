"""One indentation job: the surface of a run, its warm-started load path, one NetCDF file.

What the ``indent`` rule and ``roughcontact indent`` call with a
:class:`~roughcontact.study.settings.JobSettings`. Imports numpy and the core at import time;
``netCDF4`` and ``tqdm`` where they are used, so the job starts quickly.
"""
from __future__ import annotations

import logging
import time

import numpy as np

from .. import bem, surfaces
from ..errors import ConvergenceError, DomainTooSmallError, IndentError
from . import provenance, runfile
from .settings import JobSettings

__all__ = ["make_surface", "compute_run", "write_run", "run_indent"]

logger = logging.getLogger(__name__)


def make_surface(s: JobSettings) -> np.ndarray:
    """Heights of one run: a rough body of revolution, or a nominally flat surface; the axes
    act through their role (:meth:`JobSettings.arguments`)."""
    roughness = s.arguments("roughness")
    if s.kind == "flat":
        return surfaces.self_affine(s.n, length=s.length, seed=s.seed, **roughness)
    return surfaces.rough_sphere(s.n, radius=s.radius, length=s.length, seed=s.seed, **roughness,
                                 **s.arguments("body"))


def compute_run(s: JobSettings, progress=None) -> dict:
    """Solve the warm-started load path of one run; return arrays over force.

    Each state is reduced to its numbers (depth, stiffness, contact cells)
    as soon as it is solved, so only two states are alive at a time.
    *progress*, if given, is called as ``progress(i, total, text)`` after each
    load. Progress lines go to this module's logger.

    Raises :class:`~roughcontact.errors.IndentError` (naming the run and what to change)
    when a solve does not converge or the contact reaches the free-space grid edge.
    """
    L, E = s.length, s.e_star
    forces = s.forces()
    total = len(forces)
    z = make_surface(s)
    cell = (L / s.n) ** 2
    out = {name: np.zeros(total, dtype=runfile.VARIABLES[name].dtype)
           for name in runfile.RUN_VARIABLES + (runfile.PLASTIC_VARIABLES if s.value("hardness") is not None else ())}
    out["force"] = forces
    logger.info("indent %s: %d loads F/(E*L^2) = %g ... %g, tol = %g, stiffness = %s", s.describe(), total,
                s.force_from, s.force_to, s.tol, s.stiffness_method)
    path = bem.iter_load_path(z, forces, length=L, e_star=E, periodic=s.periodic, tol=s.tol, maxiter=s.maxiter,
                              **s.arguments("solver"))
    i = 0  # the load being solved: the generator raises while solving load i
    clock = time.perf_counter()
    try:
        for i, state in enumerate(path):
            _record(s, out, i, state, cell)
            now = time.perf_counter()
            text = (f"load step {i + 1}/{total}: F/(E*L^2) = {forces[i] / (E * L**2):.3e}, "
                    f"iterations = {state.iterations}, contact cells = {out['contact_cells'][i]}, "
                    f"k/(E*L) = {out['stiffness'][i] / (E * L):.4e}, {now - clock:.2f} s")
            clock = now
            logger.info(text)
            if progress is not None:
                progress(i + 1, total, text)
            i += 1  # the next load (enumerate sets it again when its state is solved)
    except DomainTooSmallError as exc:
        fnorm = forces[i] / (E * L**2)
        last = f"{forces[i - 1] / (E * L**2):.3g}" if i else "the first load"
        raise IndentError(
            f"indent {s.describe()}: the contact reached the edge of the free-space grid at load step "
            f"{i + 1}/{total} (F/(E*L^2) = {fnorm:.3g}); lower forces.sphere.to to {last} or below "
            f"or use more cells (grid.n) on a larger grid.length"
        ) from exc
    return out


def _record(s: JobSettings, out: dict, i: int, state, cell: float) -> None:
    """Check one solved state and store its numbers at load *i* of *out*."""
    total = len(out["force"])
    fnorm = state.force / (s.e_star * s.length**2)
    if not state.converged:
        raise IndentError(
            f"indent {s.describe()}: the contact solver did not converge at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}, {state.iterations} iterations, tol = {s.tol:g}); raise solver.maxiter, "
            f"loosen solver.tol, use more cells (grid.n) or a smaller load (forces.{s.kind}.to)"
        )
    try:
        k = bem.stiffness(state, method=s.stiffness_method, rel_step=s.rel_step)
    except (ConvergenceError, ValueError) as exc:
        other = "punch" if s.stiffness_method == "difference" else "difference"
        raise IndentError(
            f"indent {s.describe()}: the stiffness ({s.stiffness_method}) failed at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}): {exc}; try solver.stiffness = {other} or more cells (grid.n)"
        ) from exc
    cells = int(np.count_nonzero(state.contact))
    if not (np.isfinite(k) and k > 0):
        raise IndentError(
            f"indent {s.describe()}: non-positive stiffness k = {k!r} at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}, {cells} contact cells); raise forces.{s.kind}.from or grid.n"
        )
    out["depth"][i] = state.depth
    out["stiffness"][i] = k
    out["contact_cells"][i] = cells
    out["contact_area"][i] = cells * cell
    out["iterations"][i] = state.iterations
    out["converged"][i] = int(bool(state.converged))
    if "loading_stiffness" in out:  # with a hardness: the loading tangent along the plastic path too
        try:
            loading = bem.stiffness(state, method="loading", rel_step=s.rel_step)
        except (ConvergenceError, ValueError) as exc:
            raise IndentError(
                f"indent {s.describe()}: the loading stiffness failed at load step {i + 1}/{total} "
                f"(F/(E*L^2) = {fnorm:.3g}): {exc}; use more cells (grid.n) or a smaller load (forces.{s.kind}.to)"
            ) from exc
        if not (np.isfinite(loading) and loading > 0):
            raise IndentError(
                f"indent {s.describe()}: non-positive loading stiffness {loading!r} at load step {i + 1}/{total} "
                f"(F/(E*L^2) = {fnorm:.3g}); raise forces.{s.kind}.from or grid.n"
            )
        out["loading_stiffness"][i] = loading
        out["plastic_cells"][i] = int(np.count_nonzero(state.plastic))


def write_run(path, s: JobSettings, out: dict) -> None:
    """Write one run atomically (temp file, then rename) with provenance."""
    import netCDF4

    with provenance.atomic_path(path) as tmp:
        with netCDF4.Dataset(tmp, "w", format="NETCDF4") as nc:
            nc.setncatts(provenance.provenance_attrs(
                config=s.record(),
                title=runfile.TITLE,
                kind=s.kind,
                seed=s.seed,
                grid_n=s.n,
                grid_length=s.length,
                e_star=s.e_star,
                periodic=s.periodic,
                solver_tol=s.tol,
                solver_maxiter=s.maxiter,
                stiffness_method=s.stiffness_method,
                stiffness_rel_step=s.rel_step,
                force_normalized_from=s.force_from,
                force_normalized_to=s.force_to,
                force_count=s.force_count,
                **s.axes(),
            ))
            nc.createDimension("force", len(out["force"]))
            var = nc.createVariable("force", "f8", ("force",))
            var[:] = out["force"]
            var.setncatts(runfile.FORCE_ATTRS)
            for name, (dtype, long, units) in runfile.SCALARS.items():
                v = nc.createVariable(name, dtype, ())
                v.assignValue(getattr(s, name))
                v.setncatts({"long_name": long, "units": units})
            for name in (*runfile.RUN_VARIABLES, *(v for v in runfile.PLASTIC_VARIABLES if v in out)):
                meta = runfile.VARIABLES[name]
                long = f"{meta.long_name} ({s.stiffness_method})" if name == "stiffness" else meta.long_name
                v = nc.createVariable(name, meta.dtype, ("force",))
                v[:] = out[name]
                v.setncatts({"long_name": long, "units": meta.units, "coordinates": "hurst radius h_rms seed"})


def run_indent(settings: JobSettings, output, log=None, progress: bool = False) -> dict:
    """Compute one run and write it to *output* (NetCDF, atomic).

    *log*: a file that receives the ``roughcontact`` log lines (one per
    load step). *progress*: also draw a ``tqdm`` bar on stderr (the command
    line). Errors are logged before they propagate.
    """
    from tqdm.auto import tqdm

    from .logs import log_to

    with log_to(log), tqdm(total=settings.force_count, disable=not progress, unit="load",
                           desc=f"H={settings.hurst:g} R={settings.radius:g} seed={settings.seed}",
                           dynamic_ncols=True) as bar:
        def advance(i, total, text):
            bar.set_postfix_str(text.split(": ", 1)[1][:60], refresh=False)
            bar.update(1)

        out = compute_run(settings, progress=advance)
        write_run(output, settings, out)
        logger.info("wrote %s", output)
    return out
