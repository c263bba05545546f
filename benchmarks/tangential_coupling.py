"""The size of the normal–tangential coupling that the tangential solvers neglect, one iteration deep.

Cerruti's ``u_z = −Q(1 − 2ν)/(4πG) · x/ρ²`` (Johnson 1985, eq. 2.19c) of the partial-slip tractions
``q_x`` of :func:`roughcontact.bem.partial_slip` is added to the surface (the gap
``g = lift − d + u(p) + u_z(q)``) and the normal problem solved again at the same force: the change
of the pressure and of the approach is the first step of a coupled (non-Goodman) iteration, a
measure of what the neglect leaves out (it vanishes at ν = 1/2). Reported: the largest change of
the pressure (over the contact, and inside ``r < 0.8a``, away from the edge cells that open or
close), the mean change ``Σ|Δp|/Σp``, the shift of the pressure's centre along ``x`` in cells,
and the changes of the approach and of the contact area. The cell integral of ``x/ρ²`` is
``Σ_corners ± [X atan(Y/X) + (Y/2) ln(X² + Y²)]`` (``X = i ± 1/2``, ``Y = j ± 1/2``, ``x`` along
the first axis), convolved over signed offsets by FFT (``scipy.signal.fftconvolve``).

Usage::

    python benchmarks/tangential_coupling.py [--cells 24] [--friction 0.5] [--fraction 0.5]
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
from scipy.signal import fftconvolve

from roughcontact import bem, surfaces


def coupling_coefficients(n: int) -> np.ndarray:
    """``∫∫_cell x/ρ² dx dy`` at signed offsets ``(i, j)``, ``|i|, |j| < n`` (cell units), shape (2n−1)²."""
    offset = np.arange(-(n - 1), n, dtype=float)
    x, y = offset[:, None], offset[None, :]

    def corner(cx, cy):
        return cx * np.arctan(cy / cx) + 0.5 * cy * np.log(cx * cx + cy * cy)

    return (corner(x + 0.5, y + 0.5) - corner(x + 0.5, y - 0.5)
            - corner(x - 0.5, y + 0.5) + corner(x - 0.5, y - 0.5))


def normal_displacement(traction, *, length, e_star, poisson):
    """Cerruti's ``u_z`` of the cell tractions ``q_x`` (free half-space, positive into it)."""
    n = traction.shape[0]
    shear = e_star * (1 - poisson) / 2
    # ∫∫ x/ρ² over a cell of side Δ is Δ times the cell-unit integral
    kernel = -(1 - 2 * poisson) / (4 * np.pi * shear) * coupling_coefficients(n) * (length / n)
    return fftconvolve(traction, kernel, mode="same")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cells", type=int, default=24, help="Hertz contact radius in cells (default 24)")
    parser.add_argument("--friction", type=float, default=0.5)
    parser.add_argument("--fraction", type=float, default=0.5, help="Q/(mu P) (default 0.5)")
    args = parser.parse_args(argv)
    n = 4 * args.cells + 1
    a = args.cells / n
    force = 4 * a**3 / 3
    heights = surfaces.paraboloid(n, radius=1.0, length=1.0)
    state = bem.solve(heights, force=force, length=1.0, e_star=1.0)
    print(f"Hertz sphere, a = {args.cells} cells on {n}², mu = {args.friction}, Q/(mu P) = {args.fraction}")
    print(f"{'nu':>5} {'max|u_z(q)|/d':>14} {'max|dp|/max p':>14} {'inner':>8} {'mean|dp|/p':>10} "
          f"{'shift/cell':>10} {'d_d/d':>10} {'dA/A':>8}")
    centre = np.arange(n) - n // 2
    inner = np.hypot(centre[:, None], centre[None, :]) < 0.8 * args.cells
    for poisson in (0.0, 0.15, 0.3, 0.45, 0.5):
        # q_x alone: u_z below is Cerruti's of q_x (the q_y of two components, ≤ 4 % of μ max p on this
        # sphere, is left out with it; the recorded numbers were taken this way)
        path = bem.partial_slip(state, [args.fraction], friction=args.friction, poisson=poisson, stiffness=False,
                                components=1)
        u_z = normal_displacement(path.states[0].traction, length=1.0, e_star=1.0, poisson=poisson)
        coupled = bem.solve(heights + u_z, force=force, length=1.0, e_star=1.0)
        change = np.abs(coupled.pressure - state.pressure)
        dp = change.max() / state.pressure.max()
        dp_inner = change[inner].max() / state.pressure.max()
        mean = change.sum() / state.pressure.sum()
        shift = ((coupled.pressure.sum(axis=1) - state.pressure.sum(axis=1)) @ centre) / state.pressure.sum()
        dd = (coupled.depth + (heights + u_z).min() - heights.min()) / state.depth - 1
        da = coupled.contact_area / state.contact_area - 1
        print(f"{poisson:5.2f} {np.abs(u_z[state.contact]).max() / state.depth:14.3e} {dp:14.3e} {dp_inner:8.2e} "
              f"{mean:10.2e} {shift:10.3f} {dd:10.2e} {da:8.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
