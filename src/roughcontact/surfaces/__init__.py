"""Indenter height maps: self-affine roughness, bodies of revolution, rough spheres, spectral moments.

All maps live on an ``n × n`` grid of square cells of side ``Δ = length/n``; heights are the
indenter's shape ``z``, measured from the undeformed half-space towards the indenter (contact
starts where ``z`` is lowest). Self-affine roughness is :mod:`.roughness` (eqs. 1–3 of the
paper), smooth bodies and rough spheres :mod:`.bodies`, spectral moments :mod:`.moments`.
"""

from .bodies import body_of_revolution, paraboloid, radial_distance, rough_sphere
from .moments import SpectralMoments, self_affine_moments, spectral_moments
from .roughness import self_affine, wavevectors

__all__ = [
    "SpectralMoments",
    "body_of_revolution",
    "paraboloid",
    "radial_distance",
    "rough_sphere",
    "self_affine",
    "self_affine_moments",
    "spectral_moments",
    "wavevectors",
]
