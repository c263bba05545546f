"""Indenter height maps: self-affine roughness, bodies of revolution, rough spheres, spectral moments.

All maps live on an ``n × n`` grid of square cells of side ``Δ = length/n``; heights are the
indenter's shape ``z``, measured from the undeformed half-space towards the indenter (contact
starts where ``z`` is lowest). Self-affine roughness is :mod:`.roughness` (eqs. 1–3 of the
paper), smooth bodies and rough spheres :mod:`.bodies`, spectral moments :mod:`.moments`.
A user's own surface comes in through :mod:`.measured` (an instrument's scan, read with
SurfaceTopography: the ``measured`` extra), :mod:`.subwindows` (its sub-windows) and :mod:`.psd`
(a measured power spectrum, e.g. contact.engineering's export, as seeded random-phase
surfaces). :mod:`.spectra` is the one representation of an isotropic spectrum that the models
read (the grid's own modes, an analytic band, or a table); :mod:`.profiles` the 1D profiles of
the method of dimensionality reduction.
"""

from .bodies import body_of_revolution, paraboloid, radial_distance, rough_sphere
from .measured import MeasuredSurface, from_topography
from .moments import SpectralMoments, self_affine_moments, spectral_moments
from .psd import PsdTable, read_psd, surface_from_psd
from .roughness import self_affine, wavevectors
from .spectrum_fit import SpectrumFit, fit_spectrum
from .subwindows import EdgeJump, edge_jump, tiles

__all__ = [
    "EdgeJump",
    "MeasuredSurface",
    "PsdTable",
    "SpectralMoments",
    "SpectrumFit",
    "edge_jump",
    "fit_spectrum",
    "from_topography",
    "read_psd",
    "surface_from_psd",
    "tiles",
    "body_of_revolution",
    "paraboloid",
    "radial_distance",
    "rough_sphere",
    "self_affine",
    "self_affine_moments",
    "spectral_moments",
    "wavevectors",
]
