"""The solver settings the study derives from the configuration's, each written once.

The configuration's own defaults live in its schema (``config.schema.yaml``); these are the two
rules every kind of run applies on top of them: the tolerance cap of the adhesive and cohesive
solves, and the iteration limit where ``solver.maxiter`` is not set. Imports only the core's
default iteration limit, so every module of the study (the typed settings included) may use it.
"""
from __future__ import annotations

from ..._defaults import DEFAULT_MAXITER  # (not from bem: a job that only reads runs imports no solver)

__all__ = ["ADHESIVE_TOL_CAP", "capped_tol", "solver_maxiter"]

#: the loosest relative tolerance of an adhesive or cohesive solve (the adhesive retract and the
#: stickiness approach), whatever ``solver.tol`` is: their pull-off and loading slope need it
ADHESIVE_TOL_CAP = 1e-8


def capped_tol(tol: float) -> float:
    """The tolerance of an adhesive or cohesive solve: ``solver.tol``, at most :data:`ADHESIVE_TOL_CAP`."""
    return min(tol, ADHESIVE_TOL_CAP)


def solver_maxiter(maxiter: int | None) -> int:
    """The iteration limit of a run's solves: ``solver.maxiter``, or the solver's default
    (:data:`roughcontact.bem.DEFAULT_MAXITER`) where the configuration leaves it ``None``."""
    return DEFAULT_MAXITER if maxiter is None else int(maxiter)
