"""The progress bar of ``roughcontact indent``: as wide as the terminal, and shown when the terminal's
size is unknown.

:func:`progress_bar` builds it (a ``tqdm`` bar, :class:`ProgressBar`) on standard error or *file*:

- on a terminal that reports its size, one line as wide as the terminal (less the last column, which
  wraps on some terminals), following a resize (:func:`bar_columns` at every redraw);
- on a terminal that reports no size (0 columns), the same line at the width
  :func:`shutil.get_terminal_size` gives (``$COLUMNS``, standard output's terminal, else
  :data:`FALLBACK_COLUMNS`);
- on anything else (a file, a pipe, a log), plain-text lines of that width, one per
  :data:`PLAIN_INTERVAL` seconds at most and one at the end, instead of a line redrawn with carriage
  returns.

The load step's words (``F/(E*L^2) = ..., iterations = ..., contact cells = ...``) follow the bar as its
postfix, cut to whole fields where the line is too narrow: the bar keeps :data:`MIN_BAR` columns
(before, a long postfix squeezed it to one).
"""
from __future__ import annotations

import os
import shutil
import sys

from tqdm.std import tqdm
from tqdm.utils import disp_len

__all__ = ["FALLBACK_COLUMNS", "MIN_BAR", "PLAIN_INTERVAL", "ProgressBar", "bar_columns", "fit_postfix",
           "progress_bar", "terminal_columns"]

#: the width of a bar whose terminal reports no size, and of the plain lines (without ``$COLUMNS``)
FALLBACK_COLUMNS = 80
#: the fewest columns of the bar itself (tqdm's own width of a bar without a line width)
MIN_BAR = 10
#: the fewest seconds between two plain-text progress lines (a file or a pipe)
PLAIN_INTERVAL = 5.0


def terminal_columns(file) -> int | None:
    """The columns of the terminal *file* writes to; ``None`` if it is no terminal or reports no size."""
    try:
        if not file.isatty():
            return None
        columns = os.get_terminal_size(file.fileno()).columns
    except (AttributeError, ValueError, OSError):
        return None
    return columns if columns > 0 else None


def _fallback_columns() -> int:
    return shutil.get_terminal_size((FALLBACK_COLUMNS, 24)).columns


def bar_columns(file) -> int:
    """The width of the progress line on *file*: its terminal's columns less one, else (a terminal
    of no size) the fallback less one, else (no terminal) the fallback: ``$COLUMNS``, standard
    output's terminal or :data:`FALLBACK_COLUMNS`."""
    if file.isatty() if hasattr(file, "isatty") else False:
        return (terminal_columns(file) or _fallback_columns()) - 1
    return _fallback_columns()


def fit_postfix(postfix: str | None, room: int) -> str | None:
    """*postfix* (``a = 1, b = 2, ...``) in at most *room* columns: its leading fields that fit whole,
    else nothing (half a field, ``F/(E*L^...``, says nothing)."""
    if not postfix or disp_len(postfix) <= room:
        return postfix
    kept = []
    for field in postfix.split(", "):
        if disp_len(", ".join([*kept, field])) > room:
            break
        kept.append(field)
    return ", ".join(kept) or None


class _Lines:
    """A file for tqdm that writes each redraw of the status line as a line of its own (a file or a
    pipe has no carriage return to go back to); the blank writes of a clear or a close are dropped."""

    def __init__(self, file):
        self.file = file

    def write(self, text: str) -> None:
        line = text.replace("\r", "").rstrip()
        if line:
            self.file.write(line + "\n")

    def flush(self) -> None:
        self.file.flush()


class ProgressBar(tqdm):
    """A ``tqdm`` bar whose line is :func:`bar_columns` wide at every redraw (a resized terminal
    followed, a terminal of no size given the fallback) and whose postfix never squeezes the bar
    below :data:`MIN_BAR` columns (:func:`fit_postfix`)."""

    def __init__(self, *args, target=None, **kwargs):
        self._target = target if target is not None else sys.stderr   # before tqdm's first redraw
        super().__init__(*args, **kwargs)

    @property
    def format_dict(self):
        fields = super().format_dict
        if self.disable and not hasattr(self, "unit"):   # tqdm's stand-in of a bar never set up
            return fields
        columns = bar_columns(self._target)
        fields["ncols"] = columns
        if fields.get("postfix"):
            # the line without the postfix, its bar at tqdm's own MIN_BAR columns
            bare = disp_len(self.format_meter(**{**fields, "postfix": None, "ncols": None}))
            fields["postfix"] = fit_postfix(fields["postfix"], columns - bare - len(", "))
        return fields


def progress_bar(total: int, desc: str, file=None, unit: str = "load") -> ProgressBar:
    """The progress bar of *total* steps named *desc* on *file* (default: standard error at the
    call), as the module's docstring says: a line as wide as the terminal, redrawn, or plain-text
    lines where *file* is no terminal."""
    target = sys.stderr if file is None else file
    plain = not (target.isatty() if hasattr(target, "isatty") else False)
    return ProgressBar(total=total, desc=desc, unit=unit, target=target, file=_Lines(target) if plain else target,
                       ncols=bar_columns(target), mininterval=PLAIN_INTERVAL if plain else 0.1)
