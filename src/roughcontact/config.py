"""Configuration of the parameter study: schema, defaults, checks, one-line errors.

:func:`resolve_config` normalises a raw config (as Snakemake or ``yaml``
loaded it), validates it against ``workflow/schemas/config.schema.yaml`` plus
the checks a JSON schema cannot express, fills defaults and returns the
resolved config.  Every problem is reported as one line (:class:`ConfigError`)
naming the key and what is allowed.  Nothing here runs a job
(:mod:`roughcontact.study` does); ``jsonschema`` and ``yaml`` are imported
where they are used.
"""
from __future__ import annotations

import copy
import math
import os
from pathlib import Path

import numpy as np

from . import provenance

__all__ = ["ConfigError", "find_schema", "load_config", "resolve_config", "full_contact_slope"]


class ConfigError(ValueError):
    """An invalid configuration; ``str(err)`` is one line naming the key."""



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
    """Read a YAML config file (no validation)."""
    import yaml

    with open(path) as fh:
        data = yaml.safe_load(fh)
    return data if data is not None else {}


def _load_schema(schema) -> dict:
    import yaml

    if isinstance(schema, dict):
        return schema
    with open(schema if schema is not None else find_schema()) as fh:
        return yaml.safe_load(fh)


def _coerce(obj):
    """Undo what command lines and YAML 1.1 do to numbers: ``--config`` passes
    lists as strings, and PyYAML reads ``1e-5`` (no dot) and ``inf`` as strings."""
    if isinstance(obj, dict):
        return {k: _coerce(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_coerce(v) for v in obj]
    if isinstance(obj, str):
        text = obj.strip()
        if text.startswith("[") and text.endswith("]"):
            import yaml

            try:
                return _coerce(yaml.safe_load(text))
            except Exception:
                return obj
        low = text.lower()
        if low in ("inf", ".inf", "+inf", "infinity"):
            return math.inf
        if low in ("nan", ".nan"):
            return obj  # keep as text: rejected by the schema with a clear line
        try:
            return int(text)
        except ValueError:
            pass
        try:
            return float(text)
        except ValueError:
            return obj
    return obj


def _key(path) -> str:
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out or "<top level>"


def _short(value) -> str:
    text = provenance.canonical_json(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _node(schema: dict, root: dict, path) -> dict:
    """The schema node describing the instance at *path*."""
    node = schema
    for part in path:
        node = _deref(node, root)
        if isinstance(part, int):
            if "items" in node:
                node = node["items"]
            else:
                for branch in node.get("oneOf", []) + node.get("anyOf", []):
                    if "items" in branch:
                        node = branch["items"]
                        break
        else:
            node = node.get("properties", {}).get(part, {})
    return _deref(node, root)


def _deref(node: dict, root: dict) -> dict:
    ref = node.get("$ref")
    if ref and ref.startswith("#/"):
        target = root
        for part in ref[2:].split("/"):
            target = target[part]
        return {**target, **{k: v for k, v in node.items() if k != "$ref"}}
    return node


def _describe(node: dict, root: dict, with_doc: bool = True) -> str:
    node = _deref(node, root)
    if "oneOf" in node or "anyOf" in node:
        text = " or ".join(_describe(b, root, False) for b in node.get("oneOf", node.get("anyOf")))
    elif "enum" in node:
        text = "one of " + ", ".join(map(str, node["enum"]))
    else:
        kind = node.get("type")
        if kind == "array":
            text = "a non-empty list of " + ("distinct " if node.get("uniqueItems") else "")
            text += _describe(node.get("items", {}), root, False).replace("an integer", "integers").replace("a number", "numbers")
        elif kind == "object":
            text = "a mapping with keys " + ", ".join(node.get("properties", {}))
        else:
            text = {"integer": "an integer", "number": "a number", "string": "a string"}.get(kind, "a value")
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
    if with_doc and node.get("description"):
        text += f" ({node['description'].strip()})"
    return text


def _schema_error(err, root: dict) -> ConfigError:
    path = list(err.absolute_path)
    if err.validator == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        extra = sorted(set(err.instance) - set(allowed))
        where = _key(path)
        names = ", ".join(f"'{_key(path + [e])}'" for e in extra)
        return ConfigError(
            f"unknown config key {names}; allowed keys {'at top level' if not path else 'in ' + where}: "
            + ", ".join(allowed)
        )
    if err.validator == "required":
        missing = err.message.split("'")[1] if "'" in err.message else "?"
        node = _node(root, root, path + [missing])
        return ConfigError(f"missing config key '{_key(path + [missing])}'; allowed: {_describe(node, root)}")
    node = _node(root, root, path)
    if path and isinstance(path[-1], int) and not node.get("description"):
        parent = _node(root, root, path[:-1])
        if parent.get("description"):
            node = {**node, "description": parent["description"]}
    return ConfigError(f"config key '{_key(path)}' = {_short(err.instance)} is not allowed; allowed: {_describe(node, root)}")


def _fill_defaults(instance, node, root):
    node = _deref(node, root)
    if isinstance(instance, dict):
        for name, sub in node.get("properties", {}).items():
            sub = _deref(sub, root)
            if name not in instance and "default" in sub:
                instance[name] = copy.deepcopy(sub["default"])
            if name in instance:
                _fill_defaults(instance[name], sub, root)


def full_contact_slope(hurst: float, n: int, length: float) -> float:
    """Estimated rms slope / h_rms of a self-affine surface with C(q) ~ q^(-2H-2)
    between q0 = 2 pi / L and the Nyquist wave number q1 = pi n / L."""
    q = np.geomspace(2 * np.pi / length, np.pi * n / length, 4001)
    lnq = np.log(q)
    def trap(y):
        return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(lnq)))

    num = trap(q ** (2 - 2 * hurst))  # int q^3 C(q) dq = int q^4 C dlnq
    den = trap(q ** (-2 * hurst))     # int q C(q) dq = int q^2 C dlnq
    return float(np.sqrt(num / den))


def resolve_config(raw: dict, schema=None) -> dict:
    """Validate and normalise a config; return the resolved copy.

    Raises :class:`ConfigError` with one line naming the offending key and
    what is allowed.  *schema* is a path or a loaded dict (default: the
    schema of the checkout).
    """
    import jsonschema

    root = _load_schema(schema)
    cfg = _coerce(copy.deepcopy(dict(raw)))
    validator = jsonschema.Draft202012Validator(root)
    errors = sorted(validator.iter_errors(cfg), key=lambda e: (len(e.absolute_path), _key(list(e.absolute_path))))
    if errors:
        # report the shallowest problem first: an unknown top-level key explains more than its children
        raise _schema_error(errors[0], root)
    _fill_defaults(cfg, root, root)

    # normalise types
    cfg["grid"]["n"] = int(cfg["grid"]["n"])
    cfg["grid"]["length"] = float(cfg["grid"]["length"])
    cfg["e_star"] = float(cfg["e_star"])
    for axis in ("hurst", "radius", "h_rms"):
        cfg[axis] = sorted(float(v) for v in cfg[axis])
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
    for kind, rng in cfg.get("forces", {}).items():
        if not rng["from"] < rng["to"]:
            raise ConfigError(
                f"config key 'forces.{kind}': from = {rng['from']:g} must be smaller than to = {rng['to']:g}; "
                "allowed: 0 < from < to (forces F/(E* L^2))"
            )
    n, length = cfg["grid"]["n"], cfg["grid"]["length"]
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
        rmax = max(r for r in cfg["radius"] if math.isfinite(r))
        to = cfg["forces"]["sphere"]["to"]
        a_over_l = (3 * to * rmax / (4 * length)) ** (1 / 3)  # Hertz: a^3 = 3 F R / (4 E*)
        if a_over_l > 0.25:
            limit = 4 * length * 0.25**3 / (3 * rmax)
            raise ConfigError(
                f"config key 'forces.sphere.to' = {to:g} gives a Hertz contact radius of {a_over_l:.2f} L for "
                f"R = {rmax:g}, too close to the edge of the free-space grid; allowed: to <= {limit:.3g} for this radius"
            )
    return cfg
