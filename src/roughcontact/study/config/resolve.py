"""Configuration of the parameter study: resolution, cross-key checks, one-line errors.

:func:`resolve_config` normalises a raw config (as Snakemake or ``yaml``
loaded it), validates it against the package's schema (``config.schema.yaml``) plus
the checks a JSON schema cannot express, fills defaults and returns the
resolved config.  Every problem is reported as one line (:class:`ConfigError`)
naming the key, the value and what is allowed; :func:`error_line` is how the
workflow and ``roughcontact check-config`` print it.  Nothing here runs a job
(:mod:`roughcontact.study.runs.indent` does); ``jsonschema`` and ``yaml`` are imported
where they are used.

The generic schema machinery (finding and parsing the schema, coercing
command-line strings, wording errors, rejecting NaN and infinities, filling
defaults) is :mod:`roughcontact.study.config.schema`; errors are
:class:`roughcontact.errors.ConfigError`.

Cross-key checks
----------------
After the schema, :func:`resolve_config` requires an odd
``fit.slopes.window``; ``forces.sphere`` / ``forces.flat`` for the radii
listed, with ``from < to`` and forces within floating-point range; flat
surfaces pressed short of full contact (:func:`roughcontact.study.config.limits.full_contact_slope`); and a
smooth-body contact radius within L/4 of the free-space grid.  Each sweep axis brings its
own checks (:attr:`roughcontact.study.config.axes.Axis.check`): exponents other than every H,
roll-off and cutoff wavelengths that leave a self-affine band on the grid, hardnesses above
the fully plastic limit of the largest force.
"""
from __future__ import annotations

import copy
import math
import os
import sys

import numpy as np

from ...errors import ConfigError
from ...models import paper
from ...models.elasticity import effective_modulus
from .axes import AXES, kind_of
from .companions import coarse_config, default_coarse
from .limits import full_contact_slope
from .measured import resolve_inputs
from .records import force_grid
from .renamed import refuse_renamed
from .settings import StudySettings
from .coerce import coerce, read_numbers
from .schema import check_finite, fill_defaults, given_error, key_text, load_schema, printable, schema_error, short_text

__all__ = [
    "error_line",
    "load_config",
    "resolve_config",
    "study_settings",
]


def error_line(err: ConfigError) -> str:
    """The one line the workflow and ``roughcontact check-config`` print."""
    return f"Invalid configuration: {err}"


def load_config(path: str | os.PathLike) -> dict:
    """Read a YAML config file (no validation of its keys).

    Raises :class:`ConfigError` (one line naming the file) if the file cannot be read, is not
    YAML (the line and column of the problem named), is empty (nothing but blanks and comments)
    or holds something other than a mapping of config keys at its top level.
    """
    import yaml

    name = printable(str(path))
    try:
        with open(path, encoding="utf-8") as fh:
            data = yaml.safe_load(fh)
    except (OSError, UnicodeError) as err:
        raise ConfigError(f"cannot read config file {name}: "
                          f"{printable(getattr(err, 'strerror', None) or str(err))}") from err
    except (yaml.YAMLError, ValueError) as err:  # ValueError: an integer of more than 4300 digits
        mark = getattr(err, "problem_mark", None)
        where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark is not None else ""
        problem = getattr(err, "problem", None) or str(err)
        raise ConfigError(f"config file {name} is not valid YAML{where}: "
                          f"{printable(problem)}") from err
    if data is None:
        raise ConfigError(f"config file {name} is empty; allowed: a YAML mapping of config keys "
                          f"(hurst, radius, h_rms, seeds, ...)")
    if not isinstance(data, dict):
        kind = "a list" if isinstance(data, list) else f"the single value {short_text(data)}"
        raise ConfigError(f"config file {name} holds {kind}; allowed: a YAML mapping of config keys "
                          f"(key: value lines: hurst, radius, h_rms, seeds, ...)")
    return data


def resolve_config(raw: dict, schema=None, base_dir: str | os.PathLike | None = None) -> dict:
    """Validate and normalise a config; return the resolved copy.

    The grid-error companion (``grid.coarse``, absent: :func:`~.companions.default_coarse`) is
    resolved too: one it named that cannot press the sweep (e.g. a cutoff below two of its cells)
    is refused in one line naming ``grid.coarse``; a derived one is then left out (``null``).

    Raises :class:`ConfigError` with one line naming the offending key and
    what is allowed.  *schema* is a path or a loaded dict (default: the
    schema of the checkout).  *base_dir*: the directory of the config file, against which
    the relative paths of ``topography`` and ``spectrum`` are resolved (default: the current
    directory); the resolved config holds absolute paths
    (:func:`roughcontact.study.config.measured.resolve_inputs`).
    """
    grid = raw.get("grid") if isinstance(raw, dict) else None
    derived = not (isinstance(grid, dict) and "coarse" in grid)   # a bad grid fails the schema below
    cfg = _resolve(raw, schema, base_dir)
    if cfg["grid"].get("coarse") is not None and cfg.get("hurst") and any(math.isfinite(r) for r in cfg["radius"]):
        try:
            _resolve(coarse_config(cfg), schema, base_dir)
        except ConfigError as err:
            if not derived:
                raise ConfigError(f"config key 'grid.coarse' = {cfg['grid']['coarse']} is not allowed: its companion "
                                  f"study fails the checks ({err}); allowed: null or a finer grid.coarse",
                                  key="grid.coarse") from err
            cfg["grid"]["coarse"] = None   # the derived companion cannot press this sweep: no grid error
    return cfg


def _resolve(raw, schema, base_dir) -> dict:
    """:func:`resolve_config` of the study itself (not its companion)."""
    import jsonschema

    root = load_schema(schema)
    refuse_renamed(raw)   # an old key: one line naming its new name, before the schema's "unknown key"
    cfg = coerce(copy.deepcopy(raw))
    # JSON-schema bounds compare false against NaN: every number must be finite (radius may be +inf).
    # Keys the schema knows first (a NaN is the cause, not a duplicate or a bound) ...
    check_finite(cfg, root, known_only=True)
    validator = jsonschema.Draft202012Validator(root)
    errors = sorted(validator.iter_errors(cfg), key=lambda e: (len(e.absolute_path), key_text(list(e.absolute_path))))
    if errors:
        # report the shallowest problem first: an unknown top-level key explains more than its children;
        # a value made a one-element list is shown as given (seeds: six, not ['six'])
        raise given_error(errors[0], root, cfg, read_numbers(raw)) or schema_error(errors[0], root)
    # ... then everything, also below schema nodes that leave their contents open
    check_finite(cfg, root, known_only=False)
    fill_defaults(cfg, root, root)

    # normalise types
    cfg["grid"]["n"] = int(cfg["grid"]["n"])
    fine = cfg["grid"].get("realization_of")   # absent: the grid's own surfaces (resolved configs unchanged)
    if fine is not None and int(fine) < cfg["grid"]["n"]:
        raise ConfigError(f"config key 'grid.realization_of' = {fine} is not allowed; allowed: null or a grid of at "
                          f"least grid.n = {cfg['grid']['n']} points (the finer grid whose surfaces are pressed)",
                          key="grid.realization_of")
    if "coarse" not in cfg["grid"]:   # absent: the companion of half the resolution; null: none
        cfg["grid"]["coarse"] = default_coarse(cfg["grid"]["n"])
    coarse = cfg["grid"]["coarse"]
    if coarse is not None and int(coarse) >= cfg["grid"]["n"]:
        raise ConfigError(f"config key 'grid.coarse' = {coarse} is not allowed; allowed: null (no grid error) or a "
                          f"grid of fewer than grid.n = {cfg['grid']['n']} points (the same surfaces on a coarser "
                          f"grid; absent = (n + 1)/2 = {default_coarse(cfg['grid']['n'])})", key="grid.coarse")
    cfg["grid"]["length"] = float(cfg["grid"]["length"])
    if isinstance(cfg["e_star"], dict):   # the two bodies: E* of eq. 4.22 of Johnson (1985)
        bodies = cfg["e_star"]
        cfg["e_star"] = effective_modulus(bodies["e1"], bodies["nu1"], bodies.get("e2", math.inf),
                                          bodies.get("nu2", 0.0))
    cfg["e_star"] = float(cfg["e_star"])
    for axis in AXES.values():  # sorted floats, null (an optional axis's paper setting) first
        values = cfg.get(axis.name, [])   # hurst, h_rms: absent with measured inputs only
        if axis.in_units is not None:     # a value written with its unit, in the study's units
            values = [axis.in_units(v, cfg.get("units") or {}, f"{axis.name}[{i}]") for i, v in enumerate(values)]
        cfg[axis.name] = axis.normalise(values)
    if "seeds" in cfg:  # absent with measured scans only
        seeds = cfg["seeds"]
        cfg["seeds"] = list(range(int(seeds))) if isinstance(seeds, (int, float)) else sorted(int(s) for s in seeds)
    for rng in cfg["forces"].values():
        rng["from"], rng["to"], rng["count"] = float(rng["from"]), float(rng["to"]), int(rng["count"])

    # checks a JSON schema cannot express
    window = cfg["fit"]["slopes"]["window"]
    if window % 2 == 0:
        raise ConfigError(f"config key 'fit.slopes.window' = {window} is not allowed; allowed: an odd integer >= 3",
                          key="fit.slopes.window")
    resolve_inputs(cfg, base_dir)
    sticky = cfg.get("stickiness")
    if sticky is not None and sticky["cutoff"] > sticky["n"] / 2:
        raise ConfigError(f"config key 'stickiness.cutoff' = {sticky['cutoff']:g} cells is not allowed; allowed: "
                          f"2 <= cutoff <= stickiness.n/2 = {sticky['n'] / 2:g} (the shortest wavelength the grid "
                          "holds)", key="stickiness.cutoff")
    if bool(cfg["hurst"]) != bool(cfg["h_rms"]):
        empty = "hurst" if not cfg["hurst"] else "h_rms"
        raise ConfigError(f"config key '{empty}' is empty but '{'h_rms' if empty == 'hurst' else 'hurst'}' is not; "
                          "allowed: both empty (no generated surface) or both non-empty", key=empty)
    kinds = {kind_of(r) for r in cfg["radius"]}
    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
    for kind, rng in cfg["forces"].items():
        if not rng["from"] < rng["to"]:
            raise ConfigError(
                f"config key 'forces.{kind}': from = {rng['from']:g} must be smaller than to = {rng['to']:g}; "
                "allowed: 0 < from < to (forces F/(E* L^2))", key=f"forces.{kind}"
            )
        for end in ("from", "to"):
            force = rng[end] * cfg["e_star"] * length * length
            if not sys.float_info.min <= force <= sys.float_info.max:
                raise ConfigError(
                    f"config key 'forces.{kind}.{end}' = {rng[end]:g} gives a force F = {end} * e_star * "
                    f"grid.length^2 = {force:g}, outside the range of floating-point numbers; allowed: "
                    f"{sys.float_info.min:.3g} <= F <= {sys.float_info.max:.3g}", key=f"forces.{kind}.{end}"
                )
    _check_fields(cfg)
    _check_conductance(cfg)
    _check_fine_grid(cfg)
    if not cfg["hurst"]:  # measured inputs only: the checks of the generated surfaces do not apply
        return cfg
    if "flat" in kinds:
        slope = min(full_contact_slope(h, n, length) for h in cfg["hurst"]) * min(cfg["h_rms"])
        limit = 0.5 * slope
        if cfg["forces"]["flat"]["to"] >= limit:
            raise ConfigError(
                f"config key 'forces.flat.to' = {cfg['forces']['flat']['to']:g} would press the flat surfaces close to "
                f"full contact (rms slope ~ {slope:.3g} for H = {max(cfg['hurst']):g}, h_rms = {min(cfg['h_rms']):g}, "
                f"n = {n}); allowed: to < {limit:.3g}", key="forces.flat.to"
            )
    if "sphere" in kinds:
        to = cfg["forces"]["sphere"]["to"]
        for exponent in cfg["exponent"]:
            rmax = max(r for r in cfg["radius"] if math.isfinite(r))
            # smooth body (eq. 7 with H -> m): F ∝ a^(m+1), so a/L = (F/F(a = L))^(1/(m+1));
            # for m = 2 Hertz, a^3 = 3 F R / (4 E*). numpy floats: extreme sizes give inf or 0, no exception
            with np.errstate(all="ignore"):
                force_at_l = np.float64(paper.body_indentation(length, radius=rmax, e_star=1.0, exponent=exponent).force)
                force_to = np.float64(to) * np.float64(length) ** 2
                a_over_l = float((force_to / force_at_l) ** (1 / (exponent + 1)))
                limit = float(force_at_l * 0.25 ** (exponent + 1) / np.float64(length) ** 2)
            if a_over_l > 0.25:
                body = "Hertz" if exponent == 2 else f"smooth-body (m = {exponent:g})"
                raise ConfigError(
                    f"config key 'forces.sphere.to' = {to:g} gives a {body} contact radius of {a_over_l:.2f} L for "
                    f"R = {rmax:g}, too close to the edge of the free-space grid; allowed: to <= {limit:.3g} for this radius",
                    key="forces.sphere.to"
                )
    for axis in AXES.values():
        if axis.check is not None:
            axis.check(cfg, kinds)
    return cfg


def _check_fine_grid(cfg: dict) -> None:
    """``grid.fine``: a finer grid than ``n`` whose surfaces the study then presses (``grid.realization_of``
    resolved to it where absent; absent ``grid.fine``: nothing changes)."""
    grid = cfg["grid"]
    fine = grid.get("fine")
    if fine is None:
        if grid.get("fine_to") is not None:
            raise ConfigError(f"config key 'grid.fine_to' = {grid['fine_to']:g} needs grid.fine; allowed: null, or give "
                              "grid.fine (the finer grid of the small loads)", key="grid.fine_to")
        return
    grid["fine"] = fine = int(fine)
    if fine <= grid["n"]:
        raise ConfigError(f"config key 'grid.fine' = {fine} is not allowed; allowed: null or a grid of more than grid.n "
                          f"= {grid['n']} points (e.g. {2 * grid['n'] - 1}, twice as fine)", key="grid.fine")
    source = grid.get("realization_of")
    if source is not None and int(source) < fine:
        raise ConfigError(f"config key 'grid.realization_of' = {source} is not allowed with grid.fine = {fine}; allowed: "
                          f"null (the surfaces of grid.fine) or a grid of at least {fine} points", key="grid.realization_of")
    if not cfg["hurst"] or not any(math.isfinite(r) for r in cfg["radius"]):
        raise ConfigError(f"config key 'grid.fine' = {fine} needs generated sphere runs (hurst, h_rms and a finite "
                          "radius); allowed: null", key="grid.fine")
    grid["realization_of"] = fine if source is None else int(source)
    rng = cfg["forces"]["sphere"]
    if grid.get("fine_to") is None:   # the largest crossover of eq. 17 (zeta of eq. 13) of the sweep
        crossover = max(paper.crossover_force(r, hurst=h, h_rms=s, length=grid["length"], e_star=1.0,
                                              zeta=paper.zeta_estimate(h), exponent=m) / grid["length"] ** 2
                        for r in cfg["radius"] if math.isfinite(r) for h in cfg["hurst"] for s in cfg["h_rms"]
                        for m in cfg["exponent"])
        grid["fine_to"] = float(min(rng["to"], crossover))
    grid["fine_to"] = float(grid["fine_to"])
    second = float(force_grid(rng["from"], rng["to"], rng["count"])[1])
    if not second <= grid["fine_to"] <= rng["to"]:
        raise ConfigError(f"config key 'grid.fine_to' = {grid['fine_to']:g} is outside the spheres' load path; allowed: "
                          f"{second:.4g} (its second load) ... {rng['to']:g} (forces.sphere.to)", key="grid.fine_to")


def _check_fields(cfg: dict) -> None:
    """``fields``: kept by generated elastic and plastic runs, at loads within a load path; an opt-in
    quantity that only some run kinds give needs one of them in the sweep
    (:func:`roughcontact.study.quantities.missing`)."""
    from .. import quantities

    fields = cfg["fields"]
    given = [key for key in ("patches", "at", "quantities") if fields[key]]
    given += ["histograms"] if fields["histograms"]["at"] else []
    if not given:
        return
    key = f"fields.{given[0]}"
    if any(w > 0 for w in cfg.get("work_of_adhesion", []) if w is not None):
        raise ConfigError(f"config key '{key}' is not allowed with work_of_adhesion > 0; allowed: fields on "
                          "elastic or plastic runs (an adhesive run keeps its retract path instead)", key=key)
    if cfg.get("topography") or cfg.get("spectrum"):
        raise ConfigError(f"config key '{key}' is not allowed with measured inputs (topography, spectrum); allowed: "
                          "fields on the generated surfaces of a study without measured inputs", key=key)
    for i, name in enumerate(fields["quantities"]):
        lacks = quantities.missing(name, cfg)
        if lacks is not None:
            raise ConfigError(f"config key 'fields.quantities[{i}]' = {name!r} is kept by no run of this sweep: it "
                              f"needs {lacks}; allowed: remove it, or add such runs", key=f"fields.quantities[{i}]")
    kinds = {kind_of(r) for r in cfg["radius"]}
    ranges = {kind: cfg["forces"][kind] for kind in kinds}
    spans = ", ".join(f"forces.{kind} {r['from']:g} ... {r['to']:g}" for kind, r in ranges.items())
    for i, force in enumerate(fields["at"]):
        if not any(r["from"] <= force <= r["to"] for r in ranges.values()):
            raise ConfigError(f"config key 'fields.at[{i}]' = {force:g} is outside every load path; allowed: "
                              f"a force F/(E* L^2) within {spans}", key=f"fields.at[{i}]")
    for i, force in enumerate(fields["histograms"]["at"]):   # every kind's path reaches it: no run's is clipped
        if not all(r["from"] <= force <= r["to"] for r in ranges.values()):
            raise ConfigError(f"config key 'fields.histograms.at[{i}]' = {force:g} is outside a load path of the "
                              f"sweep; allowed: a force F/(E* L^2) within {spans}", key=f"fields.histograms.at[{i}]")


def _check_conductance(cfg: dict) -> None:
    """``conductance``: resistivities not both 0, and the units that make it physical."""
    section = cfg["conductance"]
    given = [key for key in ("resistivity", "conductivity") if section.get(key) is not None]
    if not given:
        return
    if section.get("resistivity") is not None and sum(section["resistivity"]) <= 0:
        raise ConfigError("config key 'conductance.resistivity' = [0, 0] is not allowed; allowed: two resistivities "
                          "(ohm m) >= 0, not both 0", key="conductance.resistivity")
    units = cfg.get("units") or {}
    needed = ["length"] + (["e_star"] if cfg.get("topography") or cfg.get("spectrum") else [])
    for unit in needed:
        if units.get(unit) is None:
            raise ConfigError(f"config key 'conductance.{given[0]}' needs units.{unit}; allowed: a conductance in "
                              f"physical units, with units.{unit} given", key=f"conductance.{given[0]}")


def study_settings(raw: dict, *, base_dir: str | os.PathLike | None = None) -> StudySettings:
    """Resolve a raw configuration (:func:`resolve_config`: one-line :class:`ConfigError` on bad
    input) and type it once (:class:`~roughcontact.study.config.settings.StudySettings`)."""
    return StudySettings.of(resolve_config(raw, base_dir=base_dir))
