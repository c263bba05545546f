"""FFT-based approximate inverse of the normal half-space operator: the preconditioner of
:func:`roughcontact.bem.solver.polonsky_keer`.

The elastic half-space maps a pressure of wavevector ``q`` to the displacement
``ũ = 2 p̃/(E* |q|)``, so its inverse multiplies by ``E* |q|/2``. On the cells ``W`` of a
constrained solve (the contact set and the cells entering it) the preconditioned residual is

    ``z = P_W R_W F⁻¹ [E* |q|/2 · F (R_Wᵀ r)]``,

``R_Wᵀ`` the zero extension of ``r`` from ``W`` to the window, ``F`` the real FFT on the
window (periodic over the window's side), ``R_W`` the restriction back to ``W`` and ``P_W`` the
removal of the mean on ``W`` (the force constraint ``Σ p = F/Δ²``: the direction keeps the total;
the deflation of the constant, on which the inverse vanishes). This is the FFT-based approximate
inverse of Vollebregt's BCCG-FD (J. Comput. Phys. 257, 333 (2014), doi:10.1016/j.jcp.2013.10.042)
with the mean as the deflated space. The operator is symmetric positive definite on the
zero-mean vectors of ``W``, so conjugate gradients stay conjugate gradients, and the condition
number of ``P_W M K`` stays bounded as the grid is refined: the iterations per load do not grow
like ``n^(1/2)`` as those of unpreconditioned CG (the condition number of ``K`` on ``m`` cells
grows like ``m^(1/2)``).

Optional (``boundary_terms``, off by default): the correction of ``M`` at the set's edge by the Schur
complement of the window's operator (:meth:`FourierInverse._schur`); measured in ``benchmarks/fixed_set.py``.

The transform runs in single precision on the window itself (not on the zero-padded size of the
convolution), a quarter of the convolution's cost: the preconditioner need only be a fixed,
symmetric, positive operator, not an exact inverse (the stopping test is on the gap).
"""

from __future__ import annotations

import numpy as np
import scipy.fft

__all__ = ["FourierInverse", "fourier_inverse"]


class FourierInverse:
    """``E* |q|/2`` on a periodic grid of cell size ``spacing``: the approximate inverse of the
    normal half-space operator on windows of any shape.

    Parameters
    ----------
    spacing : float
        Cell side ``Δ`` (length unit).
    e_star : float
        Effective modulus ``E*`` (pressure unit).

    Notes
    -----
    The symbol of the last window shape is kept (``m₁ × (m₂/2 + 1)`` single-precision values).
    """

    def __init__(self, spacing: float, e_star: float):
        self.spacing = spacing
        self.e_star = e_star
        self._shape: tuple[int, int] | None = None
        self._symbol = np.empty((0, 0), dtype=np.float32)

    def symbol(self, shape: tuple[int, int]) -> np.ndarray:
        """``E* |q|/2`` on the real-FFT half spectrum of a window of ``shape`` (single precision,
        pressure/length unit); 0 at ``q = 0``."""
        if self._shape != tuple(shape):
            qx = 2.0 * np.pi * scipy.fft.fftfreq(shape[0], d=self.spacing)
            qy = 2.0 * np.pi * scipy.fft.rfftfreq(shape[1], d=self.spacing)
            self._symbol = (0.5 * self.e_star * np.hypot(qx[:, None], qy[None, :])).astype(np.float32)
            self._shape = tuple(shape)
        return self._symbol

    def diagonal(self, shape: tuple[int, int]) -> float:
        """The diagonal ``m₀`` of ``F⁻¹ E*|q|/2 F`` on a window of ``shape``: the symbol's mean over
        the full spectrum (pressure/length unit)."""
        symbol = self.symbol(shape)
        weights = np.full(symbol.shape[1], 2.0)
        weights[0] = 1.0
        if shape[1] % 2 == 0:
            weights[-1] = 1.0
        return float((symbol.astype(float) * weights).sum() / (shape[0] * shape[1]))

    def __call__(self, shape: tuple[int, int], cells: np.ndarray, values: np.ndarray, *,
                 deflate: bool = True, boundary_terms: int | None = None) -> np.ndarray:
        """``P_W R_W F⁻¹ E*|q|/2 F R_Wᵀ values``: the preconditioned ``values`` given on the flat
        ``cells`` ``W`` of a window of ``shape`` (length unit in, pressure unit out), zero mean on ``W``.

        ``boundary_terms=k`` subtracts the Schur-complement correction of the boundary (:meth:`_schur`):
        ``M_WW`` alone exceeds the inverse ``((M⁻¹)_WW)⁻¹`` of the operator restricted to ``W`` by
        ``M_WF M_FF⁻¹ M_FW`` (``F`` the window's cells outside ``W``), a positive term that sits on the
        cells at the set's edge; ``k + 1`` more transforms. ``None``: no correction.

        ``deflate=False`` (systems without the force constraint, such as the flat punch
        ``K_cc p = 1``): no projection, and the mean ``q = 0`` is multiplied by the symbol's smallest
        nonzero value ``E* π/(m Δ)`` (``m`` the longer side) instead of 0, so that the preconditioner
        is symmetric positive definite on all vectors of ``W``.
        """
        field = np.zeros(shape, dtype=np.float32)
        field.reshape(-1)[cells] = values
        transform = scipy.fft.rfft2(field, overwrite_x=True)
        mean = transform[0, 0]
        transform *= self.symbol(shape)
        if not deflate:
            transform[0, 0] = mean * (np.pi * self.e_star / (max(shape) * self.spacing))
        if boundary_terms is None:
            result = scipy.fft.irfft2(transform, s=shape, overwrite_x=True).reshape(-1)[cells].astype(float)
        else:
            result = self._schur(shape, cells, scipy.fft.irfft2(transform, s=shape, overwrite_x=True),
                                 boundary_terms)
        if deflate:
            result -= result.mean()
        return result

    def _schur(self, shape, cells, response, terms):
        """``R_W [y − M R_Fᵀ (Σ_{k≤terms} N^k) R_F y / m₀]``, ``y = M R_Wᵀ r`` the window's response,
        ``F`` the window's cells outside ``W``, ``M_FF = m₀ (I − N)``: the Schur complement
        ``M_WW − M_WF M_FF⁻¹ M_FW`` (the inverse of ``(M⁻¹)_WW``) with ``M_FF⁻¹`` by a truncated
        Neumann series (an even number of terms, ``terms`` odd, keeps it ≥ the exact complement)."""
        scaled = self.symbol(shape) / np.float32(self.diagonal(shape))
        term = response.copy()
        term.reshape(-1)[cells] = 0.0
        total = term.copy()
        for _ in range(terms):
            step = scipy.fft.irfft2(scipy.fft.rfft2(term) * scaled, s=shape, overwrite_x=True)
            step.reshape(-1)[cells] = 0.0
            term -= step
            total += term
        correction = scipy.fft.irfft2(scipy.fft.rfft2(total, overwrite_x=True) * scaled, s=shape,
                                      overwrite_x=True).reshape(-1)[cells]
        return (response.reshape(-1)[cells] - correction).astype(float)


def fourier_inverse(operator) -> FourierInverse | None:
    """The :class:`FourierInverse` of a grid operator (its cell size and modulus), cached on it;
    ``None`` for operators on scattered cells (dense matrices), which keep unpreconditioned CG."""
    spacing = getattr(operator, "spacing", None)
    if spacing is None:
        return None
    inverse = getattr(operator, "_fourier_inverse", None)
    if inverse is None:
        inverse = operator._fourier_inverse = FourierInverse(spacing, operator.e_star)
    return inverse
