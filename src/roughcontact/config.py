"""Configuration of the parameter study: schema, defaults, checks, one-line errors.

:func:`resolve_config` normalises a raw config (as Snakemake or ``yaml``
loaded it), validates it against ``workflow/schemas/config.schema.yaml`` plus
the checks a JSON schema cannot express, fills defaults and returns the
resolved config.  Every problem is reported as one line (:class:`ConfigError`)
naming the key, the value and what is allowed; :func:`error_line` is how the
workflow and ``roughcontact check-config`` print it.  Nothing here runs a job
(:mod:`roughcontact.study` does); ``jsonschema`` and ``yaml`` are imported
where they are used.

Numbers must be finite (:func:`roughcontact._validate.is_finite_number`):
JSON-schema bounds compare false against NaN, so after the schema a walk over
the whole config rejects every NaN and infinity, except ``+inf`` where the
schema node carries ``x-allow-inf: true`` (the radius items: a nominally flat
surface).  New keys of the schema are covered without further code.
"""
from __future__ import annotations

import copy
import functools
import json
import math
import numbers
import os
import sys
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from . import _validate, theory

__all__ = [
    "ConfigError",
    "error_line",
    "find_schema",
    "finite_error",
    "full_contact_slope",
    "load_config",
    "resolve_config",
]

#: schema annotation: this number may be ``+inf`` (no other non-finite value is ever allowed)
ALLOW_INF = "x-allow-inf"


class ConfigError(ValueError):
    """An invalid configuration; ``str(err)`` is one line naming the key."""


def error_line(err: ConfigError) -> str:
    """The one line the workflow and ``roughcontact check-config`` print."""
    return f"Invalid configuration: {err}"


# --------------------------------------------------------------------------
# configuration
# --------------------------------------------------------------------------
SCHEMA_RELPATH = Path("workflow/schemas/config.schema.yaml")


def find_schema(start: str | os.PathLike | None = None) -> Path:
    """Locate ``workflow/schemas/config.schema.yaml``: above *start* (a file or
    directory), the current directory, or the checkout holding this module."""
    candidates = []
    for base in (start, Path.cwd(), Path(__file__).resolve()):
        if base is None:
            continue
        base = Path(base).resolve()
        candidates += [base, *base.parents]
    for base in candidates:
        path = base / SCHEMA_RELPATH
        if path.is_file():
            return path
    raise FileNotFoundError(f"cannot find {SCHEMA_RELPATH} (run from the roughcontact checkout)")


def load_config(path: str | os.PathLike) -> dict:
    """Read a YAML config file (no validation).

    Raises :class:`ConfigError` (one line) if the file cannot be read or is
    not YAML.
    """
    import yaml

    try:
        with open(path, encoding="utf-8") as fh:
            data = yaml.safe_load(fh)
    except (OSError, UnicodeError) as err:
        raise ConfigError(f"cannot read config file {_printable(str(path))}: "
                          f"{_printable(getattr(err, 'strerror', None) or str(err))}") from err
    except (yaml.YAMLError, ValueError) as err:  # ValueError: an integer of more than 4300 digits
        mark = getattr(err, "problem_mark", None)
        where = f" (line {mark.line + 1}, column {mark.column + 1})" if mark is not None else ""
        problem = getattr(err, "problem", None) or str(err)
        raise ConfigError(f"config file {_printable(str(path))} is not valid YAML{where}: "
                          f"{_printable(problem)}") from err
    return data if data is not None else {}


def _load_schema(schema) -> dict:
    if isinstance(schema, dict):
        return schema
    path = Path(schema if schema is not None else find_schema()).resolve()
    return _parse_schema(str(path), path.stat().st_mtime_ns)


@functools.lru_cache(maxsize=8)
def _parse_schema(path: str, mtime_ns: int) -> dict:
    """The schema file, parsed once per modification (*mtime_ns* is the cache key)."""
    import yaml

    with open(path, encoding="utf-8") as fh:
        return yaml.load(fh, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


_INF_WORDS = {"inf", ".inf", "+inf", "+.inf", "infinity", "+infinity"}
_NAN_WORDS = {"nan", ".nan"}


def _coerce(obj):
    """Undo what command lines and YAML 1.1 do to numbers: ``--config`` passes
    lists as strings, and PyYAML reads ``1e-5`` (no dot) and ``inf`` as strings.

    Only ASCII text is read as a number.  ``inf`` and ``nan`` (any spelling)
    become floats, so that the finiteness check names them; a numeral too large
    for a float stays text (rejected as not a number) instead of becoming inf.
    """
    if isinstance(obj, Mapping):
        return {k: _coerce(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_coerce(v) for v in obj]
    if isinstance(obj, str) and obj.isascii():
        text = obj.strip()
        if text.startswith("[") and text.endswith("]"):
            import yaml

            try:
                return _coerce(yaml.safe_load(text))
            except (yaml.YAMLError, ValueError):  # not YAML, or an integer of more than 4300 digits
                return obj
        low = text.lower()
        sign = -1.0 if low.startswith("-") else 1.0
        if low.lstrip("-") in _INF_WORDS or low in _INF_WORDS:
            return sign * math.inf
        if low.lstrip("+-") in _NAN_WORDS:
            return math.nan
        try:
            return int(text)
        except ValueError:
            pass
        try:
            value = float(text)
        except ValueError:
            return obj
        return value if math.isfinite(value) else obj
    return obj


def _printable(text: str) -> str:
    """*text* with every non-printable character (newlines too) escaped: one line."""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in text)


def _key(path) -> str:
    out = ""
    for part in path:
        if isinstance(part, int) and not isinstance(part, bool):
            out += f"[{part}]"
        else:
            part = _printable(str(part)) if str(part).strip() else json.dumps(str(part))  # '' and ' ' visible
            out += f".{part}" if out else part
    return out or "<top level>"


def _render(value) -> str:
    """Compact JSON-like text of a config value; ``nan``, ``inf``, ``-inf`` as
    bare words, every non-ASCII or control character escaped (one line)."""
    if isinstance(value, bool) or value is None:
        return json.dumps(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, numbers.Integral):
        value = int(value)
        if value.bit_length() > 200:  # str() of a huge integer is slow (and limited)
            return f"{'-' if value < 0 else ''}<an integer of about {int(value.bit_length() * 0.30103) + 1} digits>"
        return str(value)
    if isinstance(value, numbers.Real):
        return _render(float(value))
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, Mapping):
        items = sorted(value.items(), key=lambda kv: str(kv[0]))
        return "{" + ",".join(f"{json.dumps(str(k))}:{_render(v)}" for k, v in items) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(_render(v) for v in value) + "]"
    return json.dumps(str(value))


def _short(value) -> str:
    text = _render(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _branches(node: dict, root: dict):
    """*node* and the sub-schemas of its oneOf/anyOf/allOf, dereferenced."""
    node = _deref(node, root)
    yield node
    for key in ("oneOf", "anyOf", "allOf"):
        for branch in node.get(key, []):
            yield from _branches(branch, root)


def _node(schema: dict, root: dict, path) -> dict:
    """The schema node describing the instance at *path* ({} if the schema has none)."""
    node = schema
    for part in path:
        found = {}
        for branch in _branches(node, root):
            if isinstance(part, int) and not isinstance(part, bool):
                if isinstance(branch.get("items"), dict):
                    found = branch["items"]
                    break
            elif part in branch.get("properties", {}):
                found = branch["properties"][part]
                break
        node = found
    return _deref(node, root)


def _deref(node: dict, root: dict) -> dict:
    ref = node.get("$ref")
    if ref and ref.startswith("#/"):
        target = root
        for part in ref[2:].split("/"):
            target = target[part]
        return {**target, **{k: v for k, v in node.items() if k != "$ref"}}
    return node


_NOUNS = {"integer": ("an integer", "integers"), "number": ("a number", "numbers"),
          "string": ("a string", "strings"), "boolean": ("true or false", "true or false"), "null": ("null", "null")}


def _describe(node: dict, root: dict, with_doc: bool = True, finite: bool = False, plural: bool = False) -> str:
    """What *node* allows, in words.  *finite*: say that numbers must be finite
    (the message of a NaN or an infinity); *plural*: for list items."""
    node = _deref(node, root)
    if "oneOf" in node or "anyOf" in node:
        text = " or ".join(_describe(b, root, False, finite, plural) for b in node.get("oneOf", node.get("anyOf")))
    elif "enum" in node:
        text = "one of " + ", ".join(map(str, node["enum"]))
    elif "const" in node:
        text = _render(node["const"])
    else:
        kinds = node.get("type") or []
        kinds = kinds if isinstance(kinds, list) else [kinds]
        parts = []
        for kind in kinds:
            if kind == "array":
                text = "lists" if plural else "a list"
                if node.get("minItems", 0) >= 1:
                    text = "non-empty " + text if plural else "a non-empty list"
                text += " of " + ("distinct " if node.get("uniqueItems") else "")
                text += _describe(node.get("items", {}), root, False, finite, plural=True)
            elif kind == "object":
                text = ("mappings" if plural else "a mapping") + " with keys " + ", ".join(node.get("properties", {}))
            elif kind in _NOUNS:
                text = _NOUNS[kind][plural]
                if kind == "number" and (finite or node.get(ALLOW_INF)):
                    text = ("finite " if plural else "a finite ") + text.split(" ")[-1]
                bounds = []
                if "minimum" in node:
                    bounds.append(f">= {node['minimum']}")
                if "exclusiveMinimum" in node:
                    bounds.append(f"> {node['exclusiveMinimum']}")
                if "maximum" in node:
                    bounds.append(f"<= {node['maximum']}")
                if "exclusiveMaximum" in node:
                    bounds.append(f"< {node['exclusiveMaximum']}")
                if bounds:
                    text += " " + " and ".join(bounds)
                if kind == "number" and node.get(ALLOW_INF):
                    text += " or inf"
            else:
                text = "values" if plural else "a value"
            parts.append(text)
        text = " or ".join(parts) if parts else ("values" if plural else "a value")
    if with_doc and node.get("description"):
        text += f" ({' '.join(node['description'].split())})"
    return text


def _schema_error(err, root: dict) -> ConfigError:
    path = list(err.absolute_path)
    if err.validator == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        extra = sorted((e for e in err.instance if e not in allowed), key=str)
        where = _key(path)
        names = ", ".join(f"'{_key(path + [str(e)])}'" for e in extra)
        return ConfigError(
            f"unknown config key {names}; allowed keys {'at top level' if not path else 'in ' + where}: "
            + ", ".join(allowed)
        )
    if err.validator == "required":
        missing = next((k for k in err.validator_value if k not in err.instance), "?")
        node = _node(root, root, path + [missing])
        return ConfigError(f"missing config key '{_key(path + [missing])}'; allowed: {_describe(node, root)}")
    return ConfigError(f"config key '{_key(path)}' = {_short(err.instance)} is not allowed; "
                       f"allowed: {_describe(_documented(root, path), root)}")


def _documented(root: dict, path) -> dict:
    """The schema node at *path*; list items borrow the description of their list."""
    node = _node(root, root, path)
    if path and isinstance(path[-1], int) and not node.get("description"):
        parent = _node(root, root, path[:-1])
        if parent.get("description"):
            node = {**node, "description": parent["description"]}
    return node


def _leaves(obj, path=()):
    """(path, value) of every scalar in a nested config."""
    if isinstance(obj, Mapping):
        for key, value in obj.items():
            yield from _leaves(value, (*path, key))
    elif isinstance(obj, (list, tuple)):
        for index, value in enumerate(obj):
            yield from _leaves(value, (*path, index))
    else:
        yield list(path), obj


def _check_finite(cfg, root: dict, known_only: bool) -> None:
    """Raise the :func:`finite_error` of the first non-finite number in *cfg*;
    *known_only*: only where the schema has a node for the key."""
    for path, value in _leaves(cfg):
        if known_only and not _node(root, root, path):
            continue
        err = finite_error(path, value, root)
        if err is not None:
            raise err


def finite_error(path, value, schema: dict | None = None, allow_inf: bool | None = None) -> ConfigError | None:
    """The error for a number at config key *path* that is not finite (or not
    ``+inf`` where the schema node carries ``x-allow-inf``, or *allow_inf*);
    ``None`` if *value* is allowed or not a number.

    The one rule of :func:`roughcontact._validate.is_finite_number`, worded as
    the other config errors; *schema* (a loaded schema) supplies the bounds and
    description.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    root = schema or {}
    node = _documented(root, list(path)) if root else {}
    if allow_inf is None:
        allow_inf = bool(node.get(ALLOW_INF))
    elif allow_inf and not node.get(ALLOW_INF):
        node = {**node, ALLOW_INF: True}
    if _validate.is_finite_number(value, allow_inf):
        return None
    if not node.get("type"):
        node = {**node, "type": "number"}
    return ConfigError(f"config key '{_key(path)}' = {_short(value)} is not allowed; "
                       f"allowed: {_describe(node, root, finite=True)}")


def _fill_defaults(instance, node, root):
    node = _deref(node, root)
    if isinstance(instance, dict):
        for name, sub in node.get("properties", {}).items():
            sub = _deref(sub, root)
            if name not in instance and "default" in sub:
                instance[name] = copy.deepcopy(sub["default"])
            if name in instance:
                _fill_defaults(instance[name], sub, root)


def full_contact_slope(hurst: float, n: int, length: float, *, rolloff: float | None = None,
                       cutoff: float | None = None) -> float:
    """Estimated rms slope / h_rms of a self-affine surface with C(q) ~ q^(-2H-2)
    between q0 = 2 pi / L and the Nyquist wave number q1 = pi n / L (or the
    cutoff 2 pi/cutoff), constant below the roll-off 2 pi/rolloff."""
    with np.errstate(all="ignore"):  # extreme (but finite) L or H: the estimate is then inf or nan
        q_top = np.pi * n / length if cutoff is None else min(np.pi * n / length, 2 * np.pi / cutoff)
        q = np.geomspace(2 * np.pi / length, q_top, 4001)
        lnq = np.log(q)
        psd = np.maximum(q, 2 * np.pi / (length if rolloff is None else rolloff)) ** (-2 * hurst - 2)

        def trap(y):
            return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(lnq)))

        num = trap(q**4 * psd)  # int q^3 C(q) dq = int q^4 C dlnq
        den = trap(q**2 * psd)  # int q C(q) dq = int q^2 C dlnq
        return float(np.sqrt(num / den))


def resolve_config(raw: dict, schema=None) -> dict:
    """Validate and normalise a config; return the resolved copy.

    Raises :class:`ConfigError` with one line naming the offending key and
    what is allowed.  *schema* is a path or a loaded dict (default: the
    schema of the checkout).
    """
    import jsonschema

    root = _load_schema(schema)
    cfg = _coerce(copy.deepcopy(raw))
    # JSON-schema bounds compare false against NaN: every number must be finite (radius may be +inf).
    # Keys the schema knows first (a NaN is the cause, not a duplicate or a bound) ...
    _check_finite(cfg, root, known_only=True)
    validator = jsonschema.Draft202012Validator(root)
    errors = sorted(validator.iter_errors(cfg), key=lambda e: (len(e.absolute_path), _key(list(e.absolute_path))))
    if errors:
        # report the shallowest problem first: an unknown top-level key explains more than its children
        raise _schema_error(errors[0], root)
    # ... then everything, also below schema nodes that leave their contents open
    _check_finite(cfg, root, known_only=False)
    _fill_defaults(cfg, root, root)

    # normalise types
    cfg["grid"]["n"] = int(cfg["grid"]["n"])
    cfg["grid"]["length"] = float(cfg["grid"]["length"])
    cfg["e_star"] = float(cfg["e_star"])
    for axis in ("hurst", "radius", "h_rms", "exponent"):
        cfg[axis] = sorted(float(v) for v in cfg[axis])
    for axis in ("rolloff", "cutoff", "hardness"):  # null (the paper's setting) first
        cfg[axis] = sorted((None if v is None else float(v) for v in cfg[axis]), key=lambda v: (v is not None, v))
    seeds = cfg["seeds"]
    cfg["seeds"] = list(range(int(seeds))) if isinstance(seeds, (int, float)) else sorted(int(s) for s in seeds)
    for rng in cfg.get("forces", {}).values():
        rng["from"], rng["to"], rng["count"] = float(rng["from"]), float(rng["to"]), int(rng["count"])

    # checks a JSON schema cannot express
    window = cfg["fit"]["slopes"].get("window", 3)
    if window % 2 == 0:
        raise ConfigError(f"config key 'fit.slopes.window' = {window} is not allowed; allowed: an odd integer >= 3")
    kinds = {"sphere" if math.isfinite(r) else "flat" for r in cfg["radius"]}
    for kind in sorted(kinds):
        if kind not in cfg.get("forces", {}):
            what = "a finite radius (sphere)" if kind == "sphere" else "radius .inf (flat surface)"
            raise ConfigError(
                f"missing config key 'forces.{kind}': radius lists {what}; allowed: a mapping with keys from, to, count"
            )
    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
    for kind, rng in cfg.get("forces", {}).items():
        if not rng["from"] < rng["to"]:
            raise ConfigError(
                f"config key 'forces.{kind}': from = {rng['from']:g} must be smaller than to = {rng['to']:g}; "
                "allowed: 0 < from < to (forces F/(E* L^2))"
            )
        for end in ("from", "to"):
            force = rng[end] * cfg["e_star"] * length * length
            if not sys.float_info.min <= force <= sys.float_info.max:
                raise ConfigError(
                    f"config key 'forces.{kind}.{end}' = {rng[end]:g} gives a force F = {end} * e_star * "
                    f"grid.length^2 = {force:g}, outside the range of floating-point numbers; allowed: "
                    f"{sys.float_info.min:.3g} <= F <= {sys.float_info.max:.3g}"
                )
    if "flat" in kinds and "flat" in cfg["forces"]:
        slope = min(full_contact_slope(h, n, length) for h in cfg["hurst"]) * min(cfg["h_rms"])
        limit = 0.5 * slope
        if cfg["forces"]["flat"]["to"] >= limit:
            raise ConfigError(
                f"config key 'forces.flat.to' = {cfg['forces']['flat']['to']:g} would press the flat surfaces close to "
                f"full contact (rms slope ~ {slope:.3g} for H = {max(cfg['hurst']):g}, h_rms = {min(cfg['h_rms']):g}, "
                f"n = {n}); allowed: to < {limit:.3g}"
            )
    if "sphere" in kinds and "sphere" in cfg["forces"]:
        to = cfg["forces"]["sphere"]["to"]
        for exponent in cfg["exponent"]:
            rmax = max(r for r in cfg["radius"] if math.isfinite(r))
            # smooth body (eq. 7 with H -> m): F ∝ a^(m+1), so a/L = (F/F(a = L))^(1/(m+1));
            # for m = 2 Hertz, a^3 = 3 F R / (4 E*). numpy floats: extreme sizes give inf or 0, no exception
            with np.errstate(all="ignore"):
                force_at_l = np.float64(theory.body_indentation(length, rmax, 1.0, exponent=exponent).force)
                force_to = np.float64(to) * np.float64(length) ** 2
                a_over_l = float((force_to / force_at_l) ** (1 / (exponent + 1)))
                limit = float(force_at_l * 0.25 ** (exponent + 1) / np.float64(length) ** 2)
            if a_over_l > 0.25:
                body = "Hertz" if exponent == 2 else f"smooth-body (m = {exponent:g})"
                raise ConfigError(
                    f"config key 'forces.sphere.to' = {to:g} gives a {body} contact radius of {a_over_l:.2f} L for "
                    f"R = {rmax:g}, too close to the edge of the free-space grid; allowed: to <= {limit:.3g} for this radius"
                )
    _check_spectrum_and_hardness(cfg, kinds)
    return cfg


def _check_spectrum_and_hardness(cfg: dict, kinds: set) -> None:
    """The checks of the optional axes that a JSON schema cannot express."""
    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
    if "sphere" in kinds:
        for i, exponent in enumerate(cfg["exponent"]):
            if exponent in cfg["hurst"]:
                raise ConfigError(
                    f"config key 'exponent[{i}]' = {exponent:g} equals a Hurst exponent: the body and the roughness "
                    "then have parallel asymptotes and eqs. 16-17 no crossover; allowed: exponents other than every H")
    if None in cfg["rolloff"] and length in cfg["rolloff"]:
        raise ConfigError(f"config key 'rolloff' lists both null and grid.length = {length:g}, the same spectrum (a "
                          "roll-off at L is none); allowed: one of them")
    rolloffs = [length if r is None else r for r in cfg["rolloff"]]
    cutoffs = [0.0 if c is None else c for c in cfg["cutoff"]]
    for i, rolloff in enumerate(cfg["rolloff"]):
        if rolloff is not None and rolloff > length:
            raise ConfigError(f"config key 'rolloff[{i}]' = {rolloff:g} is not allowed; allowed: null or a wavelength "
                              f"<= grid.length = {length:g} (the longest wavelength of the surface)")
    for i, cutoff in enumerate(cfg["cutoff"]):
        if cutoff is not None and cutoff < 2 * length / n:
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: null or a wavelength "
                              f">= 2 cells = 2 grid.length/grid.n = {2 * length / n:.3g}")
        if cutoff is not None and cutoff >= min(rolloffs):
            raise ConfigError(f"config key 'cutoff[{i}]' = {cutoff:g} is not allowed; allowed: a wavelength below every "
                              f"roll-off ({min(rolloffs):g}), else no self-affine band is left")
    for i, hardness in enumerate(cfg["hardness"]):
        if hardness is None:
            continue
        for kind in sorted(kinds):
            to = cfg["forces"][kind]["to"]
            # fully plastic: F = hardness * area; a sphere's contact must stay within L/4 of its apex
            limit = hardness if kind == "flat" else math.pi * hardness / 16
            if to >= limit:
                raise ConfigError(
                    f"config key 'hardness[{i}]' = {hardness:g} (units of E*) is too soft for forces.{kind}.to = "
                    f"{to:g}: a fully plastic contact would cover {'the whole grid' if kind == 'flat' else 'more than L/4'}"
                    f"; allowed: hardness > {to / (limit / hardness):.3g} or a smaller forces.{kind}.to")
    if max(cutoffs) > 0 and "flat" in kinds and cfg["forces"].get("flat"):
        slope = min(full_contact_slope(h, n, length, rolloff=r, cutoff=c or None)
                    for h in cfg["hurst"] for r in rolloffs for c in cutoffs) * min(cfg["h_rms"])
        if cfg["forces"]["flat"]["to"] >= 0.5 * slope:
            raise ConfigError(
                f"config key 'forces.flat.to' = {cfg['forces']['flat']['to']:g} would press the flat surfaces with "
                f"a cutoff close to full contact (rms slope ~ {slope:.3g}); allowed: to < {0.5 * slope:.3g}")
