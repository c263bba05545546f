"""JSON-schema machinery of the configuration: load, describe, one-line errors.

The schema is package data (:data:`SCHEMA_PATH`, ``config.schema.yaml`` beside this module);
``load_schema`` parses it once per modification of the file.  Nothing here
knows the keys of this project's config: :mod:`roughcontact.study.config.resolve` resolves
the config with these helpers and adds the checks a JSON schema cannot
express.  ``yaml`` is imported where it is used; ``jsonschema`` is imported
by :mod:`roughcontact.study.config.resolve`, which validates.

Errors
------
Every problem is a :class:`ConfigError` whose text is one line naming the key
(``key_text``), the offending value (``_render``, shortened by ``short_text``) and
what the schema allows (``_describe``: the node's type, bounds and
description).  ``schema_error`` words a ``jsonschema`` validation error this
way.

Numbers
-------
:func:`roughcontact.study.config.coerce.coerce` first undoes what command lines and YAML 1.1 do to
numbers.  Numbers must be finite (:func:`roughcontact._validate.is_finite_number`): JSON-schema
bounds compare false against NaN, so ``check_finite`` walks the whole config
and :func:`finite_error` rejects every NaN and infinity, except ``+inf`` where
the schema node carries ``x-allow-inf: true`` (:data:`ALLOW_INF`; the radius
items: a nominally flat surface).  New keys of the schema are covered without
further code.  ``fill_defaults`` fills in the schema's ``default`` values.
"""
from __future__ import annotations

import copy
import functools
import json
import math
import numbers
from collections.abc import Mapping
from pathlib import Path

from ... import _validate
from ...errors import ConfigError

__all__ = [
    "default_of",
    "deref",
    "ALLOW_INF",
    "SCHEMA_PATH",
    "check_finite",
    "fill_defaults",
    "finite_error",
    "given_error",
    "key_text",
    "leaves",
    "load_schema",
    "printable",
    "schema_error",
    "schema_file",
    "short_text",
]

#: schema annotation: this number may be ``+inf`` (no other non-finite value is ever allowed)
ALLOW_INF = "x-allow-inf"


#: the configuration's JSON schema, shipped as package data beside this module
SCHEMA_PATH = Path(__file__).with_name("config.schema.yaml")


def load_schema(schema) -> dict:
    """The schema *schema* (a path or a loaded dict); ``None``: the package's own, the file
    :data:`SCHEMA_PATH` with the sweep axes' entries (:func:`roughcontact.study.config.axes.schema_properties`)
    inserted before ``seeds``."""
    if isinstance(schema, dict):
        return schema
    if schema is None:
        return _package_schema(SCHEMA_PATH.stat().st_mtime_ns)
    path = Path(schema).resolve()
    return _parse_schema(str(path), path.stat().st_mtime_ns)


@functools.lru_cache(maxsize=4)
def _package_schema(mtime_ns: int) -> dict:
    from .axes import schema_properties

    root = copy.deepcopy(_parse_schema(str(SCHEMA_PATH.resolve()), mtime_ns))
    properties = {}
    for name, node in root["properties"].items():
        if name == "seeds":
            properties.update(schema_properties())
        properties[name] = node
    root["properties"] = properties
    # the opt-in per-load quantities a run may keep: the registry's (one new module adds one)
    from .. import quantities

    choices = root["properties"]["fields"]["properties"]["quantities"]["items"]
    choices["enum"] = list(quantities.optional()) or [""]
    return root


def schema_file() -> str:
    """Path of a JSON file holding :func:`load_schema` ``(None)`` (written once per content, in
    the temporary directory): what Snakemake's ``validate()`` reads."""
    import hashlib
    import os
    import tempfile

    text = json.dumps(load_schema(None), sort_keys=True)
    path = Path(tempfile.gettempdir()) / f"roughcontact-schema-{hashlib.sha256(text.encode()).hexdigest()[:16]}.json"
    if not path.exists():
        tmp = path.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(text, encoding="utf-8")
        os.replace(tmp, path)
    return str(path)


@functools.lru_cache(maxsize=8)
def _parse_schema(path: str, mtime_ns: int) -> dict:
    """The schema file, parsed once per modification (*mtime_ns* is the cache key)."""
    import yaml

    with open(path, encoding="utf-8") as fh:
        return yaml.load(fh, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))


def printable(text: str) -> str:
    """*text* with every non-printable character (newlines too) escaped: one line."""
    return "".join(c if c.isprintable() else c.encode("unicode_escape").decode("ascii") for c in text)


def key_text(path) -> str:
    out = ""
    for part in path:
        if isinstance(part, int) and not isinstance(part, bool):
            out += f"[{part}]"
        else:
            part = printable(str(part)) if str(part).strip() else json.dumps(str(part))  # '' and ' ' visible
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
        return _quoted(value)
    if isinstance(value, Mapping):
        items = sorted(value.items(), key=lambda kv: str(kv[0]))
        return "{" + ",".join(f"{_quoted(str(k))}:{_render(v)}" for k, v in items) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(_render(v) for v in value) + "]"
    return json.dumps(str(value))


def _quoted(text: str) -> str:
    """*text* in single quotes, as the messages quote a key: every non-ASCII or control character
    escaped as JSON does (one line), a quote inside escaped."""
    return "'" + json.dumps(text)[1:-1].replace('\\"', '"').replace("'", "\\'") + "'"


def short_text(value) -> str:
    text = _render(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _branches(node: dict, root: dict):
    """*node* and the sub-schemas of its oneOf/anyOf/allOf, dereferenced."""
    node = deref(node, root)
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
    return deref(node, root)


def default_of(root: dict, path):
    """A deep copy of the schema's ``default`` at *path* (a sequence of keys); ``KeyError`` if none."""
    node = _node(root, root, list(path))
    if "default" not in node:
        raise KeyError(f"the schema gives no default for '{key_text(list(path))}'")
    return copy.deepcopy(node["default"])


def deref(node: dict, root: dict) -> dict:
    """*node* with its ``$ref`` (a ``#/...`` pointer into *root*) resolved and merged in."""
    ref = node.get("$ref")
    if ref and ref.startswith("#/"):
        target = root
        for part in ref[2:].split("/"):
            target = target[part]
        return {**target, **{k: v for k, v in node.items() if k != "$ref"}}
    return node


#: an integer's minimum worded: ``minimum: 1`` is a positive integer, ``minimum: 0`` a non-negative one
_SIGNED = {1: "positive integer", 0: "non-negative integer"}
#: the largest seed (and any other integer) a NumPy int64 holds: worded "< 2^63"
_INT64_MAX = 2**63 - 1

_NOUNS = {"integer": ("an integer", "integers"), "number": ("a number", "numbers"),
          "string": ("a string", "strings"), "boolean": ("true or false", "true or false"), "null": ("null", "null")}


def _describe(node: dict, root: dict, with_doc: bool = True, finite: bool = False, plural: bool = False) -> str:
    """What *node* allows, in words.  *finite*: say that numbers must be finite
    (the message of a NaN or an infinity); *plural*: for list items."""
    node = deref(node, root)
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
                sign = _SIGNED.get(node.get("minimum")) if kind == "integer" else None
                if sign is not None:   # a positive integer, not "an integer >= 1"
                    text = sign + "s" if plural else ("an " if sign[0] in "aeiou" else "a ") + sign
                elif "minimum" in node:
                    bounds.append(f">= {node['minimum']}")
                if "exclusiveMinimum" in node:
                    bounds.append(f"> {node['exclusiveMinimum']}")
                if kind == "integer" and node.get("maximum") == _INT64_MAX:
                    bounds.append("< 2^63")
                elif "maximum" in node:
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


def schema_error(err, root: dict) -> ConfigError:
    """The one-line :class:`ConfigError` of a ``jsonschema`` validation error. Where the value
    fails every branch of a ``oneOf`` but has the type of one of them, the error inside that
    branch is worded (``e_star.nu1 = 0.7``, not the whole mapping)."""
    if err.validator in ("oneOf", "anyOf") and err.context:
        inside = [e for e in err.context if e.validator != "type"]
        if inside:
            import jsonschema

            return schema_error(jsonschema.exceptions.best_match(inside), root)
    path = list(err.absolute_path)
    if err.validator == "additionalProperties":
        allowed = list(err.schema.get("properties", {}))
        extra = sorted((e for e in err.instance if e not in allowed), key=str)
        where = key_text(path)
        names = ", ".join(f"'{key_text(path + [str(e)])}'" for e in extra)
        return ConfigError(
            f"unknown config key {names}; allowed keys {'at top level' if not path else 'in ' + where}: "
            + ", ".join(allowed), key=key_text(path + [str(extra[0])]) if extra else None
        )
    if err.validator == "required":
        missing = next((k for k in err.validator_value if k not in err.instance), "?")
        node = _node(root, root, path + [missing])
        return ConfigError(f"missing config key '{key_text(path + [missing])}'; allowed: {_describe(node, root)}",
                           key=key_text(path + [missing]))
    return ConfigError(f"config key '{key_text(path)}' = {short_text(err.instance)} is not allowed; "
                       f"allowed: {_describe(_documented(root, path), root)}", key=key_text(path))


def given_error(err, root: dict, cfg, given) -> ConfigError | None:
    """The one-line :class:`ConfigError` of a ``jsonschema`` error about a value that
    :func:`~roughcontact.study.config.coerce.one_element_lists` made a one-element list although
    its key also takes a value of another type (``seeds: six``: not ``seeds = ['six']``, but
    ``seeds = 'six'``, and what ``seeds`` allows); ``None`` for any other error (:func:`schema_error`
    words it). *cfg*: the configuration validated; *given*: the same as written
    (:func:`~roughcontact.study.config.coerce.read_numbers`)."""
    path = list(err.absolute_path)
    now, was = cfg, given
    for depth in range(len(path) + 1):
        if isinstance(now, list) and not isinstance(was, (list, tuple)):
            prefix = path[:depth]
            node = _documented(root, prefix)
            kinds = set()
            for branch in _branches(node, root):
                kind = branch.get("type")
                kinds.update([kind] if isinstance(kind, str) else kind or ())
            if not kinds - {"array"}:
                return None   # a list only (hurst: abc): the item's error, hurst[0], says more
            return ConfigError(f"config key '{key_text(prefix)}' = {short_text(was)} is not allowed; "
                               f"allowed: {_describe(node, root)}", key=key_text(prefix))
        if depth == len(path):
            return None
        part = path[depth]
        try:
            now, was = now[part], was[part]
        except (KeyError, IndexError, TypeError):
            return None
    return None


def _documented(root: dict, path) -> dict:
    """The schema node at *path*; list items borrow the description of their list."""
    node = _node(root, root, path)
    if path and isinstance(path[-1], int) and not node.get("description"):
        parent = _node(root, root, path[:-1])
        if parent.get("description"):
            node = {**node, "description": parent["description"]}
    return node


def leaves(obj, path=()):
    """(path, value) of every scalar in a nested config."""
    if isinstance(obj, Mapping):
        for key, value in obj.items():
            yield from leaves(value, (*path, key))
    elif isinstance(obj, (list, tuple)):
        for index, value in enumerate(obj):
            yield from leaves(value, (*path, index))
    else:
        yield list(path), obj


def check_finite(cfg, root: dict, known_only: bool) -> None:
    """Raise the :func:`finite_error` of the first non-finite number in *cfg*;
    *known_only*: only where the schema has a node for the key."""
    for path, value in leaves(cfg):
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
    return ConfigError(f"config key '{key_text(path)}' = {short_text(value)} is not allowed; "
                       f"allowed: {_describe(node, root, finite=True)}", key=key_text(path))


def fill_defaults(instance, node, root):
    node = deref(node, root)
    if isinstance(instance, dict):
        for name, sub in node.get("properties", {}).items():
            sub = deref(sub, root)
            if name not in instance and "default" in sub:
                instance[name] = copy.deepcopy(sub["default"])
            if name in instance:
                fill_defaults(instance[name], sub, root)
