"""``roughcontact`` command line.

``roughcontact indent --hurst 0.7 --radius 0.5 --h-rms 9e-3 --seed 0 --n 513 -o run.nc``
runs one indentation (the same code as the Snakemake ``indent`` rule,
:func:`roughcontact.study.runs.indent.run_indent`) with a progress bar and writes the same
NetCDF file.  ``roughcontact measured scan.nc --unit um --tile 256 --radius 20 --e-star 100
--e-star-unit GPa -o tile0.nc`` presses one tile of a measured scan in physical units (the same
code as the Snakemake ``measured_surface`` and ``measured_indent`` rules) and writes the same
NetCDF file.  ``roughcontact check-config config.yaml`` validates a sweep
without running it; ``roughcontact list axes|models|area-models|claims|quantities`` prints what the registries hold.  Settings of ``indent`` not given on the command line come from ``--config``, else
from the defaults of the configuration schema (the same defaults as a sweep's).
"""
from __future__ import annotations

import argparse
import os
import sys

from ..errors import ConfigError, IndentError
from ..study.config import resolve as config, schema
from ..study.config.axes import AXES
from ..study.config.resolve import study_settings
from ..study.config.stickiness import StickinessSettings
from ..study.registries import REGISTRIES, listing
from ..study.runs import indent, naming as runs
from ..study.runs.jobs import JobSettings, job_settings
from . import measured
from .common import add_output_options, add_solver_options, flagged, output_error
from .measured import measured_study_from_args

__all__ = ["COMMANDS", "build_parser", "main", "measured_study_from_args", "plain_text", "settings_from_args"]

#: number flags -> their config key; each must be finite (--radius may be inf: a flat surface); and
#: each sweep axis's flag -> its key (:func:`_number_flags`)
_NUMBER_FLAGS = {
    "length": ("grid", "length"),
    "e_star": ("e_star",), "force_from": ("forces", "{kind}", "from"), "force_to": ("forces", "{kind}", "to"),
    "tol": ("solver", "tol"), "rel_step": ("solver", "rel_step"),
}
def _number_flags() -> dict:
    """:data:`_NUMBER_FLAGS` and every sweep axis (the registry, read when called)."""
    return {**{a.name: (a.name, 0) for a in AXES.values()}, **_NUMBER_FLAGS}
#: the subcommands of :func:`build_parser`
COMMANDS = ("indent", "measured", "check-config", "list")


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
    add_solver_options(ind, defaults="config or schema")
    ind.add_argument("--config", default=None, help="take grid, forces and solver settings from this config file")
    add_output_options(ind)
    ind.add_argument("-q", "--quiet", action="store_true", help="no progress bar")

    measured.add_parser(sub)

    chk = sub.add_parser("check-config", help="validate a sweep config (exit 2 with one line if invalid)")
    chk.add_argument("config", help="YAML config file, e.g. config.yaml or presets/paper.yaml")

    lst = sub.add_parser("list", help="the registered sweep axes, models, area models, claims or per-load "
                                      "quantities, one per line",
                         description="Print what a registry holds, one per line: axes (name, unit, paper value), "
                                     "models (name, the optional axes it models, summary), area-models (name, "
                                     "summary), claims (letter, statement) or quantities (name, units, the key "
                                     "that turns it on, long name); "
                                     "--json: the same as a JSON list of objects.")
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
        elif args.registry == "area-models":
            print(f"{item['name']}\t{item['summary']}")
        elif args.registry == "quantities":
            print(f"{item['name']}\tunits {item['units']}\ton {item['option'] or 'every run'}\t{item['long_name']}")
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
        scans = ""
        if study.measured:
            scans = (f"; measured: {len(study.topography)} scan(s) x {len(study.radius)} radii x their tiles, "
                     f"{len(study.spectrum)} spectrum(s) x {len(study.radius)} radii x "
                     f"{len(study.seeds) if study.spectrum else 0} seeds")
        spheres = sum(run["kind"] == "sphere" for run in runs.runs(study))
        coarse = (f", and {spheres} (the sphere runs) on the coarse grid {study.grid.coarse}² (grid.coarse)"
                  if study.grid.coarse is not None and study.generated and spheres else "")
        sticky = StickinessSettings.of(study)
        sticky = ("" if sticky is None else
                  f"; stickiness: {len(sticky.jobs())} runs ({len(sticky.hurst)} H x {len(sticky.number)} N x "
                  f"{sticky.seeds} seeds on {sticky.n}²)")
        blocks = len(runs.seed_blocks(study.seeds, study.jobs.batch)) if study.seeds else 0
        # the registered axes the sweep varies, each with its count of values
        swept = [f"{len(values)} {name}" for name, values in study.sweep if len(values) > 1]
        print(f"{args.config}: valid; {len(runs.runs(study))} runs "
              f"({len(runs.combinations(study))} combinations of {', '.join(swept) or 'the axes'} x "
              f"{len(study.seeds)} seeds) in "
              f"{len(runs.combinations(study)) * blocks} indent jobs (jobs.batch = {study.jobs.batch})"
              f"{coarse}{scans}{sticky}")
        return 0
    if args.command == "measured":
        return measured.run(args)
    if args.command == "list":
        return _list(args)
    refused = output_error(args.output)
    if refused is not None:
        print(f"roughcontact indent: invalid argument: {refused}", file=sys.stderr)
        return 2
    try:
        settings = settings_from_args(args)
    except ConfigError as err:
        print(f"roughcontact indent: invalid argument: {flagged(err)}", file=sys.stderr)
        return 2
    from .progress import progress_bar   # tqdm, imported when a bar is drawn

    try:
        indent.run_indent(settings, args.output, log=args.log, progress=False if args.quiet else progress_bar)
    except IndentError as err:
        print(f"roughcontact indent: FAILED: {err}", file=sys.stderr)
        return 1
    if not args.quiet:
        print(f"wrote {args.output}", file=sys.stderr)
    return 0
