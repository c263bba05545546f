"""Eq. 16 of Pohrt & Popov (2013) with free prefactors, fitted to a stiffness-force curve:
``F = A k³ + B k^(H+1)`` (a body ``z ∝ r^m``: ``A k^(m+1)``), the crossover force of eq. 17 where the
two terms are equal. The slopes of its asymptotic windows are
:func:`roughcontact.study.analysis.statistics.log_log_slope` (``_slopes`` here, for the crossover table).

Forces are normalised, F/(E* L²), and stiffnesses k/(E* L).
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .statistics import log_log_slope

__all__ = ["Eq16Fit", "fit_eq16"]


@dataclasses.dataclass(frozen=True)
class Eq16Fit:
    """Least-squares fit of ``F = A k³ + B k^(H+1)`` (eq. 16 with free prefactors).

    Arrays of the leading shape of the fitted stiffnesses, in normalised units
    F/(E* L²) and k/(E* L).

    Attributes
    ----------
    hertz_coefficient : numpy.ndarray
        A; Hertz (eq. 10) gives ``A = L/(6R)``, i.e. ``1/(6 R E*²)`` in physical units
        (a body ``z ∝ r^m``: eq. 7 with H → m).
    rough_coefficient : numpy.ndarray
        B; eq. 12 gives ``B = (h/L) ζ^−(H+1)``.
    crossover_stiffness : numpy.ndarray
        ``k_tr = (B/A)^(1/(m−H))``, where the two terms are equal.
    crossover_force : numpy.ndarray
        ``F_tr = A k_tr^(m+1)``, the force where the asymptotes (eqs. 10 and 12)
        intersect: eq. 17's quantity. The fitted curve itself passes ``k_tr`` at ``2 F_tr``.
    """

    hertz_coefficient: np.ndarray
    rough_coefficient: np.ndarray
    crossover_stiffness: np.ndarray
    crossover_force: np.ndarray


def fit_eq16(force, stiffness, hurst: float, *, exponent: float = 2.0, iterations: int = 40) -> Eq16Fit:
    """Fit eq. 16 with both prefactors free in log space: minimise
    ``Σ_i [ln(A k_i^(m+1) + B k_i^(H+1)) − ln F_i]²`` over ``ln A`` and ``ln B``
    (m = 2, the paraboloid: ``A k³``; a body of revolution ``z ∝ r^m`` has
    ``F ∝ k^(m+1)``, eq. 7 with H → m).

    Parameters
    ----------
    force : array_like, shape (m,)
        Loads F/(E* L²).
    stiffness : array_like, shape (..., m)
        Stiffnesses k/(E* L) at those loads; leading dimensions (e.g. bootstrap
        replicates) are fitted independently, vectorised.
    hurst : float
        Hurst exponent H (the exponents m + 1 and H + 1 are fixed).
    exponent : float
        Exponent m of the body of revolution (keyword-only; 2: the paraboloid).
    iterations : int
        Damped Gauss–Newton steps (keyword-only); 40 reach round-off on
        every curve tried, from the start below.

    Notes
    -----
    Start: the linear least-squares fit of ``A k³/F + B k^(H+1)/F = 1``
    (relative residuals, the log-space objective to first order), with a
    non-positive coefficient replaced by 10⁻⁶ of its one-term fit. Then
    Gauss–Newton in ``(ln A, ln B)``: with ``w_i = A k_i³/(A k_i³ + B k_i^(H+1))``
    the Jacobian rows are ``(w_i, 1 − w_i)``; steps are damped by 10⁻⁹ of the
    normal matrix's trace and clipped to ±2 in each log-coefficient.
    """
    F = np.asarray(force, dtype=float)
    k = np.asarray(stiffness, dtype=float)
    log_f = np.log(F)
    u = (exponent + 1.0) * np.log(k)   # ln k^(m+1)
    v = (hurst + 1.0) * np.log(k)      # ln k^(H+1)
    x, y = np.exp(u - log_f), np.exp(v - log_f)
    sxx, syy, sxy = (x * x).sum(-1), (y * y).sum(-1), (x * y).sum(-1)
    sx, sy = x.sum(-1), y.sum(-1)
    det = sxx * syy - sxy**2
    with np.errstate(divide="ignore", invalid="ignore"):
        a_lin = (sx * syy - sy * sxy) / det
        b_lin = (sy * sxx - sx * sxy) / det
    a_one = np.exp((log_f - u).mean(-1))
    b_one = np.exp((log_f - v).mean(-1))
    ln_a = np.log(np.where(np.isfinite(a_lin) & (a_lin > 0), a_lin, 1e-6 * a_one))
    ln_b = np.log(np.where(np.isfinite(b_lin) & (b_lin > 0), b_lin, 1e-6 * b_one))
    for _ in range(iterations):
        t1 = ln_a[..., None] + u
        t2 = ln_b[..., None] + v
        model = np.logaddexp(t1, t2)
        r = model - log_f
        w = np.exp(t1 - model)
        j11, j22, j12 = (w * w).sum(-1), ((1 - w) ** 2).sum(-1), (w * (1 - w)).sum(-1)
        g1, g2 = (w * r).sum(-1), ((1 - w) * r).sum(-1)
        damp = 1e-9 * (j11 + j22)
        det = (j11 + damp) * (j22 + damp) - j12**2
        d1 = -((j22 + damp) * g1 - j12 * g2) / det
        d2 = -((j11 + damp) * g2 - j12 * g1) / det
        ln_a = ln_a + np.clip(d1, -2.0, 2.0)
        ln_b = ln_b + np.clip(d2, -2.0, 2.0)
    ln_k_tr = (ln_b - ln_a) / (exponent - hurst)
    return Eq16Fit(hertz_coefficient=np.exp(ln_a), rough_coefficient=np.exp(ln_b),
                   crossover_stiffness=np.exp(ln_k_tr), crossover_force=np.exp(ln_a + (exponent + 1.0) * ln_k_tr))


#: the least-squares slope of ``log_k`` (shape (..., m)) against ``log_f`` (shape (m,)): the study's one
#: log-log slope, :func:`roughcontact.study.analysis.statistics.log_log_slope`
_slopes = log_log_slope


