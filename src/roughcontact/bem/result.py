"""The result of one kernel solve (:mod:`roughcontact.bem.solver`, :mod:`roughcontact.bem.bounded`)."""

from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["KernelResult"]


@dataclasses.dataclass(frozen=True, kw_only=True, eq=False)
class KernelResult:
    """One load solved on one window or set of cells.

    Attributes
    ----------
    pressure : numpy.ndarray
        Pressure on the cells solved (the shape of the kernel's ``lift``; pressure unit).
    depth : float
        The multiplier of the force constraint: the depth (length unit, from the kernel's
        reference).
    iterations : int
        Iterations spent.
    converged : bool
        Whether the kernel's stopping test was met within ``maxiter``.
    error : float
        The stopping test's left side over ``|d|`` at the last iterate.
    diagnosis : str
        Empty when converged; otherwise one sentence: why the kernel stopped, what it tried and
        where the violation is.
    """

    pressure: np.ndarray
    depth: float
    iterations: int
    converged: bool
    error: float
    diagnosis: str = ""

    def spent(self, earlier: int) -> "KernelResult":
        """This result with ``earlier`` iterations of previous passes added."""
        return dataclasses.replace(self, iterations=self.iterations + earlier)
