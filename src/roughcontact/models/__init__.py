"""Closed-form and semi-analytic models of rough contact stiffness.

:mod:`.paper` holds the analytic model of Pohrt & Popov (2013), eqs. 7–18 (eq. 15's equivalent
profile included); :mod:`.greenwood_tripp` the rough sphere of Greenwood & Tripp (1967) on the
summit statistics of :mod:`.asperities`; :mod:`.mdr` the method of dimensionality reduction;
:mod:`.persson` Persson's theory, flat and (through :mod:`.axisymmetric`) under a sphere.
:func:`effective_modulus` gives ``E*`` of two elastic bodies; :mod:`.adhesion` the adhesive smooth
sphere (JKR, DMT, Maugis–Dugdale); :mod:`.rough_adhesion` adhesion of rough surfaces (Fuller &
Tabor's asperities, Johnson's rough-sphere parameter, Pastewka & Robbins' stickiness);
:mod:`.tangential` the tangential stiffness (Mindlin, Cattaneo–Mindlin, the MDR's rough sphere);
:mod:`.scorecard` the registry of the scorecard's models. Models use the spectra and profiles of
:mod:`roughcontact.surfaces` and never the boundary-element method.
"""

import importlib

from .elasticity import effective_modulus

__all__ = ["asperities", "axisymmetric", "greenwood_tripp", "mdr", "paper", "persson", "tangential", "effective_modulus"]

#: the submodules, each imported when first used (PEP 562): ``from roughcontact.models import paper``
#: loads the paper's equations without Persson's theory or Greenwood–Tripp (scipy.integrate, ...)
_SUBMODULES = frozenset(__all__) - {"effective_modulus"}


def __getattr__(name: str):
    if name in _SUBMODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | _SUBMODULES)
