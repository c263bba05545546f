"""The one job record of every kind of run: what a run depends on, typed, and nothing else.

Every run of a study is a :class:`RunRecord`: the generated runs and their coarse companions,
adhesive or not (:class:`roughcontact.study.runs.jobs.JobSettings`), a measured scan's tile or a
measured spectrum's seed (:class:`roughcontact.study.runs.measured.MeasuredJob`) and a stickiness
approach (:class:`roughcontact.study.config.stickiness.StickinessRun`). The fields every kind
shares (the grid, ``E*``, the solver's tolerance) are declared here once; a force-controlled load
path adds its force grid and stiffness settings once, in :class:`ForcePathRecord`; each kind
declares only its surface recipe and path. What a record is for, alike for every kind:

* :meth:`~RunRecord.record` -- a flat mapping of plain values: the run rule's ``params`` (the
  job's identity: what makes Snakemake rerun it), the ``config`` its run file records and what the
  file's ``config_hash`` is made of;
* ``file_spec()`` -- what the run's file must be, checked by the one reader
  (:func:`roughcontact.study.files.io.read_run`);
* ``describe()`` -- the one line that names the run in logs and error messages.

Lengths are in the study's length unit, forces normalised ``F/(E* L²)``.
"""
from __future__ import annotations

import abc
import dataclasses

import numpy as np

from .defaults import solver_maxiter

__all__ = ["RunRecord", "ForcePathRecord", "force_grid"]


def force_grid(force_from: float, force_to: float, count: int) -> np.ndarray:
    """The log-spaced load path ``F/(E* L²)`` of a force range ``{from, to, count}``."""
    return np.geomspace(force_from, force_to, int(count))


@dataclasses.dataclass(frozen=True, kw_only=True)
class RunRecord(abc.ABC):
    """The fields every kind of run shares.

    Attributes
    ----------
    n : int or None
        Grid points per side (``None``: set by the input, a measured scan's tile).
    length : float or None
        Side ``L`` of the surface (``None``: set by the input, a measured scan's tile).
    e_star : float
        Effective modulus ``E*`` of the half-space (the study's modulus unit).
    tol : float
        Relative tolerance of every contact solve of the run (:func:`roughcontact.bem.solve`).
    """

    n: int | None
    length: float | None
    e_star: float
    tol: float

    def record(self) -> dict:
        """The settings as a flat mapping of plain values: the run's identity and its file's
        ``config`` (module docstring)."""
        return dataclasses.asdict(self)

    @abc.abstractmethod
    def describe(self) -> str:
        """One line naming the run, for logs and error messages."""

    @abc.abstractmethod
    def file_spec(self):
        """What the run's file must be (:class:`roughcontact.study.files.runfile.RunFileSpec`)."""


@dataclasses.dataclass(frozen=True, kw_only=True)
class ForcePathRecord(RunRecord):
    """A run on a force-controlled, log-spaced load path with the stiffness at every load.

    Attributes
    ----------
    force_from, force_to, force_count :
        The load path ``F/(E* L²)`` (``forces.sphere`` or ``forces.flat``).
    stiffness_method, rel_step :
        How ``k = dF/dd`` is computed (:func:`roughcontact.bem.stiffness`).
    maxiter : int
        Iteration limit of every contact solve (:func:`~roughcontact.study.config.defaults.solver_maxiter`).
    """

    force_from: float
    force_to: float
    force_count: int
    stiffness_method: str
    rel_step: float
    maxiter: int = solver_maxiter(None)

    def forces_normalized(self) -> np.ndarray:
        """The load path ``F/(E* L²)``, log-spaced."""
        return force_grid(self.force_from, self.force_to, self.force_count)
