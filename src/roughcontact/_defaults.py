"""Defaults that a layer above reads without importing the layer that owns them: the solver's
iteration limit (:mod:`roughcontact.bem`, re-exported there), read by the study's run records
without importing the solver (scipy.fft, scipy.sparse.linalg) into a job that only reads runs."""

#: Default maximum number of conjugate-gradient iterations per solve.
DEFAULT_MAXITER = 10_000
