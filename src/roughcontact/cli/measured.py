"""``roughcontact measured``: one tile of a measured scan pressed in physical units (the same code as
the Snakemake ``measured_surface`` and ``measured_indent`` rules), the same NetCDF file."""
from __future__ import annotations

import math
import os
import sys

from ..errors import ConfigError, IndentError
from ..study.config import schema
from ..study.config.measured import (FORCE_UNITS, LENGTH_UNITS, PRESSURE_UNITS, plain_unit, to_metres, to_newtons,
                                     to_pascals)
from ..study.config.resolve import study_settings
from ..study.config.settings import StudySettings
from ..study.runs import naming as runs
from .common import add_output_options, add_solver_options, flagged, indent_flags, output_error

#: ``--detrend`` of ``roughcontact measured`` (the config's ``topography[].detrend``)
_DETRENDS = ("height", "slope", "curvature", "center", "none")

#: config keys of ``roughcontact measured`` -> its flags (beside :data:`roughcontact.cli.common.FLAGS`)
MEASURED_FLAGS = {
    "units.length": "--unit", "units.e_star": "--e-star-unit", "tile": "--tile", "e_star": "--e-star",
    "e_star.e1": "--e1", "e_star.nu1": "--nu1", "e_star.e2": "--e2", "e_star.nu2": "--nu2", "force_unit": "--force-unit",
    "topography[0].file": "SCAN", "topography[0].size": "--size", "topography[0].detrend": "--detrend",
}


def add_parser(sub) -> None:
    """The ``measured`` subcommand on the subparsers *sub* of :func:`roughcontact.cli.build_parser`."""
    mea = sub.add_parser(
        "measured", help="one tile of a measured scan under one sphere (or flat, --radius inf), physical units -> NetCDF",
        description="Read a measured scan (any format SurfaceTopography reads; needs the 'measured' extra), level "
                    "it, cut its largest centred square into --tile x --tile tiles and press tile --index under a "
                    "sphere of --radius (free half-space; inf = the tile as a nominally flat rough punch), as the "
                    "pipeline's measured_surface and measured_indent jobs do, and write the same NetCDF file. "
                    "Lengths (--radius, --size, the heights and depths) are in --unit, E* (--e-star, or --e1 and "
                    "--nu1 with --e2 and --nu2 of the counter-body) in --e-star-unit. The load path is given in "
                    "--force-unit (N, mN, uN, nN), or without it normalised, F/(E* L^2) with L the side of the tile "
                    "(as forces.sphere and forces.flat of a config); progress lines and the file give force in N "
                    "(or --force-unit) and stiffness in N/m beside force_normalized and stiffness_normalized = "
                    "k/(E* L). Bad input (missing or unreadable scan, "
                    "unknown unit, tile index out of range, loads whose contact would reach the scan's edge): one "
                    "line, exit status 2, nothing written.")
    mea.add_argument("scan", metavar="SCAN", help="the measured scan (e.g. .nc, .x3p, .sdf, .di, .opd)")
    mea.add_argument("--unit", required=True,
                     help=f"length unit of the study ({', '.join(LENGTH_UNITS)}; µm = um): of --radius, --size and "
                          "the outputs' lengths; the scan's heights are converted to it (read in it if the file "
                          "names no unit) (config: units.length)")
    mea.add_argument("--size", type=float, default=None,
                     help="physical side of the scan along x in --unit, for files that store none (default: the file's)")
    mea.add_argument("--detrend", default="height",
                     help=f"levelling of the whole scan: {', '.join(_DETRENDS)} (default height)")
    mea.add_argument("--interpolate", action="store_true",
                     help="resample a scan of non-square pixels onto square cells (default: such a scan is an error)")
    mea.add_argument("--tile", type=int, default=None,
                     help="side of the tiles in cells, >= 17 (default: the whole square as one tile) (config: tile)")
    mea.add_argument("--index", type=int, default=0,
                     help="the tile to press, row by row from 0 (default 0), as the pipeline's R<radius>_tile<i>.nc")
    mea.add_argument("--radius", type=float, required=True, help="sphere radius R in --unit; inf = nominally flat")
    mea.add_argument("--e-star", type=float, default=None,
                     help="effective modulus E* in --e-star-unit (or give --e1 and --nu1) (config: e_star)")
    mea.add_argument("--e1", type=float, default=None, help="Young's modulus of the scanned body in --e-star-unit")
    mea.add_argument("--nu1", type=float, default=None, help="Poisson ratio of the scanned body, -1 < nu1 <= 0.5")
    mea.add_argument("--e2", type=float, default=None,
                     help="Young's modulus of the counter-body in --e-star-unit (default: rigid); "
                          "1/E* = (1 - nu1^2)/e1 + (1 - nu2^2)/e2")
    mea.add_argument("--nu2", type=float, default=None, help="Poisson ratio of the counter-body (default 0)")
    mea.add_argument("--e-star-unit", required=True,
                     help=f"pressure unit of E*, --e1 and --e2: {', '.join(PRESSURE_UNITS)} (config: units.e_star)")
    mea.add_argument("--force-unit", default=None,
                     help=f"unit of --force-from and --force-to: {', '.join(FORCE_UNITS)} (µN = uN); also the unit of "
                          "the progress lines (default: the forces are F/(E* L^2), progress in N)")
    mea.add_argument("--force-from", type=float, default=None,
                     help="smallest force, in --force-unit or F/(E* L^2) with L the tile's side (default: "
                          "forces.sphere or forces.flat of the schema)")
    mea.add_argument("--force-to", type=float, default=None, help="largest force, as --force-from")
    mea.add_argument("--force-count", type=int, default=None, help="number of log-spaced loads")
    add_solver_options(mea, defaults="schema")
    add_output_options(mea)
    mea.add_argument("-q", "--quiet", action="store_true", help="no progress lines")


def measured_study_from_args(args) -> StudySettings:
    """The settings of ``roughcontact measured``: what the pipeline resolves for a config of this
    one scan and radius (:func:`roughcontact.study.config.resolve.study_settings`; raises
    ConfigError). The scan is ``topography[0]``; forces and solver settings not given take the
    schema's defaults."""
    unit = plain_unit(args.unit)
    if unit not in LENGTH_UNITS:
        raise ConfigError(f"config key 'units.length' = {args.unit!r} is not allowed; allowed: one of "
                          f"{', '.join(LENGTH_UNITS)}", key="units.length")
    if args.e_star_unit not in PRESSURE_UNITS:
        raise ConfigError(f"config key 'units.e_star' = {args.e_star_unit!r} is not allowed; allowed: one of "
                          f"{', '.join(PRESSURE_UNITS)}", key="units.e_star")
    if args.detrend not in _DETRENDS:
        raise ConfigError(f"config key 'topography[0].detrend' = {args.detrend!r} is not allowed; allowed: one of "
                          f"{', '.join(_DETRENDS)}", key="topography[0].detrend")
    if args.size is not None and not (math.isfinite(args.size) and args.size > 0):
        raise ConfigError(f"config key 'topography[0].size' = {args.size!r} is not allowed; allowed: a finite "
                          "number > 0", key="topography[0].size")
    bodies = {key: getattr(args, key) for key in ("e1", "nu1", "e2", "nu2") if getattr(args, key) is not None}
    if args.e_star is not None and bodies:
        raise ConfigError(f"config key 'e_star' is given twice: --e-star and {', '.join('--' + k for k in bodies)}; "
                          "allowed: --e-star, or --e1 and --nu1 (with --e2 and --nu2)", key="e_star")
    if args.e_star is None and not bodies:
        raise ConfigError("missing config key 'e_star'; allowed: --e-star, or --e1 and --nu1 (with --e2 and --nu2)",
                          key="e_star")
    if args.force_unit is not None:
        if plain_unit(args.force_unit) not in FORCE_UNITS:
            raise ConfigError(f"config key 'force_unit' = {args.force_unit!r} is not allowed; allowed: one of "
                              f"{', '.join(FORCE_UNITS)}", key="force_unit")
        if args.force_from is None or args.force_to is None:
            raise ConfigError("config key 'force_unit' needs --force-from and --force-to in that unit",
                              key="force_unit")
    path = os.path.abspath(os.path.expanduser(args.scan))
    if not os.path.isfile(path):
        raise ConfigError(f"config key 'topography[0].file' = {args.scan!r}: no such file ({path})",
                          key="topography[0].file")
    kind = runs.kind_of(args.radius)
    forces = dict(schema.default_of(schema.load_schema(None), ["forces", kind]))
    for key, value in zip(("from", "to", "count"), (args.force_from, args.force_to, args.force_count)):
        if value is not None:
            forces[key] = value
    solver = {key: value for key, value in (("tol", args.tol), ("stiffness", args.stiffness),
                                            ("rel_step", args.rel_step), ("maxiter", args.maxiter))
              if value is not None}
    entry = {"file": path, "detrend": args.detrend, "interpolate": bool(args.interpolate)}
    if args.size is not None:
        entry["size"] = args.size
    raw = {"units": {"length": unit, "e_star": args.e_star_unit}, "e_star": args.e_star if bodies == {} else bodies,
           "topography": [entry],
           "tile": args.tile, "hurst": [], "h_rms": [], "radius": [args.radius], "forces": {kind: forces},
           "solver": solver}
    return study_settings(raw, base_dir=os.getcwd())


def run(args) -> int:
    """``roughcontact measured``: exit 0, 2 (bad input: one line, nothing written) or 1 (a solve failed)."""
    import logging
    import tempfile

    from ..errors import DomainTooSmallError, InputFileError
    from ..study.files import logs
    from ..study.runs import measured

    def bad(message: str) -> int:
        print(f"roughcontact measured: invalid argument: {message}", file=sys.stderr)
        return 2

    refused = output_error(args.output)
    if refused is not None:
        return bad(refused)
    try:
        study = measured_study_from_args(args)
    except ConfigError as err:
        return bad(flagged(err, {**indent_flags(), **MEASURED_FLAGS}))
    entry = study.topography[0]
    handler = None
    if not args.quiet:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("%(message)s"))
        logging.getLogger("roughcontact").addHandler(handler)
        if logging.getLogger("roughcontact").getEffectiveLevel() > logging.INFO:
            logging.getLogger("roughcontact").setLevel(logging.INFO)
    try:
        with logs.log_to(args.log), tempfile.TemporaryDirectory(prefix="roughcontact-measured-") as tmp:
            surface = os.path.join(tmp, "surface.nc")
            try:
                measured.prepare_surface(entry, surface, length_unit=study.units.length, tile=study.tile)
            except InputFileError as err:
                return bad(err.reworded({"length": "--size"}))
            except ImportError as err:   # no SurfaceTopography: not the input's fault
                print(f"roughcontact measured: FAILED: {' '.join(str(err).split())}", file=sys.stderr)
                return 1
            if args.force_unit is not None:   # forces in a unit: F/(E* L^2) with L the tile's side
                study = _normalise_forces(study, surface, args.force_unit)
            count = measured.tile_count(surface)
            if not 0 <= args.index < count:
                return bad(f"--index {args.index}: the scan {os.path.basename(entry.file)} has {count} tile(s) "
                           f"of tile = {study.tile or 'the whole square'}; allowed: 0 <= --index <= {count - 1}")
            job = measured.job_of(study, "topography", entry.name, study.radius[0], args.index,
                                  force_unit=args.force_unit or "N")
            try:
                out = measured.run_job(job, surface, args.output)
            except IndentError as err:
                if isinstance(err.__context__, DomainTooSmallError):   # loads reaching the scan's edge
                    return bad(str(err).replace("forces.sphere.to", "--force-to"))
                print(f"roughcontact measured: FAILED: {err}", file=sys.stderr)
                return 1
    finally:
        if handler is not None:
            logging.getLogger("roughcontact").removeHandler(handler)
    if not args.quiet:
        scale = to_pascals(job.pressure_unit) * to_metres(job.length_unit)
        print(f"wrote {args.output}: k = {out['stiffness'][0] * scale:.4g} ... {out['stiffness'][-1] * scale:.4g} N/m",
              file=sys.stderr)
    return 0


def _normalise_forces(study: StudySettings, surface, force_unit: str) -> StudySettings:
    """*study* with its forces given in *force_unit* (as the settings hold them) as ``F/(E* L²)``,
    ``L`` the side of a tile of the prepared *surface* file."""
    import dataclasses
    import types

    from ..study.runs import measured

    tile_length = float(measured.read_surface(surface)[2]["tile_length"])          # units.length
    unit_force = (study.e_star * to_pascals(study.units.e_star)
                  * (tile_length * to_metres(study.units.length)) ** 2)      # N per F/(E* L^2)
    kind = runs.kind_of(study.radius[0])
    given = study.forces[kind]
    scale = to_newtons(force_unit) / unit_force
    forces = {**study.forces, kind: dataclasses.replace(given, start=given.start * scale, stop=given.stop * scale)}
    return dataclasses.replace(study, forces=types.MappingProxyType(forces))
