"""The method of dimensionality reduction (Popov & Heß 2015; Geike & Popov, PRE 76, 036710 (2007),
doi:10.1103/PhysRevE.76.036710) on seeded 1D profiles of the self-affine spectrum."""
from __future__ import annotations

from .. import mdr as mdr_model
from .registry import SELF_AFFINE, Model, Surface, register

#: realisations of the MDR ensemble (relative standard error of k ≈ 0.2–1 % on the paper's sphere)
REALIZATIONS = 1000


def mdr(force, s: Surface):
    """The mean stiffness of :data:`REALIZATIONS` seeded 1D profiles with ``C1D = π q C2D`` of the
    self-affine spectrum (the fitted one for a measured surface: profiles of an arbitrary measured
    spectrum are not built) on a Winkler foundation, the sphere as ``x²/R``
    (:func:`roughcontact.models.mdr.sphere_stiffness`; ``radius = inf``: the flat foundation).
    Paraboloid only."""
    if s.exponent != 2.0:
        return None
    return mdr_model.sphere_stiffness(
        force, radius=s.radius, hurst=s.hurst, h_rms=s.h_rms, length=s.length, n=s.n, e_star=s.e_star,
        rolloff=s.rolloff, cutoff=s.cutoff, realizations=REALIZATIONS, seed=0).stiffness


register(Model("mdr", "mdr: the method of dimensionality reduction, 1000 seeded 1D profiles on a Winkler "
                      "foundation", mdr, "doi:10.1103/PhysRevE.76.036710",
               # declines (None) off the paraboloid; the profiles' spectrum has the roll-off and
               # cutoff; an elastic Winkler foundation
               axes=("exponent", "rolloff", "cutoff"), ranges=SELF_AFFINE, precomputable=True))
