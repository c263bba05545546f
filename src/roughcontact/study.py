"""The parameter study: run naming, job settings and one indentation job.

This module is what the Snakemake rules and the ``roughcontact`` command line
call with a resolved configuration (:mod:`roughcontact.config`).  It imports
only numpy (plus the core) at import time; the NetCDF writer (``netCDF4``) is
imported where it is used, so the ``indent`` job starts quickly.

Runs
----
One run is one (H, R, h_rms, seed).  ``radius = inf`` is a nominally flat
self-affine surface on the periodic half-space; a finite radius is a rough
sphere on the free (non-periodic) half-space.  :func:`job_settings` gives
everything one run needs, :func:`run_indent` computes it and writes one NetCDF
file atomically.
"""
from __future__ import annotations

import logging
import math
import re
import time

import numpy as np

from . import provenance

__all__ = [
    "IndentError",
    "format_value",
    "parse_value",
    "runs",
    "run_path",
    "run_paths",
    "combinations",
    "job_settings",
    "force_grid",
    "run_indent",
    "RUN_VARIABLES",
    "AXES",
    "kind_of",
]

#: variables of every run file (dimension ``force``)
RUN_VARIABLES = ("depth", "stiffness", "contact_area", "contact_cells", "iterations", "converged")
#: further variables of a run with a hardness (elastic runs: loading stiffness = stiffness, no plastic cell)
PLASTIC_VARIABLES = ("loading_stiffness", "plastic_cells")

RUN_DIR = "results/runs"

logger = logging.getLogger(__name__)

#: sweep axes of the runs of each surface kind, in the order of the merged
#: file's dimensions (then ``seed`` and ``force``); a flat surface has no
#: radius and no body exponent
AXES = {"sphere": ("hurst", "radius", "exponent", "h_rms", "rolloff", "cutoff", "hardness"),
        "flat": ("hurst", "h_rms", "rolloff", "cutoff", "hardness")}
#: the paper's setting of the optional axes: a paraboloid (m = 2), a spectrum from L
#: down to the grid (no roll-off, no cutoff), an elastic half-space. Runs with these
#: values have the names and settings they had before the axes existed.
DEFAULTS = {"exponent": 2.0, "rolloff": None, "cutoff": None, "hardness": None}
#: tag of each axis in a run's name, ``H0.7_R0.5_h0.009[_m4][_rolloff0.25][_cutoff0.01][_hardness0.01]``
TAGS = {"hurst": "H", "radius": "R", "h_rms": "h", "exponent": "_m", "rolloff": "_rolloff",
        "cutoff": "_cutoff", "hardness": "_hardness"}


class IndentError(RuntimeError):
    """A run that cannot produce trustworthy numbers (no convergence, or the
    contact reached the edge of the free-space grid)."""


# --------------------------------------------------------------------------
# runs and file names
# --------------------------------------------------------------------------
def format_value(x) -> str:
    """Text of a sweep value in a run name: shortest round-trip repr, ``inf``."""
    x = float(x)
    return "inf" if math.isinf(x) else repr(x)


def parse_value(text: str) -> float:
    return float(text)


def kind_of(radius) -> str:
    """``"sphere"`` for a finite radius (free half-space), ``"flat"`` for ``inf`` (periodic)."""
    return "sphere" if math.isfinite(radius) else "flat"


def coordinate(axis: str, value, length: float) -> float:
    """Value of a run's axis as a coordinate of the merged files: the paper's
    settings as numbers with the same meaning (rolloff null = the system size L,
    cutoff null = 0, i.e. no short wavelength removed, hardness null = inf, elastic)."""
    if value is None:
        return {"rolloff": float(length), "cutoff": 0.0, "hardness": math.inf}[axis]
    return float(value)


def combinations(cfg: dict) -> list[dict]:
    """One dict per (H, R, h_rms and the optional axes) in sweep order; flat
    surfaces (R = inf) take only the default body exponent (they have no body)."""
    out = []
    for hurst in cfg["hurst"]:
        for radius in cfg["radius"]:
            exponents = cfg.get("exponent", [DEFAULTS["exponent"]]) if math.isfinite(radius) else [DEFAULTS["exponent"]]
            for exponent in exponents:
                for h_rms in cfg["h_rms"]:
                    for rolloff in cfg.get("rolloff", [None]):
                        for cutoff in cfg.get("cutoff", [None]):
                            for hardness in cfg.get("hardness", [None]):
                                out.append({"hurst": hurst, "radius": radius, "exponent": exponent, "h_rms": h_rms,
                                            "rolloff": rolloff, "cutoff": cutoff, "hardness": hardness,
                                            "kind": kind_of(radius)})
    return out


def runs(cfg: dict) -> list[dict]:
    """One dict per run: the axes of :func:`combinations`, ``seed`` and ``kind``."""
    return [{**combo, "seed": seed} for combo in combinations(cfg) for seed in cfg["seeds"]]


def combo_name(run: dict) -> str:
    """Name of a run's (H, R, h_rms, ...) directory: ``H0.7_R0.5_h0.009``, plus a tag
    for every optional axis off its default (``_m4``, ``_rolloff0.25``, ...)."""
    name = "_".join(f"{TAGS[a]}{format_value(run[a])}" for a in ("hurst", "radius", "h_rms"))
    for axis, default in DEFAULTS.items():
        if run.get(axis, default) != default:
            name += f"{TAGS[axis]}{format_value(run[axis])}"
    return name


_COMBO = re.compile(r"H(?P<hurst>[^_/]+)_R(?P<radius>[^_/]+)_h(?P<h_rms>[^_/]+?)"
                    + "".join(rf"(?:{TAGS[a]}(?P<{a}>[^_/]+?))?" for a in DEFAULTS) + "$")


def parse_combo(name: str) -> dict:
    """The axes of a run directory name (:func:`combo_name`); ``ValueError`` if it is not one."""
    match = _COMBO.match(name)
    if not match:
        raise ValueError(f"{name!r} is not a run name like H0.7_R0.5_h0.009[_m4][_rolloff0.25]...")
    out = {axis: parse_value(match.group(axis)) for axis in ("hurst", "radius", "h_rms")}
    for axis, default in DEFAULTS.items():
        text = match.group(axis)
        out[axis] = default if text is None else parse_value(text)
    return out


RUN_PATTERN = RUN_DIR + "/{combo}/seed{seed}.nc"
LOG_PATTERN = "logs/indent/{combo}_seed{seed}.log"
#: Snakemake's per-job benchmark (wall seconds, peak RSS ``max_rss`` in MB) of each run
BENCHMARK_PATTERN = "results/benchmarks/indent/{combo}_seed{seed}.tsv"


def run_path(run: dict, pattern: str = RUN_PATTERN) -> str:
    """Path of one run (a dict of :func:`runs`) after *pattern*."""
    return pattern.format(combo=combo_name(run), seed=int(run["seed"]))


def parse_run_path(path: str) -> dict:
    """The axes and seed of a run file's path (inverse of :func:`run_path`)."""
    parts = str(path).replace("\\", "/").split("/")
    match = re.fullmatch(r"seed(\d+)\.nc", parts[-1])
    if len(parts) < 2 or not match:
        raise ValueError(f"{path!r} is not a run file path like {RUN_PATTERN}")
    return {**parse_combo(parts[-2]), "seed": int(match.group(1))}


def run_paths(cfg: dict) -> list[str]:
    return [run_path(r) for r in runs(cfg)]


def force_grid(rng: dict) -> np.ndarray:
    """Log-spaced F/(E* L^2) of a force range ``{from, to, count}``."""
    return np.geomspace(rng["from"], rng["to"], int(rng["count"]))


def job_settings(cfg: dict, run: dict) -> dict:
    """Everything one run (a dict of :func:`runs`) depends on, and nothing else,
    so that adding a seed or a sweep value does not invalidate finished runs.
    Optional axes at their default (:data:`DEFAULTS`) are left out, so such a
    run has the settings (and the hash) it had before the axes existed."""
    radius = float(run["radius"])
    kind = kind_of(radius)
    rng = cfg["forces"][kind]
    settings = {
        "hurst": float(run["hurst"]),
        "radius": radius,
        "h_rms": float(run["h_rms"]),
        "seed": int(run["seed"]),
        "kind": kind,
        "periodic": kind == "flat",
        "n": cfg["grid"]["n"],
        "length": cfg["grid"]["length"],
        "e_star": cfg["e_star"],
        "forces": {"from": rng["from"], "to": rng["to"], "count": rng["count"]},
        "tol": cfg["solver"]["tol"],
        "stiffness": cfg["solver"]["stiffness"],
        "rel_step": cfg["solver"].get("rel_step", 1e-3),
        "maxiter": cfg["solver"].get("maxiter"),
    }
    for axis, default in DEFAULTS.items():
        value = run.get(axis, default)
        if value != default:
            settings[axis] = float(value)
    return settings


def indent_resources(cfg: dict) -> dict:
    """Generous per-job estimates for schedulers (SLURM): ``mem_mb`` and
    ``runtime`` (minutes) of one ``indent`` job, from the grid and load count.

    Memory: surface generation (24 bytes per cell), the heights and two states
    alive at a time (pressure, contact set: ~17 bytes per cell each), FFT
    kernels up to the doubled grid, over a ~250 MB interpreter; times 1.5.
    Runtime: measured ~10 s for a 513^2 flat run of 13 loads on one core,
    scaled by n^2 log n and the load count, times 10.
    """
    n = cfg["grid"]["n"]
    count = max(r["count"] for r in cfg["forces"].values())
    mem = 250 + (n * n * (24 + 8 + 2 * 17) + 8 * (2 * n) ** 2 * 16) / 1e6
    scale = (n * n * math.log(n)) / (513 * 513 * math.log(513)) * count / 13
    return {"mem_mb": int(math.ceil(1.5 * mem / 100) * 100), "runtime": int(max(5, math.ceil(10 * scale * 10 / 60)))}


def settings_from_wildcards(cfg: dict, wildcards) -> dict:
    return job_settings(cfg, {**parse_combo(wildcards.combo), "seed": int(wildcards.seed)})


def describe_run(s: dict) -> str:
    r = "inf (flat, periodic)" if not math.isfinite(s["radius"]) else f"{s['radius']:g}"
    extra = "".join(f", {axis} = {s[axis]:g}" for axis in DEFAULTS if axis in s)
    return f"H = {s['hurst']:g}, R = {r}, h_rms = {s['h_rms']:g}{extra}, seed = {s['seed']}, n = {s['n']}"


# --------------------------------------------------------------------------
# one indentation
# --------------------------------------------------------------------------
def make_surface(s: dict) -> np.ndarray:
    """Heights of one run: a rough body of revolution, or a nominally flat surface."""
    from . import surfaces

    spectrum = {"rolloff": s.get("rolloff"), "cutoff": s.get("cutoff")}
    if s["kind"] == "flat":
        return surfaces.self_affine(s["n"], hurst=s["hurst"], h_rms=s["h_rms"], length=s["length"], seed=s["seed"],
                                    **spectrum)
    return surfaces.rough_sphere(s["n"], radius=s["radius"], hurst=s["hurst"], h_rms=s["h_rms"],
                                 length=s["length"], seed=s["seed"], exponent=s.get("exponent", 2.0), **spectrum)


def compute_run(s: dict, progress=None) -> dict:
    """Solve the warm-started load path of one run; return arrays over force.

    Each state is reduced to its numbers (depth, stiffness, contact cells)
    as soon as it is solved, so only two states are alive at a time.
    *progress*, if given, is called as ``progress(i, total, text)`` after each
    load. Progress lines go to the ``roughcontact.study`` logger.

    Raises :class:`IndentError` (naming the run and what to change) when a
    solve does not converge or the contact reaches the free-space grid edge.
    """
    from . import contact

    L, E, n = s["length"], s["e_star"], s["n"]
    forces = force_grid(s["forces"]) * E * L**2
    total = len(forces)
    z = make_surface(s)
    cell = (L / n) ** 2
    out = {name: np.zeros(total) for name in ("depth", "stiffness", "contact_area")}
    out.update({name: np.zeros(total, dtype=np.int64) for name in ("contact_cells", "iterations", "converged")})
    hardness = s["hardness"] * E if "hardness" in s else None
    if hardness is not None:
        out.update(loading_stiffness=np.zeros(total), plastic_cells=np.zeros(total, dtype=np.int64))
    out["force"] = forces
    logger.info("indent %s: %d loads F/(E*L^2) = %g ... %g, tol = %g, stiffness = %s", describe_run(s), total,
             s["forces"]["from"], s["forces"]["to"], s["tol"], s["stiffness"])
    extra = {"maxiter": int(s["maxiter"])} if s.get("maxiter") else {}
    path = contact.iter_load_path(z, forces, length=L, e_star=E, periodic=s["periodic"], tol=s["tol"],
                                  hardness=hardness, **extra)
    i = 0
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
    except contact.DomainTooSmallError as exc:
        fnorm = forces[i] / (E * L**2)
        raise IndentError(
            f"indent {describe_run(s)}: the contact reached the edge of the free-space grid at load step "
            f"{i + 1}/{total} (F/(E*L^2) = {fnorm:.3g}); lower forces.sphere.to below {fnorm:.3g} "
            f"or use more cells (grid.n) on a larger grid.length"
        ) from exc
    return out


def _record(s: dict, out: dict, i: int, state, cell: float) -> None:
    """Check one solved state and store its numbers at load *i* of *out*."""
    from . import contact

    total = len(out["force"])
    fnorm = state.force / (s["e_star"] * s["length"] ** 2)
    if not state.converged:
        raise IndentError(
            f"indent {describe_run(s)}: the contact solver did not converge at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}, {state.iterations} iterations, tol = {s['tol']:g}); raise solver.maxiter, "
            f"loosen solver.tol, use more cells (grid.n) or a smaller load (forces.{s['kind']}.to)"
        )
    try:
        if s["stiffness"] == "difference":
            k = contact.stiffness(state, method="difference", rel_step=s["rel_step"])
        else:
            k = contact.stiffness(state)
    except (RuntimeError, ValueError) as exc:
        raise IndentError(
            f"indent {describe_run(s)}: the stiffness ({s['stiffness']}) failed at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}): {exc}; try solver.stiffness = "
            f"{'punch' if s['stiffness'] == 'difference' else 'difference'} or more cells (grid.n)"
        ) from exc
    cells = int(np.count_nonzero(state.contact))
    if not (np.isfinite(k) and k > 0):
        raise IndentError(
            f"indent {describe_run(s)}: non-positive stiffness k = {k!r} at load step {i + 1}/{total} "
            f"(F/(E*L^2) = {fnorm:.3g}, {cells} contact cells); raise forces.{s['kind']}.from or grid.n"
        )
    out["depth"][i] = state.depth
    out["stiffness"][i] = k
    out["contact_cells"][i] = cells
    out["contact_area"][i] = cells * cell
    out["iterations"][i] = state.iterations
    out["converged"][i] = int(bool(state.converged))
    if "loading_stiffness" in out:  # with a hardness: the loading tangent along the plastic path too
        out["loading_stiffness"][i] = contact.stiffness(state, method="loading", rel_step=s["rel_step"])
        out["plastic_cells"][i] = int(np.count_nonzero(state.plastic))


def write_run(path, s: dict, out: dict) -> None:
    """Write one run atomically (temp file, then rename) with provenance."""
    import netCDF4

    with provenance.atomic_path(path) as tmp:
        with netCDF4.Dataset(tmp, "w", format="NETCDF4") as nc:
            attrs = provenance.provenance_attrs(
                config=s,
                title="roughcontact indentation run",
                kind=s["kind"],
                seed=s["seed"],
                grid_n=s["n"],
                grid_length=s["length"],
                e_star=s["e_star"],
                periodic=s["periodic"],
                solver_tol=s["tol"],
                stiffness_method=s["stiffness"],
                stiffness_rel_step=s["rel_step"],
                force_normalized_from=s["forces"]["from"],
                force_normalized_to=s["forces"]["to"],
                force_count=s["forces"]["count"],
                **{f"{axis}": s[axis] for axis in DEFAULTS if axis in s},
            )
            nc.setncatts(attrs)
            nc.createDimension("force", len(out["force"]))
            var = nc.createVariable("force", "f8", ("force",))
            var[:] = out["force"]
            var.setncatts({"long_name": "normal force F", "units": "e_star * length**2 (F/(E* L^2) = force / that)"})
            for name, value, long in (
                ("hurst", s["hurst"], "Hurst exponent H"),
                ("radius", s["radius"], "sphere radius R (inf: nominally flat, periodic)"),
                ("h_rms", s["h_rms"], "rms roughness height"),
            ):
                v = nc.createVariable(name, "f8", ())
                v.assignValue(value)
                v.setncatts({"long_name": long, "units": "length" if name != "hurst" else "1"})
            v = nc.createVariable("seed", "i8", ())
            v.assignValue(s["seed"])
            v.long_name = "random seed of the surface"
            meta = {
                "depth": ("f8", "indentation depth from first touch", "length"),
                "stiffness": ("f8", f"normal contact stiffness dF/dd ({s['stiffness']})", "e_star * length"),
                "contact_area": ("f8", "contact area (contact cells * (L/n)^2)", "length**2"),
                "contact_cells": ("i8", "number of grid cells in contact", "1"),
                "iterations": ("i8", "solver iterations (warm-started from the previous load)", "1"),
                "converged": ("i1", "solver converged (1) or not (0)", "1"),
                "loading_stiffness": ("f8", "loading tangent dF/dd along the plastic path (forward quotient, "
                                            "solver.rel_step); stiffness is the unloading one", "e_star * length"),
                "plastic_cells": ("i8", "number of grid cells that flowed (pressure at the hardness)", "1"),
            }
            for name in (*RUN_VARIABLES, *(v for v in PLASTIC_VARIABLES if v in out)):
                dtype, long, units = meta[name]
                v = nc.createVariable(name, dtype, ("force",))
                v[:] = out[name]
                v.setncatts({"long_name": long, "units": units, "coordinates": "hurst radius h_rms seed"})


def run_indent(settings: dict, output, log=None, progress: bool = False) -> dict:
    """Compute one run and write it to *output* (NetCDF, atomic).

    *log*: a file that receives the ``roughcontact`` log lines (one per
    load step). *progress*: also draw a ``tqdm`` bar on stderr (the command
    line). Errors are logged before they propagate.
    """
    from tqdm.auto import tqdm

    from .logs import log_to

    with log_to(log), tqdm(total=int(settings["forces"]["count"]), disable=not progress, unit="load",
                                desc=f"H={settings['hurst']:g} R={settings['radius']:g} seed={settings['seed']}",
                                dynamic_ncols=True) as bar:
        def advance(i, total, text):
            bar.set_postfix_str(text.split(": ", 1)[1][:60], refresh=False)
            bar.update(1)

        out = compute_run(settings, progress=advance)
        write_run(output, settings, out)
        logger.info("wrote %s", output)
    return out
