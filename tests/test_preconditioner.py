"""The preconditioned constrained CG (:mod:`roughcontact.bem.preconditioner`, :func:`roughcontact.bem.solver.polonsky_keer`).

* the preconditioner is the exact inverse of the periodic operator on zero-mean fields of the whole grid
  (closed form ``E*|q|/2 · 2/(E*|q|) = 1``), and symmetric positive definite on the zero-mean vectors of a set of cells;
* it cuts the iterations of a rough-sphere load (an iteration count, not a time);
* on three presets' load paths (the default sphere, a flat periodic path, a hardness path) force, depth and
  stiffness equal those of the unpreconditioned solver before it (``REFERENCE``, 257², tol 1e-8).

Tolerances of the comparison with ``REFERENCE``, derived from the solver tolerance ``tol``: two states that both
meet the stopping test ``max_c |g − d| ≤ tol·d`` on the same contact set have depths within ``2 tol`` relative
(each depth is the mean gap over the set within ``tol·d`` of the exact one); the contact sets must be equal, and
then the punch stiffness, solved to ``‖K_cc p − 1‖ ≤ tol ‖1‖`` from either state, agrees to ``10 tol`` relative
(the conditioning of ``K_cc`` on a few thousand cells times ``tol``; 2e-9 measured). Forces are matched to
round-off by both.
"""

import functools

import numpy as np
import pytest

from roughcontact import bem, surfaces
from roughcontact.bem import operators, preconditioner, solver

TOL = 1e-8

#: The unpreconditioned solver of commit 4a52b85 (roughcontact 0.1, before issue 41) on the paths of
#: :func:`_paths`: depth (L), stiffness (E* L) and contact cells per load.
REFERENCE = {
    'sphere': dict(
        depth=[
            0.000176247109304795, 0.00029718829393185, 0.000488460715193617, 0.000757139188081568,
            0.000990345976407007, 0.00130237990787519, 0.00168743934526793, 0.00218227383987247,
            0.0028709901610587, 0.00389854122126233, 0.00533038414187706, 0.00723505599187539,
            0.00993015624841799, 0.0138947351419078, 0.0196570097257855, 0.0277656092448082, 0.0397575816387157,
            0.0574508613293013, 0.0822922336421687],
        stiffness=[
            0.00606566634431434, 0.00606566634431434, 0.00758759013543379, 0.0121151692509182, 0.0190982940276475,
            0.0250209336818801, 0.031541912227877, 0.0475219418218514, 0.0522464979198814, 0.0659868845090013,
            0.0792552861685337, 0.106143365233967, 0.124790260555939, 0.148847308702305, 0.179395704448046,
            0.218493605619358, 0.251171238437168, 0.303079220609667, 0.376945631594767],
        cells=[
            2, 2, 3, 6, 10, 13, 22, 45, 63, 100, 158, 265, 416, 653, 1019, 1663, 2530, 3810, 6069],
    ),
    'flat': dict(
        depth=[
            0.00148862873379467, 0.00200323018162433, 0.00265677651927809, 0.00353290208683181,
            0.00443486832878361, 0.00531931347757562, 0.00633372868894022, 0.00755498203680774,
            0.00905176386619133, 0.0111157207133664],
        stiffness=[
            0.0120328323208835, 0.0207025877157379, 0.0235819178693295, 0.0354555516273792, 0.0662959336682034,
            0.119679766917179, 0.181782478993522, 0.265801185457281, 0.379836902527399, 0.482574883877329],
        cells=[
            6, 15, 22, 35, 59, 122, 211, 372, 671, 1135],
    ),
    'hardness': dict(
        depth=[
            0.00135997159265871, 0.00167059339583052, 0.00197778582978422, 0.00258135031678598,
            0.0033277036732742, 0.00421781824659615, 0.00555736920583165, 0.00731864189250945,
            0.00996374193650977, 0.0142512029077751, 0.0200910950912117, 0.0316140916476913],
        stiffness=[
            0.0330638069948448, 0.0416596571049472, 0.0504029135030023, 0.0587143638857524, 0.0707569902181117,
            0.0826650552310062, 0.106083709738641, 0.126419162646876, 0.14997070702039, 0.184419939796763,
            0.228232958762419, 0.28681686107084],
        cells=[
            26, 42, 61, 102, 164, 251, 404, 643, 1015, 1624, 2615, 4193],
    ),
}


def _paths():
    sphere = surfaces.rough_sphere(257, radius=0.5, hurst=0.7, h_rms=9e-3, length=1.0, seed=0)
    flat = surfaces.self_affine(257, hurst=0.7, h_rms=9e-3, length=1.0, seed=0)
    return {"sphere": (sphere, np.geomspace(1e-6, 2e-2, 19), {}),                     # config.yaml's sphere path
            "flat": (flat, np.geomspace(1e-5, 2e-3, 10), {"periodic": True}),         # its flat path
            "hardness": (sphere, np.geomspace(1e-5, 1.9e-3, 12), {"hardness": 0.03})}  # presets/plastic.yaml


@pytest.fixture(scope="module")
def solved():
    return {name: bem.load_path(z, forces, length=1.0, e_star=1.0, tol=TOL, **kw)
            for name, (z, forces, kw) in _paths().items()}


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_load_paths_equal_the_unpreconditioned_solver(solved, name):
    states, reference = solved[name], REFERENCE[name]
    _, forces, _ = _paths()[name]
    assert all(state.converged for state in states)
    np.testing.assert_allclose([s.force for s in states], forces, rtol=1e-12)
    assert [int(s.contact.sum()) for s in states] == reference["cells"], "contact sets differ"
    np.testing.assert_allclose([s.depth for s in states], reference["depth"], rtol=2 * TOL, atol=0)
    np.testing.assert_allclose([bem.stiffness(s) for s in states], reference["stiffness"], rtol=10 * TOL, atol=0)


def test_inverse_of_the_periodic_operator():
    """On the whole periodic grid ``M K p = p − mean p`` (single precision: 1e-5 of max |p|)."""
    n = 64
    operator = operators.PeriodicOperator(n, 2.0, 3.0)
    pressure = np.random.default_rng(1).random((n, n))
    inverse = preconditioner.fourier_inverse(operator)
    cells = np.arange(n * n)
    result = inverse((n, n), cells, operator(pressure).reshape(-1))
    np.testing.assert_allclose(result, (pressure - pressure.mean()).reshape(-1), atol=1e-5 * pressure.max())


@pytest.mark.parametrize("periodic", [False, True])
def test_preconditioner_is_symmetric_positive_on_zero_mean_vectors(periodic):
    """``xᵀ M y = yᵀ M x`` and ``xᵀ M x > 0`` for zero-mean ``x, y`` on a random set of cells of a window."""
    n, shape = 128, (40, 56)
    operator = operators.operator_for(n, 1.0, 1.0, periodic)
    inverse = preconditioner.fourier_inverse(operator)
    rng = np.random.default_rng(2)
    cells = np.sort(rng.choice(shape[0] * shape[1], 300, replace=False))
    x, y = rng.standard_normal((2, cells.size))
    x -= x.mean()
    y -= y.mean()
    mx, my = inverse(shape, cells, x), inverse(shape, cells, y)
    assert abs(mx.sum()) < 1e-9 * np.abs(mx).sum()
    assert x @ my == pytest.approx(y @ mx, rel=1e-5)
    assert x @ mx > 0


def test_preconditioning_cuts_the_iterations(monkeypatch):
    """The largest load of the 257² default sphere path from the one before it: the preconditioned CG needs at
    most 0.6× the iterations of the same CG with ``M = I`` (0.4× measured), to the same depth within 2 tol."""
    z, forces, _ = _paths()["sphere"]
    previous = bem.solve(z, force=forces[-2], length=1.0, e_star=1.0, tol=TOL)
    preconditioned = bem.solve(z, force=forces[-1], length=1.0, e_star=1.0, tol=TOL, initial=previous.pressure)
    monkeypatch.setattr(solver, "fourier_inverse", lambda operator: None)
    plain = bem.solve(z, force=forces[-1], length=1.0, e_star=1.0, tol=TOL, initial=previous.pressure)
    assert preconditioned.converged and plain.converged
    assert preconditioned.depth == pytest.approx(plain.depth, rel=2 * TOL)
    assert preconditioned.iterations <= 0.6 * plain.iterations, (preconditioned.iterations, plain.iterations)


@pytest.mark.parametrize("terms", [0, 1, 3])
def test_boundary_terms_keep_the_preconditioner_symmetric_positive(terms):
    """The Schur-complement correction (``boundary_terms``) is a symmetric positive operator on the zero-mean
    vectors of a set of cells (single precision: symmetric to 1e-5)."""
    n, shape = 128, (40, 56)
    inverse = preconditioner.fourier_inverse(operators.operator_for(n, 1.0, 1.0, False))
    rng = np.random.default_rng(3)
    cells = np.sort(rng.choice(shape[0] * shape[1], 600, replace=False))
    x, y = rng.standard_normal((2, cells.size))
    x -= x.mean()
    y -= y.mean()
    mx, my = (inverse(shape, cells, v, boundary_terms=terms) for v in (x, y))
    assert x @ my == pytest.approx(y @ mx, rel=1e-5)
    assert x @ mx > 0


def test_boundary_terms_tend_to_the_inverse_of_the_restricted_operator():
    """Many Neumann terms: the corrected preconditioner inverts the window's ``E*|q|/2`` inverse restricted to the
    cells, ``(M⁻¹)_CC``, on zero-mean vectors (the exact Schur complement ``M_CC − M_CF M_FF⁻¹ M_FC``), to 1e-5
    (single precision; 60 terms: 30 reach 8e-7 of max |x| on this 24² window, no correction leaves 0.6)."""
    n, shape = 64, (24, 24)
    inverse = preconditioner.fourier_inverse(operators.operator_for(n, 1.0, 1.0, False))
    rng = np.random.default_rng(4)
    cells = np.sort(rng.choice(shape[0] * shape[1], 200, replace=False))
    x = rng.standard_normal(cells.size)
    x -= x.mean()
    symbol = inverse.symbol(shape).astype(float)
    pseudo = np.where(symbol > 0, 1.0 / np.where(symbol > 0, symbol, 1.0), 0.0)
    field = np.zeros(shape)
    field.reshape(-1)[cells] = x
    restricted = np.fft.irfft2(np.fft.rfft2(field) * pseudo, s=shape).reshape(-1)[cells]  # (M⁻¹)_CC x
    result = inverse(shape, cells, restricted, boundary_terms=60)
    np.testing.assert_allclose(result, x, atol=1e-5 * np.abs(x).max())


@pytest.mark.parametrize("terms", [-1, 1.5, True])
def test_bad_boundary_terms_are_refused_in_one_line(terms):
    lift = np.zeros((8, 8))
    operator = operators.operator_for(8, 1.0, 1.0, False)
    with pytest.raises(ValueError, match="boundary_terms must be None or an integer >= 0"):
        solver.polonsky_keer(lift, operator, 1.0, np.ones((8, 8)), TOL, 10, boundary_terms=terms)


@pytest.fixture
def corrected(monkeypatch):
    """Every elastic solve with one Neumann term of the boundary correction (``boundary_terms=1``)."""
    from roughcontact.bem import contact
    monkeypatch.setattr(contact, "polonsky_keer", functools.partial(solver.polonsky_keer, boundary_terms=1))


@pytest.mark.parametrize("name", ["sphere", "hardness"])
def test_boundary_terms_leave_the_load_paths_unchanged(corrected, name):
    """The corrected preconditioner reaches the same states within the solver tolerance (see the module's
    tolerances): same contact sets, depths within 2 tol, stiffnesses within 10 tol of ``REFERENCE``."""
    z, forces, kw = _paths()[name]
    states = bem.load_path(z, forces, length=1.0, e_star=1.0, tol=TOL, **kw)
    reference = REFERENCE[name]
    assert all(state.converged for state in states)
    assert [int(s.contact.sum()) for s in states] == reference["cells"], "contact sets differ"
    np.testing.assert_allclose([s.depth for s in states], reference["depth"], rtol=2 * TOL, atol=0)
    np.testing.assert_allclose([bem.stiffness(s) for s in states], reference["stiffness"], rtol=10 * TOL, atol=0)


def test_boundary_terms_cut_the_iterations(solved, corrected):
    """Over the 257² default sphere path, one Neumann term of the boundary correction needs at most 0.85× the
    iterations of today's preconditioner (232 → 180 measured: 0.78)."""
    z, forces, kw = _paths()["sphere"]
    states = bem.load_path(z, forces, length=1.0, e_star=1.0, tol=TOL, **kw)
    plain, fewer = (sum(s.iterations for s in path) for path in (solved["sphere"], states))
    assert fewer <= 0.85 * plain, (fewer, plain)
