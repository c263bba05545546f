"""Configuration keys that were renamed: refused in a configuration, read in a recorded one.

The study-wide analysis settings once sat under ``fit.zeta`` although every fit, verdict, score
and interval of the study uses them: ``fit.resolved_cells`` is now ``fit.resolved_cells``,
``fit.bootstrap`` is ``fit.bootstrap``, ``fit.confidence`` is ``fit.confidence``.
A configuration that still writes an old key is refused by
:func:`~roughcontact.study.config.resolve.resolve_config` in one line naming the new ones
(:func:`refuse_renamed`); a configuration recorded in a file written before the rename (a run
file's or a merged file's ``config`` attribute) is read in the new layout (:func:`current_layout`),
so that the results of an earlier study stay readable.
"""
from __future__ import annotations

import copy
from collections.abc import Mapping

from ...errors import ConfigError

__all__ = ["RENAMED", "current_layout", "refuse_renamed"]

#: ``{old key path: new key path}`` of the renamed configuration keys
RENAMED = {
    ("fit", "zeta", "min_cells"): ("fit", "resolved_cells"),
    ("fit", "zeta", "bootstrap"): ("fit", "bootstrap"),
    ("fit", "zeta", "confidence"): ("fit", "confidence"),
}


def _text(path: tuple) -> str:
    return ".".join(path)


def _found(cfg) -> list:
    """The old key paths of :data:`RENAMED` that *cfg* holds."""
    found = []
    for old in RENAMED:
        node = cfg
        for part in old:
            if not isinstance(node, Mapping) or part not in node:
                break
            node = node[part]
        else:
            found.append(old)
    return found


def refuse_renamed(cfg) -> None:
    """Raise :class:`~roughcontact.errors.ConfigError` (one line naming the new keys) where the
    configuration *cfg* writes a renamed key."""
    found = _found(cfg)
    if found:
        olds = ", ".join(f"'{_text(old)}'" for old in found)
        news = ", ".join(f"'{_text(RENAMED[old])}'" for old in found)
        raise ConfigError(f"config key {olds} was renamed: write {news} instead (the study-wide resolved loads, "
                          f"bootstrap resamples and confidence level)", key=_text(found[0]))


def current_layout(cfg):
    """*cfg*, a configuration recorded by an earlier version, in the current layout: each renamed
    key moved to its new place (a copy; *cfg* itself where it has none)."""
    found = _found(cfg)
    if not found:
        return cfg
    cfg = copy.deepcopy(dict(cfg))
    for old in found:
        *parent_path, name = old
        parent = cfg
        for part in parent_path:
            parent = parent[part]
        value = parent.pop(name)
        *target_path, new_name = RENAMED[old]
        target = cfg
        for part in target_path:
            target = target.setdefault(part, {})
        target.setdefault(new_name, value)
    return cfg
