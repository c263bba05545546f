"""The indent job's error when the contact reaches the edge names the load that failed."""
from types import SimpleNamespace

import pytest

from roughcontact.errors import DomainTooSmallError, IndentError
from roughcontact.study.runs import indent
from roughcontact.study.runs.jobs import JobSettings

SETTINGS = JobSettings(hurst=0.7, radius=0.5, h_rms=9e-3, seed=0, n=33, length=1.0, e_star=1.0, force_from=1e-5,
                       force_to=1e-3, force_count=5, tol=1e-8, stiffness_method="punch", rel_step=1e-4)


def _fails_at_third_load(*args, **kwargs):
    yield SimpleNamespace(iterations=3)
    yield SimpleNamespace(iterations=3)
    raise DomainTooSmallError("the contact reached the edge")


@pytest.fixture
def edge_at_third_load(monkeypatch):
    monkeypatch.setattr(indent.bem, "iter_load_path", _fails_at_third_load)
    monkeypatch.setattr(indent, "_record", lambda *args: None)


def test_edge_error_names_the_failing_step(edge_at_third_load):
    with pytest.raises(IndentError, match=r"load step 3/5 \(F/\(E\*L\^2\) = 0\.0001\)"):
        indent.compute_run(SETTINGS)


def test_edge_error_suggests_the_last_load_that_worked(edge_at_third_load):
    # loads 1e-5, 3.16e-5, 1e-4, ...: the second (3.16e-5) is the last solved
    with pytest.raises(IndentError, match=r"lower forces.sphere.to to 3.16e-05 or below"):
        indent.compute_run(SETTINGS)
