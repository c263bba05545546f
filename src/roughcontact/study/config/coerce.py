"""Numbers as a configuration means them: what command lines and YAML 1.1 do to numbers undone.

:func:`coerce` is the first step of resolving a configuration
(:func:`roughcontact.study.config.resolve.resolve_config`), before the schema checks it.
"""
from __future__ import annotations

import math
from collections.abc import Mapping

__all__ = ["coerce"]

_INF_WORDS = {"inf", ".inf", "+inf", "+.inf", "infinity", "+infinity"}
_NAN_WORDS = {"nan", ".nan"}


def coerce(obj):
    """Undo what command lines and YAML 1.1 do to numbers: ``--config`` passes
    lists as strings, and PyYAML reads ``1e-5`` (no dot) and ``inf`` as strings.

    Only ASCII text is read as a number.  ``inf`` and ``nan`` (any spelling)
    become floats, so that the finiteness check names them; a numeral too large
    for a float stays text (rejected as not a number) instead of becoming inf.
    """
    if isinstance(obj, Mapping):
        return {k: coerce(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [coerce(v) for v in obj]
    if isinstance(obj, str) and obj.isascii():
        text = obj.strip()
        if text.startswith("[") and text.endswith("]"):
            import yaml

            try:
                return coerce(yaml.safe_load(text))
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
