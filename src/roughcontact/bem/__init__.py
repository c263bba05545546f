"""Boundary-element method: a rigid indenter pressed into an elastic half-space.

The face is :func:`solve` (one load), :func:`load_path` and :func:`iter_load_path`
(warm-started loads), :func:`stiffness` (``k = dF/dd`` of a solved state),
:func:`displacement` and :class:`ContactState`. Behind it: the half-space influence
operators (:mod:`.operators`), the constrained conjugate-gradient kernels
(:mod:`.solver`), the windows and working sets they run on (:mod:`.active_sets`), the
flat-punch stiffness (:mod:`.punch`) and penetration-hardness plasticity (:mod:`.plastic`).
Adhesive paths, elastic only: the detachment criterion (:mod:`.adhesion`) and the Maugis–Dugdale
cohesive zone (:mod:`.cohesive`). Conventions are those of :mod:`roughcontact`.
"""

from .contact import (
    DEFAULT_MAXITER,
    ContactState,
    displacement,
    iter_load_path,
    load_path,
    solve,
    stiffness,
)

__all__ = ["DEFAULT_MAXITER", "ContactState", "displacement", "iter_load_path", "load_path", "solve",
           "stiffness"]
