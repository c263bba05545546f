"""The progress bar of ``roughcontact indent`` (:func:`roughcontact.cli.progress.progress_bar`): as wide
as the terminal, its bar never squeezed by the load step's words, shown at a fallback width where the
terminal reports no size, and as plain-text lines where standard error is no terminal."""
from __future__ import annotations

import contextlib
import fcntl
import io
import os
import pty
import struct
import sys
import termios

import pytest

from roughcontact import cli
from roughcontact.cli import progress

DESC = "H=0.7 R=0.5 seed=0"
#: a load step's words, as the load path logs them (longer than a 120-column line leaves)
WORDS = "F/(E*L^2) = 2.000e-02, iterations = 16, contact cells = 452, k/(E*L) = 1.2345e-01, converged = 1"


@pytest.fixture(autouse=True)
def no_size_elsewhere(monkeypatch):
    """No $COLUMNS and a standard output of no terminal: the fallback is FALLBACK_COLUMNS wherever
    the tests run (shutil.get_terminal_size reads both)."""
    monkeypatch.delenv("COLUMNS", raising=False)
    monkeypatch.setattr(sys, "__stdout__", io.StringIO())


@contextlib.contextmanager
def _terminal(columns: int):
    """A pseudo-terminal of *columns* columns (0: one that reports no size), as a text file."""
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 40 if columns else 0, columns, 0, 0))
    with os.fdopen(slave, "w", encoding="utf-8") as file:
        try:
            yield file
        finally:
            os.close(master)


def _stepped(file, steps=3, total=5):
    """A bar on *file* after *steps* of *total* load steps, each given WORDS (as run_indent does)."""
    bar = progress.progress_bar(total, DESC, file=file)
    for _ in range(steps):
        bar.set_postfix_str(WORDS, refresh=False)
        bar.update(1)
    return bar


def _bar(line: str) -> str:
    """The bar of a tqdm line: between its first two '|'."""
    return line.split("|")[1]


def test_the_line_fills_a_120_column_terminal():
    with _terminal(120) as tty:
        bar = _stepped(tty)
        line = str(bar)
        bar.close()
    assert len(line) == 119   # the last column left free: a full line wraps on some terminals


def test_the_bar_keeps_its_width_beside_the_load_steps_words():
    with _terminal(120) as tty:
        bar = _stepped(tty)
        line = str(bar)
        bar.close()
    assert len(_bar(line)) >= progress.MIN_BAR


def test_the_load_steps_words_are_cut_to_whole_fields():
    with _terminal(120) as tty:
        bar = _stepped(tty)
        line = str(bar)
        bar.close()
    assert line.endswith("F/(E*L^2) = 2.000e-02, iterations = 16]")


def test_a_terminal_without_size_gets_the_fallback_width():
    with _terminal(0) as tty:
        bar = _stepped(tty)
        line = str(bar)
        bar.close()
    assert len(line) == progress.FALLBACK_COLUMNS - 1


def test_a_terminal_without_size_shows_the_bar():
    with _terminal(0) as tty:
        bar = _stepped(tty)
        line = str(bar)
        bar.close()
    assert len(_bar(line)) >= progress.MIN_BAR   # before: no line at all


def test_no_terminal_gets_lines_without_carriage_returns():
    out = io.StringIO()
    _stepped(out, steps=5).close()
    assert "\r" not in out.getvalue()


def test_no_terminal_gets_a_first_and_a_last_line():
    out = io.StringIO()
    _stepped(out, steps=5).close()
    assert [line.split("|")[2].split()[0] for line in out.getvalue().splitlines()] == ["0/5", "5/5"]


def test_no_terminal_gets_lines_of_the_fallback_width():
    out = io.StringIO()
    _stepped(out, steps=5).close()
    assert [len(line) for line in out.getvalue().splitlines()] == [progress.FALLBACK_COLUMNS] * 2


def test_no_terminal_gets_lines_of_COLUMNS(monkeypatch):
    monkeypatch.setenv("COLUMNS", "132")
    out = io.StringIO()
    _stepped(out, steps=5).close()
    assert [len(line) for line in out.getvalue().splitlines()] == [132, 132]


def test_fit_postfix_keeps_the_fields_that_fit():
    assert progress.fit_postfix("a = 1, b = 22, c = 3", 13) == "a = 1, b = 22"


def test_fit_postfix_drops_a_field_that_does_not_fit_whole():
    assert progress.fit_postfix("abcdefghijk = 1, b = 2", 10) is None


def test_indent_draws_progress_lines_on_a_pipe(tmp_path):
    """`roughcontact indent` with standard error no terminal (here a StringIO): plain lines, the last
    one at 3/3 of the loads."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = cli.main(["indent", "--hurst", "0.7", "--radius", "0.5", "--h-rms", "9e-3", "--n", "17",
                         "--force-count", "3", "-o", str(tmp_path / "run.nc")])
    assert (code, [line.split("|")[2].split()[0] for line in err.getvalue().splitlines()[:-1]]) == (0, ["0/3", "3/3"])
