"""``roughcontact`` command line.

``roughcontact indent --hurst 0.7 --radius 0.5 --h-rms 9e-3 --seed 0 --n 513 -o run.nc``
runs one indentation (the same code as the Snakemake ``indent`` rule,
:func:`roughcontact.study.runs.indent.run_indent`) with a progress bar and writes the same
NetCDF file.  ``roughcontact measured scan.nc --unit um --tile 256 --radius 20 --e-star 100
--e-star-unit GPa -o tile0.nc`` presses one tile of a measured scan in physical units (the same
code as the Snakemake ``measured_surface`` and ``measured_indent`` rules) and writes the same
NetCDF file.  ``roughcontact check-config config.yaml`` validates a sweep
without running it; ``roughcontact list axes|models|claims`` prints what the registries hold.  Settings of ``indent`` not given on the command line come from ``--config``, else
from the defaults of the configuration schema (the same defaults as a sweep's).
"""
from __future__ import annotations

import argparse
import math
import os
import sys

from .errors import ConfigError, IndentError
from .study.config import resolve as config, schema
from .study.runs import indent, naming as runs
from .study.config.axes import AXES
from .study.registries import REGISTRIES, listing
from .study.config.measured import (FORCE_UNITS, LENGTH_UNITS, PRESSURE_UNITS, plain_unit, to_metres, to_newtons,
                                    to_pascals)
from .study.runs.jobs import JobSettings, job_settings
from .study.config.resolve import study_settings
from .study.config.stickiness import StickinessSettings
from .study.config.settings import StudySettings

#: ``--detrend`` of ``roughcontact measured`` (the config's ``topography[].detrend``)
_DETRENDS = ("height", "slope", "curvature", "center", "none")

#: config keys (:attr:`ConfigError.key`) -> the command-line flag of ``indent``, beside each
#: sweep axis's own (``'hurst[0]'`` -> ``--hurst``: :func:`_indent_flags`)
_FLAGS = {
    "seeds[0]": "--seed",
    "grid.n": "--n", "grid.length": "--length", "e_star": "--e-star", "solver.tol": "--tol",
    "solver.stiffness": "--stiffness", "solver.rel_step": "--rel-step", "solver.maxiter": "--maxiter",
    "forces.sphere.from": "--force-from", "forces.flat.from": "--force-from",
    "forces.sphere.to": "--force-to", "forces.flat.to": "--force-to",
    "forces.sphere.count": "--force-count", "forces.flat.count": "--force-count",
    "forces.sphere": "--force-from/--force-to", "forces.flat": "--force-from/--force-to",
}
#: number flags -> their config key; each must be finite (--radius may be inf: a flat surface); and
#: each sweep axis's flag -> its key (:func:`_number_flags`)
_NUMBER_FLAGS = {
    "length": ("grid", "length"),
    "e_star": ("e_star",), "force_from": ("forces", "{kind}", "from"), "force_to": ("forces", "{kind}", "to"),
    "tol": ("solver", "tol"), "rel_step": ("solver", "rel_step"),
}
#: config keys of ``roughcontact measured`` -> its flags (beside :data:`_FLAGS`)
_MEASURED_FLAGS = {
    "units.length": "--unit", "units.e_star": "--e-star-unit", "tile": "--tile", "e_star": "--e-star",
    "e_star.e1": "--e1", "e_star.nu1": "--nu1", "e_star.e2": "--e2", "e_star.nu2": "--nu2", "force_unit": "--force-unit",
    "topography[0].file": "SCAN", "topography[0].size": "--size", "topography[0].detrend": "--detrend",
}


def _indent_flags() -> dict:
    """:data:`_FLAGS` and every sweep axis's key -> flag (the registry, read when called)."""
    return {**{f"{a.name}[0]": a.flag for a in AXES.values()}, **_FLAGS}


def _number_flags() -> dict:
    """:data:`_NUMBER_FLAGS` and every sweep axis (the registry, read when called)."""
    return {**{a.name: (a.name, 0) for a in AXES.values()}, **_NUMBER_FLAGS}
#: the subcommands of :func:`build_parser`
COMMANDS = ("indent", "measured", "check-config", "list")


def _add_solver_options(parser, *, defaults: str) -> None:
    """The contact solver's options, shared by ``indent`` and ``measured`` (*defaults*: where an
    option not given comes from)."""
    parser.add_argument("--tol", type=float, default=None, help=f"solver tolerance (default: {defaults})")
    parser.add_argument("--stiffness", choices=["punch", "difference"], default=None, help="stiffness method")
    parser.add_argument("--rel-step", type=float, default=None, help="relative step of --stiffness difference")
    parser.add_argument("--maxiter", type=int, default=None, help="most solver iterations per load")


def _add_output_options(parser) -> None:
    """The output file and the log file, shared by ``indent`` and ``measured``."""
    parser.add_argument("-o", "--output", required=True, help="NetCDF file to write (atomically)")
    parser.add_argument("--log", default=None, help="also append progress lines to this file")


def build_parser() -> argparse.ArgumentParser:
    """The ``roughcontact`` argument parser (subcommands :data:`COMMANDS`)."""
    p = argparse.ArgumentParser(prog="roughcontact", description=plain_text(__doc__),
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)

    ind = sub.add_parser("indent", help="one rough-sphere (or flat, --radius inf) indentation -> NetCDF",
                         description="Press one rough sphere (finite --radius, free half-space) or one nominally "
                                     "flat surface (--radius inf, periodic) along a log-spaced load path and write "
                                     "depth, stiffness and contact area per load to a NetCDF file. Forces are "
                                     "F/(E* L^2).")
    for spec in AXES.values():  # one flag per sweep axis (roughcontact.study.config.axes)
        ind.add_argument(spec.flag, type=float, required=not spec.optional, default=None, help=spec.flag_help)
    ind.add_argument("--seed", type=int, default=0, help="random seed of the surface (default 0)")
    ind.add_argument("--n", type=int, default=None, help="grid points per side (default: config or schema)")
    ind.add_argument("--length", type=float, default=None, help="side length L (default: config or schema)")
    ind.add_argument("--e-star", type=float, default=None, help="effective modulus E* (default: config or schema)")
    ind.add_argument("--force-from", type=float, default=None, help="smallest F/(E* L^2)")
    ind.add_argument("--force-to", type=float, default=None, help="largest F/(E* L^2)")
    ind.add_argument("--force-count", type=int, default=None, help="number of log-spaced loads")
    _add_solver_options(ind, defaults="config or schema")
    ind.add_argument("--config", default=None, help="take grid, forces and solver settings from this config file")
    _add_output_options(ind)
    ind.add_argument("-q", "--quiet", action="store_true", help="no progress bar")

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
    _add_solver_options(mea, defaults="schema")
    _add_output_options(mea)
    mea.add_argument("-q", "--quiet", action="store_true", help="no progress lines")

    chk = sub.add_parser("check-config", help="validate a sweep config (exit 2 with one line if invalid)")
    chk.add_argument("config", help="YAML config file, e.g. config.yaml or presets/paper.yaml")

    lst = sub.add_parser("list", help="the registered sweep axes, models or claims, one per line",
                         description="Print what a registry holds, one per line: axes (name, unit, paper value), "
                                     "models (name, the optional axes it models, summary) or claims (letter, "
                                     "statement); --json: the same as a JSON list of objects.")
    lst.add_argument("registry", choices=REGISTRIES, help="which registry")
    lst.add_argument("--json", action="store_true", help="a JSON list of objects (name, and paper for axes)")
    return p


def _list(args) -> int:
    """``roughcontact list``: one line per registered item, or ``--json``."""
    import json

    items = listing(args.registry)
    if args.json:
        print(json.dumps(items, indent=1))
        return 0
    for item in items:
        if args.registry == "axes":
            paper = "(required)" if not item["optional"] else ("null" if item["paper"] is None else f"{item['paper']}")
            print(f"{item['name']}\tunit {item['unit']}\tpaper {paper}\t{item['role']}")
        elif args.registry == "models":
            print(f"{item['name']}\taxes {','.join(item['axes']) or '-'}\t{item['summary']}")
        else:
            print(f"{item['name']}\t{item['statement']}")
    return 0


def _check_numbers(args) -> None:
    """Every number flag finite (``--radius`` may be inf), by the rule of the
    config (:func:`roughcontact.study.config.schema.finite_error`); raises ConfigError."""
    loaded = schema.load_schema(None)
    kind = runs.kind_of(args.radius)
    for name, path in _number_flags().items():
        value = getattr(args, name)
        if value is None:
            continue
        path = [part.format(kind=kind) if isinstance(part, str) else part for part in path]
        err = schema.finite_error(path, value, loaded, allow_inf=name == "radius")
        if err is not None:
            raise err


def _mapping(value, path):
    """*value* if it is a mapping, else the ConfigError of --config's key *path*."""
    if not isinstance(value, dict):
        raise ConfigError(f"config key '{schema.key_text(path)}' = {schema.short_text(value)} is not allowed; "
                                 "allowed: a mapping", key=schema.key_text(path))
    return value


def settings_from_args(args) -> JobSettings:
    """Resolved job settings for ``roughcontact indent`` (raises ConfigError).

    The flags override ``--config``; what neither gives takes the schema's default
    (:func:`roughcontact.study.config.resolve.resolve_config`)."""
    _check_numbers(args)
    kind = runs.kind_of(args.radius)
    base = _mapping(config.load_config(args.config) if args.config else {}, [])
    grid = dict(_mapping(base.get("grid", {}), ["grid"]))
    for key, value in (("n", args.n), ("length", args.length)):
        if value is not None:
            grid[key] = value
    given = _mapping(_mapping(base.get("forces", {}), ["forces"]).get(kind, {}), ["forces", kind])
    forces = {**schema.default_of(schema.load_schema(None), ["forces", kind]), **given}
    for key, value in zip(("from", "to", "count"), (args.force_from, args.force_to, args.force_count)):
        if value is not None:
            forces[key] = value
    solver = dict(_mapping(base.get("solver", {}), ["solver"]))
    for key, value in (("tol", args.tol), ("stiffness", args.stiffness), ("rel_step", args.rel_step),
                       ("maxiter", args.maxiter)):
        if value is not None:
            solver[key] = value
    axes = {name: [getattr(args, name)] for name in AXES if getattr(args, name) is not None}
    cfg = {
        "grid": grid, "seeds": [args.seed], "solver": solver, "forces": {kind: forces}, **axes,
        **({"e_star": args.e_star} if args.e_star is not None else
           {"e_star": base["e_star"]} if "e_star" in base else {}),
        **({"fit": base["fit"]} if "fit" in base else {}),
    }
    study = study_settings(cfg)
    run = {**{name: getattr(study, name)[0] for name in AXES}, "seed": args.seed}
    return job_settings(study, run)


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


def _measured(args) -> int:
    """``roughcontact measured``: exit 0, 2 (bad input: one line, nothing written) or 1 (a solve failed)."""
    import logging
    import tempfile

    from .errors import DomainTooSmallError, InputFileError
    from .study.files import logs
    from .study.runs import measured

    def bad(message: str) -> int:
        print(f"roughcontact measured: invalid argument: {message}", file=sys.stderr)
        return 2

    try:
        study = measured_study_from_args(args)
    except ConfigError as err:
        return bad(_flagged(err, {**_indent_flags(), **_MEASURED_FLAGS}))
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

    from .study.runs import measured

    tile_length = float(measured.read_surface(surface)[2]["tile_length"])          # units.length
    unit_force = (study.e_star * to_pascals(study.units.e_star)
                  * (tile_length * to_metres(study.units.length)) ** 2)      # N per F/(E* L^2)
    kind = runs.kind_of(study.radius[0])
    given = study.forces[kind]
    scale = to_newtons(force_unit) / unit_force
    forces = {**study.forces, kind: dataclasses.replace(given, start=given.start * scale, stop=given.stop * scale)}
    return dataclasses.replace(study, forces=types.MappingProxyType(forces))


def _flagged(err: ConfigError, flags: dict | None = None) -> str:
    """The one line of a config error in the command line's words: the key it is about
    (:attr:`ConfigError.key`) named by its flag, e.g. ``--hurst (hurst[0]) = 3 is not allowed``."""
    flags = _indent_flags() if flags is None else flags
    message = str(err)
    flag = flags.get(err.key)
    if flag is None:
        return message
    return message.replace(f"config key '{err.key}'", f"{flag} ({err.key})", 1)


def plain_text(doc: str, width: int = 79) -> str:
    """*doc* (reST) as plain text for ``--help``: the double backquotes of literals and the roles
    (``:func:`` and the like) dropped, a role's target starting with a tilde shortened to its last
    name, each paragraph re-wrapped to *width* columns."""
    import re
    import textwrap

    text = re.sub(r":[a-z]+:`~?([^`]*)`", lambda m: m.group(1).rsplit(".", 1)[-1] if m.group(0).count("~")
                  else m.group(1), doc)
    text = re.sub(r"``([^`]*)``", r"\1", text)
    text = re.sub(r"`([^`]*)`", r"\1", text)
    paragraphs = [" ".join(par.split()) for par in text.strip().split("\n\n")]
    return "\n\n".join(textwrap.fill(par, width, break_on_hyphens=False) for par in paragraphs if par)


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    if args.command == "check-config":
        try:
            study = study_settings(config.load_config(args.config),
                                   base_dir=os.path.dirname(os.path.abspath(args.config)))
        except ConfigError as err:
            print(config.error_line(err), file=sys.stderr)
            return 2
        measured = ""
        if study.measured:
            measured = (f"; measured: {len(study.topography)} scan(s) x {len(study.radius)} radii x their tiles, "
                        f"{len(study.spectrum)} spectrum(s) x {len(study.radius)} radii x "
                        f"{len(study.seeds) if study.spectrum else 0} seeds")
        coarse = (f", and as many on the coarse grid {study.grid.coarse}² (grid.coarse)"
                  if study.grid.coarse is not None and study.generated else "")
        sticky = StickinessSettings.of(study)
        sticky = ("" if sticky is None else
                  f"; stickiness: {len(sticky.jobs())} runs ({len(sticky.hurst)} H x {len(sticky.number)} N x "
                  f"{sticky.seeds} seeds on {sticky.n}²)")
        print(f"{args.config}: valid; {len(runs.runs(study))} indent jobs "
              f"({len(runs.combinations(study))} (H, R, h_rms) x {len(study.seeds)} seeds){coarse}{measured}{sticky}")
        return 0
    if args.command == "measured":
        return _measured(args)
    if args.command == "list":
        return _list(args)
    try:
        settings = settings_from_args(args)
    except ConfigError as err:
        print(f"roughcontact indent: invalid argument: {_flagged(err)}", file=sys.stderr)
        return 2
    try:
        indent.run_indent(settings, args.output, log=args.log, progress=not args.quiet)
    except IndentError as err:
        print(f"roughcontact indent: FAILED: {err}", file=sys.stderr)
        return 1
    if not args.quiet:
        print(f"wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":  # python -m roughcontact.cli
    sys.exit(main())
