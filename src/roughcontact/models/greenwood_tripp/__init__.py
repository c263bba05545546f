"""Greenwood & Tripp (1967): the elastic contact of a rough sphere (J. Appl. Mech. 34, 153):
a smooth elastic sphere on a Greenwood–Williamson surface of independent summits, the model and
its notation in :mod:`roughcontact.models.greenwood_tripp.solver`.

* :mod:`~roughcontact.models.greenwood_tripp.solver` — GT's integral equation in their
  dimensionless units (the units, the kernel and the limits are in its docstring):
  :func:`gt_function`, :func:`influence_matrix`, :func:`greenwood_tripp`,
  :class:`GreenwoodTrippSolution`;
* :mod:`~roughcontact.models.greenwood_tripp.sphere` — the load curve in physical units:
  :func:`greenwood_tripp_curve`, :func:`self_affine_sphere_curve`, :class:`GreenwoodTrippCurve`.

Summit statistics (``η``, ``β``, ``σ``) from a surface's spectral moments:
:mod:`roughcontact.models.asperities` on the moments of :mod:`roughcontact.surfaces.moments`.
"""

from .solver import GreenwoodTrippSolution, greenwood_tripp, gt_function, influence_matrix
# SPHERE_DEPTHS_STAR (the default d* of self_affine_sphere_curve) is public but not in __all__
from .sphere import (SPHERE_DEPTHS_STAR, GreenwoodTrippCurve,  # noqa: F401
                     greenwood_tripp_curve, self_affine_sphere_curve)

__all__ = [
    "GreenwoodTrippCurve",
    "GreenwoodTrippSolution",
    "greenwood_tripp",
    "greenwood_tripp_curve",
    "self_affine_sphere_curve",
    "gt_function",
    "influence_matrix",
]
