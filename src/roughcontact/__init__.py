"""roughcontact: boundary-element contact mechanics of rough spheres.

Reproduces and extends R. Pohrt, V. L. Popov, "Contact Mechanics of Rough
Spheres: Crossover from Fractal to Hertzian Behavior", Adv. Tribol. 2013,
974178 (2013).

Conventions (used throughout):

* ``z`` (``heights``) is the rigid indenter's shape on an ``n × n`` grid of
  square cells of side ``Δ = length/n``, measured from the undeformed
  half-space towards the indenter.
* ``depth`` is the rigid-body approach counted from first touch (0 when
  ``min z`` just touches).
* The half-space surface displacement is ``u = depth − (z − min z)`` wherever
  the pressure is positive; the gap is ``≥ 0`` elsewhere; pressure ``≥ 0``.
* ``force = Σ pressure × Δ²``; ``stiffness = dF/d(depth)``.
* Units are the caller's: results scale exactly as ``F ∝ E*L²``,
  ``k ∝ E*L``, ``d ∝ L``.

Subpackages, bottom up: :mod:`~roughcontact.surfaces` (height maps and spectra,
eqs. 1–3), :mod:`~roughcontact.bem` (the boundary-element solver and stiffness),
:mod:`~roughcontact.models` (the paper's eqs. 7–18 and other closed forms) and
:mod:`~roughcontact.study` (the parameter study; not imported here). Errors are in
:mod:`~roughcontact.errors`.
"""

import importlib
from importlib.metadata import PackageNotFoundError, version

from . import errors, surfaces

try:
    __version__ = version("roughcontact")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0+unknown"

__all__ = ["bem", "errors", "models", "surfaces", "__version__"]


#: the subpackages imported when first used (PEP 562): an indentation job, which needs only the
#: surfaces and the solver, starts without ``models`` (scipy.special, scipy.integrate), and an
#: analysis job, which reads run files, without ``bem`` (scipy.fft, scipy.sparse.linalg)
_LAZY = ("bem", "models")


def __getattr__(name: str):
    """``roughcontact.bem`` and ``roughcontact.models`` imported when first used (:data:`_LAZY`)."""
    if name in _LAZY:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
