"""Pastewka & Robbins' stickiness of nominally flat surfaces (the ``stickiness`` section; claim (q)).

Pastewka & Robbins (PNAS 111 (2014) 3298, doi:10.1073/pnas.1320846111) find that a rough
surface pressed into an adhesive half-space is *sticky* — its contact grows while the load
falls, so that it holds a finite area at zero or tensile load — when their number
``N = (h′E*Δr/(2w)) (h′²/(h″Δr))^(2/3)`` is below 1 (:func:`roughcontact.models.rough_adhesion.
pastewka_robbins_stickiness`; ``h′`` the rms gradient, ``h″`` the rms of ``∇²h/2``, ``Δr`` the
range of the interaction and ``w`` its work). Their criterion assumes a wide band of roughness
and ``Δr`` small against ``g₀ = (16/3)h′²/h″``.

The study presses periodic self-affine surfaces with a short-wavelength cutoff into a half-space
that sticks by a Maugis–Dugdale law (:mod:`roughcontact.bem.cohesive`), by displacement, up to a
contact fraction, and measures the loading slope ``F/A`` there
(:mod:`roughcontact.study.stickiness.run`); the runs are merged into a table with intervals over
seeds (:mod:`roughcontact.study.stickiness.merge`) that claim (q) reads. The sweep is
:class:`roughcontact.study.stickiness.settings.StickinessSettings`.

Imports the core and numpy only; xarray and matplotlib where they are used.
"""
from .run import loading_slope, stickiness_run
from .settings import StickinessRun, StickinessSettings

__all__ = ["StickinessRun", "StickinessSettings", "loading_slope", "stickiness_run"]
