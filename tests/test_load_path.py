"""The one load-path loop (roughcontact.study.runs.path.LoadPath): each state recorded by its path
kind, one progress and log line per state, and a solver's failure translated once into an
IndentError naming the run, the state and what to change."""
from __future__ import annotations

import numpy as np
import pytest

from roughcontact.errors import ConvergenceError, IndentError
from roughcontact.study.runs.path import LoadPath


def test_each_state_is_recorded_and_reported_once():
    kept, lines = [], []
    follow = LoadPath("run A", 3, lambda i, x: kept.append(x) or f"x = {x:g}", what="approach",
                      progress=lambda i, total, text: lines.append((i, total, text)))
    for i, x in enumerate([0.5, 1.5]):
        follow(i, x)
    assert kept == [0.5, 1.5] and follow.done == 2
    assert [(i, total) for i, total, _ in lines] == [(1, 3), (2, 3)]
    assert lines[1][2].startswith("approach 2/3: x = 1.5, ") and lines[1][2].endswith(" s"), lines[1][2]
    assert follow.where == "approach 3/3", "the state being solved next"


def test_a_solver_failure_names_the_state_it_failed_at():
    follow = LoadPath("run B", 4, lambda i: "ok")
    with pytest.raises(IndentError, match=r"run B failed at load step 2/4 \(no luck\); do less") as info:
        with follow.failing(ConvergenceError, lambda exc: f"run B failed at {follow.where} ({exc}); do less"):
            follow(0)
            raise ConvergenceError("no luck")
    assert isinstance(info.value.__cause__, ConvergenceError), "chained to the solver's error"


def test_other_errors_pass_through():
    follow = LoadPath("run C", 1, lambda i: "ok")
    with pytest.raises(ValueError):
        with follow.failing(ConvergenceError, lambda exc: "never"):
            raise ValueError("not the solver's")


def test_a_record_that_rejects_a_state_stops_the_path():
    """A path kind's record raises IndentError for a state it cannot use: nothing is counted."""
    def record(i, k):
        if not np.isfinite(k):
            raise IndentError(f"state {i + 1}: k = {k}")
        return "fine"

    follow = LoadPath("run D", 2, record)
    follow(0, 1.0)
    with pytest.raises(IndentError, match="state 2: k = nan"):
        follow(1, float("nan"))
    assert follow.done == 1
