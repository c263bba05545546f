"""One registry loader for the package's four registries: sweep axes
(:mod:`roughcontact.study.config.axes`), models of the scorecard (:mod:`roughcontact.models.scorecard`),
claims (:mod:`roughcontact.study.claims`) and per-load quantities (:mod:`roughcontact.study.quantities`).

A registry is a ``dict`` that the modules of one package fill as they are imported, each calling
its ``register``: :func:`add` is that call's rule (one entry per key), :func:`import_modules`
imports every module of the package, the named ones first in their order, then the others by
name, so that a new entry is one new module. Only the standard library is imported here.
"""
from __future__ import annotations

import importlib
import pkgutil

__all__ = ["add", "import_modules", "rank"]


def add(registry: dict, key: str, item, what: str):
    """Enter *item* under *key* in *registry* and return it; ``ValueError`` naming *what* (``model``,
    ``claim``, ...) for a key registered already."""
    if key in registry:
        raise ValueError(f"{what} {key!r} is registered already")
    registry[key] = item
    return item


def rank(module: str, order: tuple) -> tuple:
    """Where the module *module* (dotted or short name) stands: its place in *order*, then the
    modules not in it by name."""
    short = module.rsplit(".", 1)[-1]
    return (order.index(short) if short in order else len(order), short)


def import_modules(package: str, path, order: tuple = (), skip: tuple = ("registry",)) -> None:
    """Import every module of *package* (its ``__path__`` *path*) but *skip*, by :func:`rank`."""
    found = [m.name for m in pkgutil.iter_modules(path) if m.name not in skip]
    for name in sorted(found, key=lambda m: rank(m, order)):
        importlib.import_module(f"{package}.{name}")
