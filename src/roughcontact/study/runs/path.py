"""The one load-path loop of every run kind: each state recorded, reported and checked once.

A run follows a path of states: the force-controlled loading of a generated or measured run
(:func:`roughcontact.study.runs.indent.solve_load_path`), the adhesive loading of an adhesive run
(:func:`roughcontact.study.runs.adhesive.adhesive_run`) and the displacement-controlled approach
of a stickiness run (:func:`roughcontact.study.runs.stickiness.stickiness_run`). A path kind gives
:class:`LoadPath` its *record*: what to keep of a state and the words that describe it. The
:class:`LoadPath` is what the solver's loop (or its ``on_state`` callback) calls with each state;
it writes the one progress and log line of a state, counts the states and translates a solver's
failure into an :class:`~roughcontact.errors.IndentError` naming the run, the state at which it
failed and what to change (:meth:`LoadPath.failing`).

Only the standard library and the package's errors are imported here.
"""
from __future__ import annotations

import contextlib
import logging
import time
from collections.abc import Callable

from ...errors import IndentError

__all__ = ["LoadPath"]

logger = logging.getLogger(__name__)


class LoadPath:
    """One path being followed: the loop body of every run kind.

    Parameters
    ----------
    name : str
        The run, as log lines and error messages name it (e.g. ``indent H = 0.7, ...``).
    total : int
        States the path has at most (loads, approaches).
    record : callable
        ``record(i, *state) -> str``: keeps what the path kind needs of state *i* (0-based) and
        returns the words of its log line (``F/(E*L^2) = ..., contact cells = ...``); it may raise
        an :class:`~roughcontact.errors.IndentError` for a state that cannot be used.
    what : str
        The word of a state in lines and messages: ``load step`` or ``approach``.
    progress : callable, optional
        ``progress(i, total, text)`` after each state (1-based *i*; the command line's bar).

    Attributes
    ----------
    done : int
        States recorded so far; the state being solved is ``done + 1`` of ``total``.
    """

    def __init__(self, name: str, total: int, record: Callable, *, what: str = "load step",
                 progress: Callable | None = None):
        self.name, self.total, self.record, self.what, self.progress = name, int(total), record, what, progress
        self.done = 0
        self._clock = time.perf_counter()

    def __call__(self, i: int, *state) -> None:
        """Record state *i* (``record(i, *state)``), then log its line and report its progress:
        ``<what> i+1/total: <record's words>, <seconds since the previous state> s``."""
        words = self.record(i, *state)
        now = time.perf_counter()
        text = f"{self.what} {i + 1}/{self.total}: {words}, {now - self._clock:.2f} s"
        self._clock = now
        self.done = i + 1
        logger.info("%s: %s", self.name, text)
        if self.progress is not None:
            self.progress(i + 1, self.total, text)

    @property
    def where(self) -> str:
        """The state being solved, e.g. ``approach 5/16``."""
        return f"{self.what} {self.done + 1}/{self.total}"

    @contextlib.contextmanager
    def failing(self, errors: type | tuple, message: Callable):
        """Translate a solver's *errors* raised in the block into an
        :class:`~roughcontact.errors.IndentError` of ``message(exc)`` (the run, :attr:`where` and
        what to change), chained to the solver's error."""
        try:
            yield self
        except errors as exc:
            raise IndentError(message(exc)) from exc
