"""Numbers as a configuration means them: what command lines and YAML 1.1 do to numbers undone,
and a scalar where the schema wants a list read as a one-element list (``hurst: 0.7`` is
``hurst: [0.7]``).

:func:`coerce` is the first step of resolving a configuration
(:func:`roughcontact.study.config.resolve.resolve_config`), before the schema checks it.
"""
from __future__ import annotations

import math
from collections.abc import Mapping

__all__ = ["coerce", "one_element_lists", "read_numbers"]

_INF_WORDS = {"inf", ".inf", "+inf", "+.inf", "infinity", "+infinity"}
_NAN_WORDS = {"nan", ".nan"}


def coerce(obj):
    """Undo what command lines and YAML 1.1 do to numbers: ``--config`` passes
    lists as strings, and PyYAML reads ``1e-5`` (no dot) and ``inf`` as strings; then, for a whole
    configuration (a mapping), :func:`one_element_lists`.

    Only ASCII text is read as a number.  ``inf`` and ``nan`` (any spelling)
    become floats, so that the finiteness check names them; a numeral too large
    for a float stays text (rejected as not a number) instead of becoming inf.
    """
    out = _numbers(obj)
    return one_element_lists(out) if isinstance(out, Mapping) else out


#: the JSON types a Python value may be meant as (an integer is also a number; a float, e.g. ``seeds: 6.0``
#: or ``nan``, is meant as the key's own number, and its error names the key, not a list's item)
_JSON_TYPES = ((bool, {"boolean"}), (int, {"integer", "number"}), (float, {"integer", "number"}), (str, {"string"}),
               (type(None), {"null"}), (Mapping, {"object"}))


def one_element_lists(cfg, schema=None):
    """*cfg* with every value the schema wants as a list but given as one value of another type
    (``hurst: 0.7``, ``fields: {at: 1.0e-3}``, ``tangential: {at: 2.0e-5}``) made a one-element list;
    a value the key also accepts as it is (``seeds: 6``, ``tangential: {at: null}``) stays.
    *schema*: the loaded schema (default: the package's,
    :func:`roughcontact.study.config.schema.load_schema`)."""
    from .schema import load_schema

    root = load_schema(schema)
    return _lists(cfg, root, root)


def _lists(instance, node, root):
    from .schema import _branches

    if not isinstance(instance, Mapping):
        return instance
    properties = {}
    for branch in _branches(node, root):
        for key, sub in branch.get("properties", {}).items():
            properties.setdefault(key, sub)
    out = {}
    for key, value in instance.items():
        sub = properties.get(key)
        if sub is None:
            out[key] = value
            continue
        types = set()
        for branch in _branches(sub, root):
            kind = branch.get("type")
            types.update([kind] if isinstance(kind, str) else kind or ())
        have = next((t for cls, t in _JSON_TYPES if isinstance(value, cls)), set())
        if "array" in types and not isinstance(value, (list, tuple)) and not (have & types):
            out[key] = [value]
        else:
            out[key] = _lists(value, sub, root)
    return out


def read_numbers(obj):
    """:func:`coerce` without :func:`one_element_lists`: the configuration as written, its numbers
    read (what an error message shows as the value given)."""
    return _numbers(obj)


def _numbers(obj):
    """:func:`coerce` without :func:`one_element_lists`."""
    if isinstance(obj, Mapping):
        return {k: _numbers(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_numbers(v) for v in obj]
    if isinstance(obj, str) and obj.isascii():
        text = obj.strip()
        if text.startswith("[") and text.endswith("]"):
            import yaml

            try:
                return _numbers(yaml.safe_load(text))
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
