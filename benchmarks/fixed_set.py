"""The normal solver's preconditioners on a fixed contact set: how the CG iterations grow with the grid.

Issue 41: the constrained CG's iterations grow with n, and on a fixed contact set the error of today's
preconditioner falls less per iteration as the grid is refined. This benchmark isolates that phase: the
contact set ``C`` of the largest load (2·10⁻² E*L²) of the default sphere (R = 0.5 L, H = 0.7,
h_rms = 9·10⁻³ L, seed 0, non-periodic, solved by ``bem.solve`` to tol 10⁻⁸) is frozen and the linear
system of the force-controlled problem on it, ``P K_CC p = −P lift_C`` with ``Σ p`` fixed (``P`` removes
the mean on ``C``), is solved by preconditioned CG from the uniform pressure to ``‖r‖ ≤ 10⁻⁸ ‖r₀‖``.
Prints per n and preconditioner the iterations and the condition number of the preconditioned operator
estimated from CG's Lanczos coefficients.

Preconditioners (``M = E*|q|/2`` on the window of the solve, ``m₀`` its diagonal, ``F`` the window's cells
outside ``C``; all symmetric positive definite on zero-mean vectors of ``C``):

``none``
    ``P`` (Polonsky & Keer's unpreconditioned CG);
``fft``
    ``P M_CC P``: today's :mod:`roughcontact.bem.preconditioner` (Vollebregt's FFT inverse restricted to C);
``sqrt-d``, ``1/sqrt-d``
    ``P D M_CC D P`` with ``D = diag(w)``, ``w = (min(d, 2)/2)^(±1/2)``, ``d`` the distance of a cell to the
    set's edge in cells (``scipy.ndimage.distance_transform_edt``; 1 on the edge cells): the weights of
    Hiptmair, Jerez-Hanckes & Urzúa-Torres (SIAM J. Numer. Anal. 52, 2295 (2014)) for the edge singularity,
    cut at 2 cells (uncut or per island they are worse still);
``edge-diag``
    ``P (M_CC − diag s) P``, ``s_i = Σ_F M_if²/m₀``: a diagonal (Jacobi-like) correction of the edge cells;
``schur:k``
    ``P (M_CC − M_CF [m₀⁻¹ Σ_{j≤k} N^j] M_FC) P`` with ``M_FF = m₀ (I − N)``: the Schur complement whose
    exact form ``M_CC − M_CF M_FF⁻¹ M_FC = ((M⁻¹)_CC)⁻¹`` is the inverse of the window's operator restricted
    to C, with ``M_FF⁻¹`` by k + 1 terms of its Neumann series; ``k + 2`` FFT pairs on the window per
    application (``fft``: one). ``polonsky_keer(..., boundary_terms=k)``; ``schur:63`` is the exact
    complement to single precision, the floor of this family.

``two-grid`` (not in the default list: slow)
    the Schur complement with ``M_FF⁻¹`` by one symmetric two-grid cycle on ``F``: one Richardson step
    ``v ← v + (u − M_FF v/m₀)`` before and after a coarse correction on 2 × 2 blocks (piecewise-constant
    prolongation ``P`` onto ``F``, restriction ``Pᵀ``, Galerkin coarse operator ``Pᵀ M_FF P/m₀`` solved
    by CG to 10⁻¹⁰, each product through the fine window's transform): whether multigrid on the
    non-contact cells reaches the exact complement (it would, with a coarse operator as cheap as the
    fine one's quarter; the cost here is not representative).

``--path`` also solves the default sphere path (the 27 loads 10⁻⁷ … 2·10⁻² E*L² of ``large_grid.py``, tol
10⁻⁸, ``bem.iter_load_path``) with ``polonsky_keer(..., boundary_terms=k)`` for k = None (today), 0, 1, 3, 63,
and prints the iterations over all loads, those of the largest load, the CPU seconds of the path (process time:
comparable between rows of one run on a loaded machine, unlike the wall time; the kernel's table is
built before the first row) and the largest relative
difference of the depth from today's (k = None) over the loads.

Usage::

    python benchmarks/fixed_set.py [--n 129 257 513 1025] [--hertz] [--path]

``--hertz``: a smooth sphere (one round contact) instead of the rough one.
"""

from __future__ import annotations

import argparse
import functools
import sys
import time
from pathlib import Path

import numpy as np
import scipy.fft
import scipy.ndimage

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import E_STAR, HURST, H_RMS, LENGTH, RADIUS, print_header  # noqa: E402

from large_grid import FORCES  # noqa: E402

from roughcontact import bem, surfaces  # noqa: E402
from roughcontact.bem import contact, solver  # noqa: E402
from roughcontact.bem.preconditioner import fourier_inverse  # noqa: E402

FORCE = 2e-2
TOL = 1e-8
VARIANTS = ("none", "fft", "sqrt-d", "1/sqrt-d", "edge-diag", "schur:0", "schur:1", "schur:3", "schur:7", "schur:63")
#: Measured on request only (``--variants``).
SLOW = ("two-grid",)


def frozen_set(n: int, hertz: bool):
    """Heights, the converged pressure of the largest load and the window of its solve."""
    if hertz:
        x = (np.arange(n) - n // 2) * LENGTH / n
        heights = (x[:, None] ** 2 + x[None, :] ** 2) / (2 * RADIUS)
    else:
        heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, seed=0)
    state = bem.solve(heights, force=FORCE * E_STAR * LENGTH**2, length=LENGTH, e_star=E_STAR, tol=TOL)
    return heights, state.pressure, state.window


def preconditioners(inverse, shape, mask, cells):
    """The preconditioners of :data:`VARIANTS` as functions of a residual on ``cells``."""
    def project(x):
        return x - x.mean()

    distance = scipy.ndimage.distance_transform_edt(mask).reshape(-1)[cells]
    up, down = (np.minimum(distance, 2.0) / 2.0) ** 0.5, (np.minimum(distance, 2.0) / 2.0) ** -0.5
    symbol = inverse.symbol(shape).astype(float)
    kernel = scipy.fft.irfft2(symbol, s=shape)
    m0 = kernel[0, 0]
    outside = (~mask).astype(float)
    squared = scipy.fft.irfft2(scipy.fft.rfft2(kernel**2) * scipy.fft.rfft2(outside), s=shape)
    edge = squared.reshape(-1)[cells] / m0  # Σ_F M_if² / m₀ (the kernel is even)
    table = {
        "none": project,
        "fft": lambda r: inverse(shape, cells, r),
        "sqrt-d": lambda r: project(up * inverse(shape, cells, up * r)),
        "1/sqrt-d": lambda r: project(down * inverse(shape, cells, down * r)),
        "edge-diag": lambda r: project(inverse(shape, cells, r) - edge * r),
    }
    for k in (0, 1, 3, 7, 63):
        table[f"schur:{k}"] = (lambda k: lambda r: inverse(shape, cells, r, boundary_terms=k))(k)
    table["two-grid"] = _two_grid(shape, mask, cells, symbol, m0)
    return table


def _two_grid(shape, mask, cells, symbol, m0):
    """``P_C (M_CC − M_CF V M_FC) P_C`` with ``V ≈ M_FF⁻¹`` one symmetric two-grid cycle (``two-grid``)."""
    outside = ~mask
    coarse = ((shape[0] + 1) // 2, (shape[1] + 1) // 2)

    def window(field):  # M on the window (periodic)
        return scipy.fft.irfft2(scipy.fft.rfft2(field) * symbol, s=shape)

    def operator_ff(field):  # M_FF/m₀, zero on C
        return np.where(outside, window(field), 0.0) / m0

    def prolong(values):
        return np.where(outside, np.repeat(np.repeat(values, 2, 0), 2, 1)[: shape[0], : shape[1]], 0.0)

    def restrict(field):
        padded = np.zeros((2 * coarse[0], 2 * coarse[1]))
        padded[: shape[0], : shape[1]] = field
        return padded.reshape(coarse[0], 2, coarse[1], 2).sum(axis=(1, 3))

    def coarse_solve(rhs):  # CG on Pᵀ (M_FF/m₀) P
        x, r = np.zeros_like(rhs), rhs.copy()
        direction, rr = r.copy(), float((r * r).sum())
        start = np.sqrt(rr)
        for _ in range(1000):
            if np.sqrt(rr) <= 1e-10 * start:
                break
            q = restrict(operator_ff(prolong(direction)))
            alpha = rr / float((direction * q).sum())
            x += alpha * direction
            r -= alpha * q
            rr, old = float((r * r).sum()), rr
            direction = r + (rr / old) * direction
        return x

    def apply(r):
        field = np.zeros(shape)
        field.reshape(-1)[cells] = r
        response = window(field)
        u = np.where(outside, response, 0.0)
        v = u.copy()  # one Richardson step from 0
        v += prolong(coarse_solve(restrict(u - operator_ff(v))))
        v += u - operator_ff(v)
        z = (response - window(v) / m0).reshape(-1)[cells]
        return z - z.mean()
    return apply


def pcg(apply, precondition, rhs, maxiter=5000):
    """Iterations of preconditioned CG to ``‖r‖ ≤ TOL ‖r₀‖`` from 0, and the condition number of the
    preconditioned operator from the Lanczos coefficients (Saad, Iterative Methods, §6.7.3)."""
    x, r = np.zeros_like(rhs), rhs.copy()
    z = precondition(r)
    t, rz, start = z.copy(), r @ z, np.linalg.norm(r)
    alphas, betas = [], []
    while len(alphas) < maxiter:
        kt = apply(t)
        alpha = rz / (t @ kt)
        x += alpha * t
        r -= alpha * kt
        alphas.append(alpha)
        if np.linalg.norm(r) <= TOL * start:
            break
        z = precondition(r)
        rz, beta = r @ z, (r @ z) / rz
        betas.append(beta)
        t = z + beta * t
    m = len(alphas)
    lanczos = np.diag([1 / alphas[j] + (betas[j - 1] / alphas[j - 1] if j else 0.0) for j in range(m)])
    off = [np.sqrt(betas[j]) / alphas[j] for j in range(m - 1)]
    lanczos += np.diag(off, 1) + np.diag(off, -1)
    values = np.linalg.eigvalsh(lanczos)
    return m, values[-1] / values[0]


def measure(n: int, hertz: bool, variants) -> list[tuple[str, int, int, float]]:
    heights, pressure, window = frozen_set(n, hertz)
    operator = contact.operator_for(n, LENGTH, E_STAR, False)
    inverse = fourier_inverse(operator)
    local = pressure[window]
    shape, mask = local.shape, local > 0
    cells = np.flatnonzero(mask)
    field = np.zeros(shape)

    def apply(x):  # P K_CC x
        field.reshape(-1)[:] = 0.0
        field.reshape(-1)[cells] = x
        y = operator(field).reshape(-1)[cells]
        return y - y.mean()

    uniform = np.full(cells.size, pressure.sum() / cells.size)
    lift = (heights - heights.min())[window].reshape(-1)[cells]
    rhs = -lift - apply(uniform)
    rhs -= rhs.mean()
    table = preconditioners(inverse, shape, mask, cells)
    return [(name, cells.size, *pcg(apply, table[name], rhs)) for name in variants]


def path_rows(n: int, terms=(None, 0, 1, 3, 63)) -> list[tuple]:
    """Per ``boundary_terms``: iterations over the default sphere path, of its largest load, CPU seconds, and the
    largest relative depth difference from the first entry's."""
    heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, seed=0)
    forces = np.geomspace(*FORCES[:2], FORCES[2]) * E_STAR * LENGTH**2
    rows, reference = [], None
    contact.operator_for(n, LENGTH, E_STAR, False).coefficients  # the whole table: the first row does not pay it
    try:
        for k in terms:
            contact.polonsky_keer = functools.partial(solver.polonsky_keer, boundary_terms=k)
            tick = time.process_time()
            states = [(s.iterations, s.depth, s.converged)
                      for s in bem.iter_load_path(heights, forces, length=LENGTH, e_star=E_STAR, tol=TOL)]
            seconds = time.process_time() - tick
            iterations, depths, converged = (np.array(column) for column in zip(*states))
            if not converged.all():
                raise RuntimeError(f"n = {n}, boundary_terms = {k}: a load did not converge")
            reference = depths if reference is None else reference
            rows.append((k, int(iterations.sum()), int(iterations.max()), seconds,
                         float(np.abs(depths / reference - 1).max())))
    finally:
        contact.polonsky_keer = solver.polonsky_keer
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[129, 257, 513, 1025])
    parser.add_argument("--hertz", action="store_true", help="a smooth sphere instead of the rough one")
    parser.add_argument("--variants", nargs="+", default=list(VARIANTS), choices=VARIANTS + SLOW)
    parser.add_argument("--path", action="store_true", help="also the default sphere path per boundary_terms")
    args = parser.parse_args(argv)
    print_header(f"{'smooth' if args.hertz else 'rough'} "
          f"sphere, contact set of F = {FORCE:g} E*L² frozen; PCG to rel. residual {TOL:g}")
    print(f"{'n':>5} {'cells':>7} | {'preconditioner':>14} | {'iterations':>10} {'kappa':>7}")
    for n in args.n:
        for name, cells, iterations, kappa in measure(n, args.hertz, args.variants):
            print(f"{n:5d} {cells:7d} | {name:>14} | {iterations:10d} {kappa:7.1f}", flush=True)
    if args.path:
        print(f"default sphere path, {FORCES[2]} loads, tol {TOL:g}; CPU s = process time of the path")
        print(f"{'n':>5} | {'boundary_terms':>14} | {'iterations':>10} {'largest':>7} | {'CPU s':>7} | depth vs None")
        for n in args.n:
            for k, total, largest, seconds, depth in path_rows(n):
                print(f"{n:5d} | {str(k):>14} | {total:10d} {largest:7d} | {seconds:7.2f} | {depth:.1e}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
