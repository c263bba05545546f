"""Persson's interfacial law (J. Chem. Phys. 115, 3840 (2001), doi:10.1063/1.1388626; Yang &
Persson, JPCM 20, 215214 (2008)) from a spectrum, under the paraboloid or over a flat surface."""
from __future__ import annotations

from .. import persson as persson_model
from .registry import SELF_AFFINE, Model, Surface, register


def persson(force, s: Surface):
    """Persson's ū(p) from the measured spectrum, else the grid's own discrete one: under the
    paraboloid an axisymmetric compliant layer in series with the half-space
    (:func:`roughcontact.models.persson.sphere_stiffness`, γ = 0.42); a flat surface
    ``k = K(p) L²`` at ``p = F/L²`` (:func:`~roughcontact.models.persson.interfacial_stiffness`).
    Paraboloid only."""
    if s.exponent != 2.0:
        return None
    spectrum = s.grid_spectrum()
    if s.flat:
        return persson_model.interfacial_stiffness(force / s.length**2, spectrum, e_star=s.e_star) * s.length**2
    return persson_model.sphere_stiffness(force, spectrum, radius=s.radius, e_star=s.e_star).stiffness


register(Model("persson", "persson: Persson's interfacial law from the grid's spectrum as a compliant layer under "
                          "the paraboloid", persson, "doi:10.1063/1.1388626",
               # declines (None) off the paraboloid; the grid's spectrum has the roll-off and
               # cutoff; elastic only
               axes=("exponent", "rolloff", "cutoff"), ranges=SELF_AFFINE, precomputable=True))
