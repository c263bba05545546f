"""Tangential influence operators: surface displacement ``u_x`` from a tangential traction ``q_x``.

Cerruti's solution (Johnson 1985, eq. 2.19; §3.8 for distributed tractions): a tangential point
force ``Q`` in ``x`` on the surface of a half-space of shear modulus ``G`` and Poisson ratio ``ν``
displaces the surface by

    u_x = Q/(2πG) · [(1 − ν)/ρ + ν x²/ρ³],
    u_y = Q/(2πG) · ν x y/ρ³,
    u_z = −Q(1 − 2ν)/(4πG) · x/ρ².

Simplifications, stated: the traction has one component, ``q_x`` in the loading direction
(``q_y = 0``; the standard simplification of Cattaneo–Mindlin and of the rough-surface BEM of
Grzemba et al. 2014), and only ``u_x`` enters the contact conditions (``u_y``, which ``q_x``
produces only through ``ν x y/ρ³``, is left free). The normal–tangential coupling ``u_z(q_x)``
(and ``u_x(p)``) is neglected: exact for elastically similar bodies and for ``ν = 1/2``, the
assumption of Mindlin, Cattaneo, Ciavarella–Jäger and the MDR.

Moduli: the package works in ``E*``. For a rigid indenter on an elastic half-space
``E* = E/(1 − ν²)`` and ``G = E/(2(1 + ν))``, so ``G = E*(1 − ν)/2`` and
``1/(2πG) = 1/(π E* (1 − ν))``.

``x`` is the grid's first axis (``heights[i, j]``: ``i`` along ``x``). Traction is piecewise
constant on the square cells (side ``Δ``), displacements are taken at the cell centres, as for
the normal operators of :mod:`roughcontact.bem.operators`:

* :class:`FreeTangentialOperator` — non-periodic half-space: the cell integral of Cerruti's
  ``u_x`` in closed form (:func:`cerruti_coefficients`), convolved by zero-padded FFT;
* :class:`PeriodicTangentialOperator` — periodic over ``length``:
  ``ũ_x(q) = 2 (1 − ν q_x²/|q|²) q̃_x(q) / (E* (1 − ν) |q|)``, ``ũ_x(0) = 0`` (the Fourier
  transform of Cerruti's ``u_x``; Johnson 1985, §2.2; e.g. Campañá, Persson & Müser,
  J. Phys.: Condens. Matter 23, 085001 (2011), doi:10.1088/0953-8984/23/8/085001).

At ``ν = 0`` both equal the normal operators of the same ``E*``.
"""

from __future__ import annotations

import functools

import numpy as np
import scipy.fft

from .operators import FreeSpaceOperator, PeriodicOperator, love_coefficients

__all__ = ["shear_modulus", "cerruti_coefficients", "FreeTangentialOperator",
           "PeriodicTangentialOperator", "tangential_operator_for"]


def shear_modulus(e_star: float, poisson: float) -> float:
    """``G = E*(1 − ν)/2`` of an elastic half-space under a rigid indenter (force/length²).

    From ``E* = E/(1 − ν²)`` and ``G = E/(2(1 + ν))`` (Johnson 1985, §3.8 and eq. 4.22).
    """
    return 0.5 * e_star * (1.0 - poisson)


def cerruti_coefficients(n: int, poisson: float) -> np.ndarray:
    """Dimensionless ``u_x`` at offset ``(i, j)`` cells (``i`` along ``x``) from a cell under ``q_x``.

    ``u_x = c[|i|, |j|] · q Δ/(π E*)`` for a uniform tangential traction ``q`` on one square cell
    of side ``Δ``: the cell integral of Cerruti's ``u_x`` (module docstring),

    ``c = c_Love + ν/(1 − ν) · Σ_corners ± Y asinh(X/|Y|)``,

    ``X = i ± 1/2`` (along ``x``), ``Y = j ± 1/2``, corners signed as in
    :func:`~roughcontact.bem.operators.love_coefficients` (whose ``c_Love`` integrates ``1/ρ``);
    ``Y asinh(X/|Y|)`` integrates ``x²/ρ³`` (``∂²/∂x∂y [y ln(x + ρ)] = x²/ρ³``, the ``y ln|y|``
    terms cancel between corners). Self-coefficient ``c[0, 0] = 4 ln(1 + √2) (1 + ν/(2(1 − ν)))``.
    """
    offset = np.arange(n, dtype=float)
    x = offset[:, None]
    y = offset[None, :]

    def corner(cx, cy):
        return cy * np.arcsinh(cx / np.abs(cy))

    along = (corner(x + 0.5, y + 0.5) - corner(x + 0.5, y - 0.5)
             - corner(x - 0.5, y + 0.5) + corner(x - 0.5, y - 0.5))
    return love_coefficients(n) + (poisson / (1.0 - poisson)) * along


class FreeTangentialOperator(FreeSpaceOperator):
    """Non-periodic half-space, ``u_x`` from ``q_x`` on an ``n × n`` grid (DC-FFT).

    Parameters
    ----------
    n : int
        Cells per side.
    length : float
        Side length of the grid (length unit).
    e_star : float
        Effective modulus ``E*`` (pressure unit).
    poisson : float
        Poisson ratio ``ν`` of the half-space, ``−1 < ν ≤ 1/2``.

    Notes
    -----
    The kernel is even in ``x`` and in ``y`` separately, so the tables, windows and cached
    spectra of :class:`~roughcontact.bem.operators.FreeSpaceOperator` serve it unchanged.
    """

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.poisson = float(poisson)
        super().__init__(n, length, e_star)

    def _unit_table(self, side: int) -> np.ndarray:
        return cerruti_coefficients(side, self.poisson) * (self.spacing / (np.pi * self.e_star))


class PeriodicTangentialOperator(PeriodicOperator):
    """Half-space periodic over ``length``, ``u_x`` from ``q_x`` on an ``n × n`` grid.

    ``ũ_x(q) = 2 (1 − ν q_x²/|q|²) q̃_x / (E* (1 − ν) |q|)`` for ``q ≠ 0``; ``ũ_x(0) = 0``
    (zero-mean displacement). Parameters as :class:`FreeTangentialOperator`.
    """

    def __init__(self, n: int, length: float, e_star: float, poisson: float):
        self.n = n
        self.spacing = length / n
        self.e_star = e_star
        self.poisson = float(poisson)
        qx = 2.0 * np.pi * scipy.fft.fftfreq(n, d=self.spacing)
        qy = 2.0 * np.pi * scipy.fft.rfftfreq(n, d=self.spacing)
        q2 = qx[:, None] ** 2 + qy[None, :] ** 2
        q2[0, 0] = 1.0
        shape = 1.0 - self.poisson * qx[:, None] ** 2 / q2
        q = np.sqrt(q2)
        q[0, 0] = np.inf
        self.spectrum = 2.0 * shape / (e_star * (1.0 - self.poisson) * q)
        self.self_coefficient = float(self._kernel[0, 0])


@functools.lru_cache(maxsize=8)
def tangential_operator_for(n: int, length: float, e_star: float, poisson: float, periodic: bool):
    """Shared, cached tangential operator for a grid (kernel spectra are reused across solves)."""
    cls = PeriodicTangentialOperator if periodic else FreeTangentialOperator
    return cls(n, length, e_star, poisson)
