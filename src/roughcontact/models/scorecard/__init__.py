"""The models of the scorecard, one module each, registered where they are defined.

A model predicts the stiffness ``k(F)`` of a rough body from a :class:`Surface`: the parameters
of a generated surface (H, h_rms, the grid, roll-off and cutoff) or a measured spectrum fit
(H and h_rms fitted, the measured spectrum and its moments). The generated scorecard
(:mod:`roughcontact.study.analysis.scorecard`) and the measured one
(:mod:`roughcontact.study.analysis.measured_models`) both loop over :func:`models`, so a new model is
one module in this package that calls :func:`register` (worked example in the package guide,
``docs/guide/package.md``); every module here is imported when the registry is first read.
"""
from __future__ import annotations

from ..._registry import import_modules, rank
from .registry import MODELS, SELF_AFFINE, Model, Range, Surface, register

__all__ = ["MODELS", "Model", "Range", "SELF_AFFINE", "Surface", "register", "models", "predict"]

#: the modules of the seven models of Pohrt & Popov's comparison and this package's, in the
#: order of the tables and figures; further modules of this package follow in name order
_ORDER = ("eq16", "contact_scale", "greenwood_tripp", "mdr", "persson")


def _rank(module: str) -> tuple:
    """Where a module's models stand: :data:`_ORDER`, then the other modules by name."""
    return rank(module, _ORDER)


def _load() -> None:
    """Import every module of this package once (each registers its models)."""
    import_modules(__name__, __path__, _ORDER)


def models() -> dict[str, Model]:
    """``{name: Model}`` of every registered model: by module (:data:`_ORDER`, then by name), then
    in the order each module registers them, whatever imported the modules first."""
    if not _loaded:
        _load()
        _loaded.append(True)
    return dict(sorted(MODELS.items(), key=lambda item: _rank(getattr(item[1].predict, "__module__", ""))))


_loaded: list = []


def predict(force, surface: Surface, known=None) -> dict:
    """``{name: k}`` of every model that applies to *surface* at the forces *force* (force
    units, 1-D), each an array (NaN where the model has no solution). *known*: ``{name: k or
    None}`` already computed for this surface and these forces (a precomputed model,
    :attr:`Model.precomputable`), taken instead of computing them again."""
    import numpy as np

    known = known or {}
    out = {}
    for name, model in models().items():
        k = known[name] if name in known else model.predict(force, surface)
        if k is not None:
            out[name] = np.asarray(k, dtype=float)
    return out
