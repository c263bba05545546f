"""The Cerruti kernel of :mod:`roughcontact.bem.cerruti` against quadrature and against the normal
kernel it must equal at ν = 0."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import dblquad

from roughcontact.bem.cerruti import (FreeCerrutiPair, FreeTangentialOperator, PeriodicCerrutiPair,
                                      PeriodicTangentialOperator, cerruti_coefficients,
                                      cerruti_cross_coefficients, shear_modulus)
from roughcontact.bem.operators import FreeSpaceOperator, PeriodicOperator, love_coefficients


@pytest.mark.parametrize("offset", [(1, 0), (0, 1), (2, 3), (5, 1)])
def test_cell_integral_matches_quadrature(offset):
    """The closed-form cell integral of Cerruti's u_x (ν = 0.3) equals adaptive quadrature of
    (1 − ν)/ρ + ν x²/ρ³ over the cell, scaled by 1/(1 − ν): quadrature to 1e-11 absolute, so
    1e-9 relative holds (the integrand is smooth off the loaded cell)."""
    nu, (i, j) = 0.3, offset
    exact, _ = dblquad(lambda y, x: 1 / np.hypot(x, y) + nu / (1 - nu) * x * x / np.hypot(x, y) ** 3,
                       i - 0.5, i + 0.5, j - 0.5, j + 0.5, epsabs=1e-12, epsrel=1e-12)
    assert cerruti_coefficients(8, nu)[i, j] == pytest.approx(exact, rel=1e-9)


def test_self_coefficient():
    """On its own cell ∫∫x²/ρ³ = ½∫∫1/ρ (x² + y² = ρ², symmetric square), so
    c[0, 0] = 4 ln(1 + √2)(1 + ν/(2(1 − ν))); rounding only."""
    nu = 0.4
    expected = 4 * np.log1p(np.sqrt(2)) * (1 + nu / (2 * (1 - nu)))
    assert cerruti_coefficients(1, nu)[0, 0] == pytest.approx(expected, rel=1e-14)


def test_kernel_is_not_symmetric_in_x_and_y():
    """u_x is larger along x than across it (ν x²/ρ³): offset (3, 0) beats (0, 3)."""
    c = cerruti_coefficients(4, 0.3)
    assert c[3, 0] > c[0, 3]


@pytest.mark.parametrize("n", [31, 32])
@pytest.mark.parametrize("tangential_operator, normal_operator, seed", [
    (FreeTangentialOperator, FreeSpaceOperator, 0), (PeriodicTangentialOperator, PeriodicOperator, 1)],
    ids=["free", "periodic"])
def test_zero_poisson_equals_normal(n, tangential_operator, normal_operator, seed):
    """At ν = 0 Cerruti's u_x is Boussinesq's u_z with E* = 2G: the free operators agree to rounding,
    and the periodic spectrum 2(1 − ν q_x²/q²)/(E*(1 − ν)q) is the normal 2/(E* q)."""
    rng = np.random.default_rng(seed)
    traction = rng.random((n, n))
    tangential = tangential_operator(n, 2.0, 3.0, 0.0)(traction)
    normal = normal_operator(n, 2.0, 3.0)(traction)
    assert np.max(np.abs(tangential - normal)) <= 1e-12 * np.max(np.abs(normal))


def test_free_scale():
    """One loaded cell: u_x = c Δ q/(π E*) with the coefficient table, for non-unit L and E*."""
    n, length, e_star, nu = 16, 3.0, 7.5, 0.25
    traction = np.zeros((n, n))
    traction[5, 7] = 2.0
    u = FreeTangentialOperator(n, length, e_star, nu)(traction)
    c = cerruti_coefficients(n, nu)
    expected = 2.0 * c[abs(9 - 5), abs(7 - 7)] * (length / n) / (np.pi * e_star)
    assert u[9, 7] == pytest.approx(expected, rel=1e-12)


def test_periodic_matches_free_far_from_images():
    """A patch of traction small against the period: the periodic u_x, less its value at the
    patch's far side, matches the free one less its value there to 1% of the peak (the images'
    field is smooth over the patch: its variation is O((patch/L)²) of the peak)."""
    n, nu = 256, 0.4
    traction = np.zeros((n, n))
    traction[124:132, 124:132] = 1.0
    free = FreeTangentialOperator(n, 1.0, 1.0, nu)(traction)
    periodic = PeriodicTangentialOperator(n, 1.0, 1.0, nu)(traction)
    window = (slice(112, 144), slice(112, 144))
    a = free[window] - free[112, 128]
    b = periodic[window] - periodic[112, 128]
    assert np.max(np.abs(a - b)) <= 0.01 * free.max()


def test_shear_modulus():
    """G = E/(2(1 + ν)) with E = E*(1 − ν²): G = E*(1 − ν)/2."""
    e_star, nu = 5.0, 0.3
    young = e_star * (1 - nu**2)
    assert shear_modulus(e_star, nu) == pytest.approx(young / (2 * (1 + nu)), rel=1e-15)


def test_love_is_the_zero_poisson_table():
    """cerruti_coefficients(n, 0) is love_coefficients(n)."""
    assert np.array_equal(cerruti_coefficients(6, 0.0), love_coefficients(6))


@pytest.mark.parametrize("offset", [(1, 1), (2, 3), (5, 1), (1, 0), (0, 4)])
def test_cross_integral_matches_quadrature(offset):
    """The closed-form cell integral of Cerruti's u_y under q_x, ν/(1 − ν) · xy/ρ³ (antiderivative
    −ρ), equals adaptive quadrature over the cell (ν = 0.3): 1e-9 relative; 0 on the axes (odd)."""
    nu, (i, j) = 0.3, offset
    exact, _ = dblquad(lambda y, x: nu / (1 - nu) * x * y / np.hypot(x, y) ** 3,
                       i - 0.5, i + 0.5, j - 0.5, j + 0.5, epsabs=1e-13, epsrel=1e-12)
    assert cerruti_cross_coefficients(8, nu)[i, j] == pytest.approx(exact, rel=1e-9, abs=1e-15)


@pytest.mark.parametrize("n", [31, 32])
@pytest.mark.parametrize("pair, single", [(FreeCerrutiPair, FreeTangentialOperator),
                                          (PeriodicCerrutiPair, PeriodicTangentialOperator)],
                         ids=["free", "periodic"])
def test_pair_blocks(n, pair, single):
    """The two-component operator: its u_x under q_x is the one-component operator's, its u_y under
    q_y that operator on the transposed grid (x ↔ y), its dense matrix is symmetric (reciprocity)
    and gives its FFT products; all to rounding (1e-12 of the peak)."""
    rng = np.random.default_rng(2)
    qx, qy = rng.random((2, n, n))
    operator, one = pair(n, 2.0, 3.0, 0.3), single(n, 2.0, 3.0, 0.3)
    ux, uy = operator(qx, qy)
    zero = np.zeros((n, n))
    assert np.max(np.abs(operator(qx, zero)[0] - one(qx))) <= 1e-12 * np.abs(ux).max()
    assert np.max(np.abs(operator(zero, qy)[1] - one(qy.T).T)) <= 1e-12 * np.abs(uy).max()
    rows, cols = np.nonzero(np.ones((n, n), dtype=bool))
    matrix = operator.influence_matrix(rows, cols)
    assert np.max(np.abs(matrix - matrix.T)) <= 1e-14 * np.abs(matrix).max()
    product = matrix @ np.concatenate([qx.ravel(), qy.ravel()])
    assert np.max(np.abs(product - np.concatenate([ux.ravel(), uy.ravel()]))) <= 1e-12 * np.abs(ux).max()


@pytest.mark.parametrize("pair", [FreeCerrutiPair, PeriodicCerrutiPair], ids=["free", "periodic"])
def test_pair_decouples_at_zero_poisson(pair):
    """ν = 0: u_y under q_x is exactly 0 (the cross kernel carries the factor ν)."""
    qx = np.random.default_rng(3).random((16, 16))
    assert not np.any(pair(16, 1.0, 1.0, 0.0)(qx, np.zeros((16, 16)))[1])


def test_periodic_pair_matches_free():
    """A smooth traction patch q_x = (1 − r²/a²)^(1/2), a = 16 cells on 256² (ν = 0.3): the periodic
    u_x (less its mean on the patch) and u_y match the free ones on the patch, measured 2026-11-27
    to 5.6e-4 and 4.0e-3 of their peaks (8.9e-3 for u_y at a = 8 on 128²: the periodic kernel is
    the continuum spectrum sampled on the grid, as tamaas' and the normal periodic operator's, whose
    near field differs from the cell integral, most for the odd cross kernel); bounds 0.2 % and 1 %."""
    n, a = 256, 16
    x = (np.arange(n) - n // 2)[:, None]
    y = (np.arange(n) - n // 2)[None, :]
    inside = (x**2 + y**2) <= a**2
    traction = np.sqrt(np.clip(1 - (x**2 + y**2) / a**2, 0, None))
    zero = np.zeros((n, n))
    free = FreeCerrutiPair(n, 1.0, 1.0, 0.3)(traction, zero)
    periodic = PeriodicCerrutiPair(n, 1.0, 1.0, 0.3)(traction, zero)
    dx = (free[0] - free[0][inside].mean()) - (periodic[0] - periodic[0][inside].mean())
    assert np.abs(dx[inside]).max() <= 2e-3 * np.abs(free[0]).max()
    assert np.abs(free[1] - periodic[1])[inside].max() <= 1e-2 * np.abs(free[1]).max()
