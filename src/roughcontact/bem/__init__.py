"""Boundary-element method: a rigid indenter pressed into an elastic half-space.

The face is :func:`solve` (one load), :func:`load_path` and :func:`iter_load_path`
(warm-started loads), :func:`stiffness` (``k = dF/dd`` of a solved state, :mod:`.incremental`),
:func:`displacement` and :class:`ContactState`. Behind it: the half-space influence
operators (:mod:`.operators`), the constrained conjugate-gradient kernels
(:mod:`.solver`) and their FFT preconditioner (:mod:`.preconditioner`), the windows and working sets they run on (:mod:`.active_sets`), the
flat-punch stiffness (:mod:`.punch`) and penetration-hardness plasticity (:mod:`.plastic`).
Tangential contact, elastic only (the normal–tangential coupling neglected): the Cerruti kernel
(:mod:`.cerruti`), the full-stick stiffness :func:`tangential_stiffness` and Cattaneo–Mindlin
partial slip :func:`partial_slip` (:mod:`.tangential`, loads :mod:`.slip_loads`, kernels
:mod:`.slip_vector` for two traction components and :mod:`.slip` for one), and the
Ciavarella–Jäger construction :func:`ciavarella_jager` (:mod:`.cj_superposition`).
Adhesive paths, elastic only: the detachment criterion (:mod:`.adhesion`) and the Maugis–Dugdale
cohesive zone (:mod:`.cohesive`). The patches of a contact set: :func:`contact_patches`
(:mod:`.patches`). Conventions are those of :mod:`roughcontact`.
"""

from .contact import (
    DEFAULT_MAXITER,
    ContactState,
    displacement,
    iter_load_path,
    load_path,
    solve,
)
from .incremental import stiffness
from .patches import Patches, contact_patches
from .tangential import SlipPath, SlipState, partial_slip, tangential_stiffness
from .cj_superposition import CiavarellaJagerPath, ciavarella_jager

#: the version of the solvers' results: bumped on purpose by a change that alters what a run computes
#: (a run of the pipeline is computed again when it changes; a change that keeps every result does not
#: bump it). History: 1, the solvers of roughcontact 0.1.
SOLVER_VERSION = 1

__all__ = ["SOLVER_VERSION", "DEFAULT_MAXITER", "ContactState", "displacement", "iter_load_path", "load_path", "solve",
           "stiffness", "Patches", "contact_patches", "SlipPath", "SlipState", "partial_slip", "tangential_stiffness",
           "CiavarellaJagerPath", "ciavarella_jager"]
