"""Persson's contact theory on a :class:`~roughcontact.surfaces.spectra.Spectrum`, flat and spherical.

Every integral over wavenumbers is a sum over the spectrum's bins,
``∫ d²q C(q) g(q) → Σ_i variance_i g(q_i)`` (the sums are spelled out in
:mod:`roughcontact.models.persson.interface`): with the grid's own discrete spectrum
(:func:`roughcontact.surfaces.spectra.from_heights`) the theory sees exactly the modes of the
finite system, the ``q0`` shell included.

* :mod:`~roughcontact.models.persson.interface` — the flat interface law: :func:`w`,
  :func:`contact_area_fraction`, :func:`mean_separation`, :func:`interfacial_stiffness`,
  :func:`separation_scale`;
* :mod:`~roughcontact.models.persson.sphere` — the rough sphere on it: :func:`sphere_stiffness`,
  :class:`SphereStiffness`.

``E*`` is the effective modulus (force/length²), pressures are nominal (mean)
pressures in force/length²; lengths are the spectrum's unit.

References
----------
B. N. J. Persson, J. Chem. Phys. 115, 3840 (2001), doi:10.1063/1.1388626 (area).
B. N. J. Persson, Phys. Rev. Lett. 99, 125502 (2007), doi:10.1103/PhysRevLett.99.125502
(separation against pressure).
C. Yang, B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214 (2008),
doi:10.1088/0953-8984/20/21/215214 (elastic energy, γ ≈ 0.42).
"""

from .interface import (contact_area_fraction, interfacial_stiffness, mean_separation,
                        separation_scale, w)
from .sphere import SphereStiffness, sphere_stiffness

__all__ = [
    "SphereStiffness",
    "contact_area_fraction",
    "interfacial_stiffness",
    "mean_separation",
    "separation_scale",
    "sphere_stiffness",
    "w",
]
