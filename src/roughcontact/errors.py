"""The package's exceptions: one base class, one child per kind of failure.

Every error the package raises on purpose is a :class:`RoughContactError`, so a caller can
catch them all at once; each child also derives from the built-in exception it refines
(``ValueError`` for bad input, ``RuntimeError`` for a computation that cannot finish), so
code that catches those keeps working. ``str(err)`` is one line that names what to change.
"""
from __future__ import annotations

__all__ = [
    "RoughContactError",
    "ConfigError",
    "InputFileError",
    "ConvergenceError",
    "DomainTooSmallError",
    "IndentError",
    "MergeError",
]


class RoughContactError(Exception):
    """Base class of every error raised on purpose by :mod:`roughcontact`."""


class ConfigError(RoughContactError, ValueError):
    """An invalid configuration; ``str(err)`` is one line naming the key.

    Attributes
    ----------
    key : str or None
        The configuration key the error is about, as the message names it (``'grid.n'``,
        ``'hurst[0]'``); ``None`` where no single key is at fault. The command line maps it
        to its flag.
    """

    def __init__(self, message: str, *, key: str | None = None):
        super().__init__(message)
        self.key = key


class InputFileError(RoughContactError, ValueError):
    """An input file (a measured topography, a spectrum table) that cannot be used.

    ``str(err)`` is one line naming the file and what is wrong.

    Attributes
    ----------
    parameter : str or None
        The argument of the reading function that would fix it (``"length"`` where the file gives
        no physical size), spelled ``parameter=`` in the message; :meth:`reworded` names it as
        a caller's interface does (``--size``, ``topography[0].size``).
    """

    def __init__(self, message: str, *, parameter: str | None = None):
        super().__init__(message)
        self.parameter = parameter

    def reworded(self, names: dict) -> str:
        """The message with ``parameter=`` named by ``names[parameter]`` (unchanged without one)."""
        if self.parameter is None or self.parameter not in names:
            return str(self)
        return str(self).replace(f"{self.parameter}=", names[self.parameter])


class ConvergenceError(RoughContactError, RuntimeError):
    """An iterative solve that did not reach its stopping test within its iteration limit."""


class DomainTooSmallError(RoughContactError, RuntimeError):
    """The contact reached the edge of the free-space (non-periodic) grid."""


class IndentError(RoughContactError, RuntimeError):
    """A run that cannot produce trustworthy numbers (no convergence, or the contact
    reached the edge of the free-space grid); the message names the run and what to change."""


class MergeError(RoughContactError, RuntimeError):
    """A run file that cannot be merged; the message names the file and the cause."""
