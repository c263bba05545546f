"""The models of the area scorecard: the real contact area ``A(F)`` of a rough sphere, one module
each, registered where they are defined (as the stiffness models of
:mod:`roughcontact.models.scorecard`).

An area model reads the same :class:`~roughcontact.models.scorecard.Surface` as a stiffness model
and predicts ``A`` (length²) at each force; :func:`rms_slope` is the ``h′_rms`` every model uses.
The closed forms are in :mod:`.laws`; the scorecard is
:func:`roughcontact.study.analysis.area.area_scorecard`.
"""
from __future__ import annotations

import dataclasses
from typing import Callable

from ..._registry import add, import_modules, rank

__all__ = ["AreaModel", "AREA_MODELS", "register", "models", "predict", "rms_slope"]


@dataclasses.dataclass(frozen=True)
class AreaModel:
    """One model of the area scorecard.

    Attributes
    ----------
    name : str
        Its name in ``area/area_models.csv`` and the figure.
    summary : str
        One sentence for the report.
    predict : callable
        ``predict(force, surface) -> A``: the real contact area (length²) at each force, or
        ``None`` where the model does not apply to *surface* (a :class:`~roughcontact.models.scorecard.Surface`).
    reference : str
        Where the model comes from (a DOI).
    """

    name: str
    summary: str
    predict: Callable
    reference: str = ""


#: every registered area model, in registration order
AREA_MODELS: dict[str, AreaModel] = {}
#: the modules of the area models, in the order of the tables; further modules follow by name
_ORDER = ("persson", "linear_hertz", "three_regime")
_loaded: list = []


def register(model: AreaModel) -> AreaModel:
    """Add *model* to :data:`AREA_MODELS` (a second model of the same name is an error)."""
    return add(AREA_MODELS, model.name, model, "area model")


def models() -> dict[str, AreaModel]:
    """``{name: AreaModel}`` of every registered area model, by module (:data:`_ORDER`, then by name)."""
    if not _loaded:
        import_modules(__name__, __path__, _ORDER, skip=("laws",))
        _loaded.append(True)
    return dict(sorted(AREA_MODELS.items(), key=lambda item: rank(getattr(item[1].predict, "__module__", ""),
                                                                  _ORDER)))


def rms_slope(surface) -> float:
    """``h′_rms = √⟨|∇h|²⟩`` of the spectrum of *surface*'s grid (its roll-off and cutoff; a measured
    spectrum where it has one): ``√Σ q² variance``
    (:attr:`roughcontact.surfaces.spectra.Spectrum.rms_slope`), dimensionless."""
    return surface.grid_spectrum().rms_slope


def predict(force, surface) -> dict:
    """``{name: A}`` of every area model that applies to *surface* at the forces *force* (1-D)."""
    import numpy as np

    out = {}
    for name, model in models().items():
        area = model.predict(force, surface)
        if area is not None:
            out[name] = np.asarray(area, dtype=float)
    return out
