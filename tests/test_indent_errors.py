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


# --- a solve that does not converge: its one line, and the loads solved before it ----------------

HARD = JobSettings(hurst=0.7, radius=0.5, h_rms=9e-3, seed=0, n=65, length=1.0, e_star=1.0, force_from=1e-4,
                   force_to=1e-3, force_count=4, tol=1e-8, stiffness_method="punch", rel_step=1e-4,
                   options=(("hardness", 0.03),))


@pytest.fixture
def stalls_at_third_load(monkeypatch, tmp_path):
    """The hardness path of HARD with maxiter cut to 2 from the third load on: the run fails there."""
    original = indent.bem.iter_load_path

    def cut(z, forces, **kwargs):
        states = original(z, forces[:2], **kwargs)
        yield from states
        last = kwargs.pop("maxiter")
        yield from original(z, forces[2:], maxiter=2, **kwargs)
        assert last

    monkeypatch.setattr(indent.bem, "iter_load_path", cut)
    output = tmp_path / "run.nc"
    with pytest.raises(IndentError) as info:
        indent.run_indent(HARD, output)
    return output, str(info.value)


def test_stall_message_is_one_line(stalls_at_third_load):
    _, message = stalls_at_third_load
    assert "\n" not in message


def test_stall_message_names_the_load(stalls_at_third_load):
    _, message = stalls_at_third_load
    assert "did not converge at load step 3/4" in message


def test_stall_message_says_what_the_kernel_tried(stalls_at_third_load):
    _, message = stalls_at_third_load
    assert "projected-gradient steps" in message and "largest violation at cell" in message


def test_stall_leaves_no_output(stalls_at_third_load):
    output, _ = stalls_at_third_load
    assert not output.exists()


def test_stall_keeps_the_loads_solved_before(stalls_at_third_load):
    xr = pytest.importorskip("xarray")
    output, message = stalls_at_third_load
    kept = indent.partial_path(output)
    assert kept in message
    with xr.open_dataset(kept) as run:
        assert run["force"].size == 2


def test_stall_file_says_why(stalls_at_third_load):
    xr = pytest.importorskip("xarray")
    output, _ = stalls_at_third_load
    with xr.open_dataset(indent.partial_path(output)) as run:
        assert "did not converge at load step 3/4" in run.attrs["failure"]
