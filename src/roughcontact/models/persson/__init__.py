"""Persson's contact theory on a :class:`~roughcontact.surfaces.spectra.Spectrum`, flat and spherical.

* :mod:`~roughcontact.models.persson.interface` — the flat interface law: :func:`w`,
  :func:`contact_area_fraction`, :func:`mean_separation`, :func:`interfacial_stiffness`,
  :func:`separation_scale`;
* :mod:`~roughcontact.models.persson.sphere` — the rough sphere on it: :func:`sphere_stiffness`,
  :class:`SphereStiffness`.

Units, the bin sums and the references (DOIs) are in
:mod:`roughcontact.models.persson.interface`.
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
