"""The fast paths of the solver give the whole-grid solution: working sets, dense limits,
pruned convolutions, lazily grown influence tables."""

import numpy as np
import pytest
import scipy.fft

from roughcontact import bem
from roughcontact import surfaces
from roughcontact.bem import active_sets
from roughcontact.bem import operators
from roughcontact.bem import solver

E_STAR = 1.0
FORCES = np.geomspace(1e-5, 3e-3, 6)


@pytest.fixture(scope="module")
def flat_surface():
    return surfaces.self_affine(129, hurst=0.7, h_rms=9e-3, length=1.0, seed=5)


def _record_working_sets(monkeypatch):
    """Wrap active_sets.solve_working_set; returns the list of its results."""
    results = []
    original = active_sets.solve_working_set
    monkeypatch.setattr(active_sets, "solve_working_set",
                        lambda *args: results.append(original(*args)) or results[-1])
    return results


def _assert_whole_grid(states, z, forces, hardness=None):
    for force, state in zip(forces, states):
        full = bem.solve(z, force=force, length=1.0, e_star=E_STAR, periodic=True,
                             windowed=False, hardness=hardness)
        assert state.converged, f"not converged at F = {force:g}"
        assert state.depth == pytest.approx(full.depth, rel=1e-7), f"depth differs at F = {force:g}"
        assert np.array_equal(state.contact, full.contact), f"contact set differs at F = {force:g}"


def test_working_set_equals_whole_grid(flat_surface, monkeypatch):
    """Loads whose candidates exceed the dense limit are solved on a working set, and give
    the whole-grid FFT solution."""
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 600)
    results = _record_working_sets(monkeypatch)
    states = bem.load_path(flat_surface, FORCES, length=1.0, e_star=E_STAR, periodic=True)
    assert any(r is not None for r in results), "no load was solved on a working set"
    _assert_whole_grid(states, flat_surface, FORCES)


def test_working_set_that_outgrows_the_limit_continues_on_the_grid(flat_surface, monkeypatch):
    """A working set that would exceed the dense limit hands its pressure to the FFT solver;
    the result is still the whole-grid solution."""
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 150)
    monkeypatch.setattr(active_sets, "WORKING_MARGIN", 0.0)  # a first set too small: it must grow
    results = _record_working_sets(monkeypatch)
    states = bem.load_path(flat_surface, FORCES, length=1.0, e_star=E_STAR, periodic=True)
    assert any(r is not None for r in results), "no load went through the working set"
    _assert_whole_grid(states, flat_surface, FORCES)


def test_working_set_with_hardness(flat_surface, monkeypatch):
    """The capped kernel on a working set gives the capped whole-grid solution."""
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 600)
    results = _record_working_sets(monkeypatch)
    hardness = 0.05
    forces = FORCES[-3:]
    states = []
    for force in forces:  # each from the elastic state of the previous load: no flow history
        initial = states[-1].pressure if states else None
        states.append(bem.solve(flat_surface, force=force, length=1.0, e_star=E_STAR,
                                    periodic=True, hardness=hardness, initial=initial))
    assert any(r is not None for r in results), "no load was solved on a working set"
    assert any(s.plastic.any() for s in states), "the cap was never reached"
    _assert_whole_grid(states, flat_surface, forces, hardness=hardness)


def test_dense_limit_grows_with_the_periodic_grid(monkeypatch):
    """At least DENSE_CELLS, more on larger periodic grids, at most DENSE_BYTES of matrix;
    DENSE_CELLS = 0 switches dense matrices off."""
    limits = [active_sets.dense_limit(operators.PeriodicOperator(n, 1.0, 1.0)) for n in (129, 513, 1025)]
    assert limits[0] == limits[1] == active_sets.DENSE_CELLS
    assert limits[2] == int(np.sqrt(active_sets.DENSE_BYTES // 8))
    assert active_sets.dense_limit(operators.FreeSpaceOperator(1025, 1.0, 1.0)) == active_sets.DENSE_CELLS
    monkeypatch.setattr(active_sets, "DENSE_CELLS", 0)
    assert active_sets.dense_limit(operators.PeriodicOperator(1025, 1.0, 1.0)) == 0


@pytest.mark.parametrize("periodic", [False, True])
def test_influence_blocks_and_out(periodic):
    """Rectangular blocks (other source cells) and ``out=`` give the entries of the square matrix."""
    n = 65
    op = operators.operator_for(n, 1.0, 2.0, periodic)
    rng = np.random.default_rng(1)
    cells = rng.choice(n * n, 700, replace=False)  # more rows than one gathered block
    rows, cols = np.divmod(cells, n)
    full = op.influence_matrix(rows, cols)
    offsets = np.abs(rows[:, None] - rows[None, :]), np.abs(cols[:, None] - cols[None, :])
    if periodic:
        expected = op(np.eye(1, n * n).reshape(n, n))[
            (rows[:, None] - rows[None, :]) % n, (cols[:, None] - cols[None, :]) % n]
    else:
        expected = op.coefficients[offsets]
    assert np.array_equal(full, expected), "square influence matrix"
    out = np.full((400, 450), np.nan)
    block = op.influence_matrix(rows[:300], cols[:300], rows[250:], cols[250:], out=out[:300, :450])
    assert np.array_equal(block, full[:300, 250:]) and np.array_equal(out[:300], full[:300, 250:])


def test_free_coefficients_grow_on_demand():
    """The lazily grown table holds Love's coefficients: a window's convolution and the
    whole table equal those computed on the whole grid at once."""
    n = 97
    op = operators.FreeSpaceOperator(n, 2.0, 3.0)
    scale = (2.0 / n) / (np.pi * 3.0)
    rng = np.random.default_rng(2)
    pressure = rng.uniform(size=(20, 17))
    small = op(pressure)
    assert op._table.shape[0] < n, "the table was built for the whole grid"
    assert np.array_equal(op.coefficients, operators.love_coefficients(n) * scale)
    assert np.allclose(small, op(pressure), rtol=0, atol=1e-14 * np.abs(small).max())


def test_pruned_convolution_equals_padded_fft():
    """The axis-by-axis pruned transforms equal rfft2/irfft2 of the zero-padded window."""
    n = 128
    op = operators.FreeSpaceOperator(n, 1.0, 1.0)
    rng = np.random.default_rng(3)
    pressure = rng.uniform(size=(45, 61))
    padded, spectrum = op._spectrum(pressure.shape)
    reference = scipy.fft.irfft2(scipy.fft.rfft2(pressure, s=padded) * spectrum, s=padded)[:45, :61]
    assert np.allclose(op(pressure), reference, rtol=0, atol=1e-14 * np.abs(reference).max())


def test_single_precision_phase_gives_the_double_solution(flat_surface, monkeypatch):
    """Periodic P&K iterations convolve in single precision while the error is large; the
    accepted state is checked in double precision and equals the all-double solve."""
    calls = []
    single = operators.PeriodicOperator.single
    monkeypatch.setattr(operators.PeriodicOperator, "single",
                        lambda self, p: calls.append(1) or single(self, p))
    state = bem.solve(flat_surface, force=3e-3, length=1.0, e_star=E_STAR, periodic=True,
                          windowed=False)
    assert calls, "no single-precision convolution"
    monkeypatch.setattr(solver, "_SINGLE_ERROR", 0.0)
    double = bem.solve(flat_surface, force=3e-3, length=1.0, e_star=E_STAR, periodic=True,
                           windowed=False)
    assert state.gap_error <= state.tol
    assert state.depth == pytest.approx(double.depth, rel=1e-7)
    assert np.array_equal(state.contact, double.contact)


def test_working_set_out_of_iterations_is_not_converged(flat_surface, monkeypatch):
    """A working-set solve stopped by maxiter reports converged=False, never a solution
    checked only on the working set or only at the loose tolerance."""
    lower = bem.solve(flat_surface, force=0.8 * FORCES[-1], length=1.0, e_star=E_STAR,
                          periodic=True)
    monkeypatch.setattr(active_sets, "solve_candidates", lambda *args: None)
    results = _record_working_sets(monkeypatch)
    for maxiter in (1, 5, 12):
        state = bem.solve(flat_surface, force=FORCES[-1], length=1.0, e_star=E_STAR,
                              periodic=True, initial=lower.pressure, maxiter=maxiter)
        assert not state.converged, f"converged in {maxiter} iterations"
    assert any(r is not None for r in results), "no working-set solve"
