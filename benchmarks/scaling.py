"""Cost growth with the grid: one rough-sphere solve at a fixed contact radius, n = 129 … 1025.

The sphere (R = 0.5, H = 0.7, h_rms = 9e-3, L = 1) is pressed by the same force on every grid,
so the contact radius (≈ 0.07 L, Hertz) and the window around it are fixed in physical units;
the windowed solve convolves on that window, the full-grid solve on the 2n × 2n padded grid.
Prints, per n: the window the solve ran on, time and iterations of a cold solve windowed and
on the whole grid, the tangent stiffness time, and the relative difference of depth and
stiffness between the two solves.

Usage::

    python benchmarks/scaling.py [--n 129 257 513 1025] [--force 1e-3] [--repeat 3]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import E_STAR, HURST, H_RMS, LENGTH, RADIUS, machine_lines  # noqa: E402

from roughcontact import bem
from roughcontact import surfaces  # noqa: E402


def best_of(repeat: int, func):
    """Result of the fastest of ``repeat`` calls of ``func`` and its wall time (s)."""
    best, result = np.inf, None
    for _ in range(repeat):
        tick = time.perf_counter()
        result = func()
        best = min(best, time.perf_counter() - tick)
    return result, best


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[129, 257, 513, 1025],
                        help="grid sizes (default 129 257 513 1025)")
    parser.add_argument("--force", type=float, default=1e-3, help="F/(E* L²) (default 1e-3)")
    parser.add_argument("--repeat", type=int, default=3, help="timed repeats, best kept (default 3)")
    parser.add_argument("--tol", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    args = parser.parse_args(argv)

    for line in machine_lines([]):
        print(line)
    force = args.force * E_STAR * LENGTH**2
    print(f"problem: rough sphere R={RADIUS:g}, H={HURST:g}, h_rms={H_RMS:g}, L={LENGTH:g}, seed=0, "
          f"F/(E*L²)={args.force:g}, tol={args.tol:g}; cold solves, best of {args.repeat}")
    header = (f"{'n':>5} {'cells':>6} {'window':>9} | {'windowed s':>10} {'it':>4} {'stiff s':>8} | "
              f"{'full s':>8} {'it':>4} {'stiff s':>8} | {'full/win':>8} {'Δd/d':>9} {'Δk/k':>9}")
    print(header)
    print("-" * len(header))
    for n in args.n:
        heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH,
                                        seed=0)
        timed = {}
        for windowed in (True, False):
            state, seconds = best_of(args.repeat, lambda: bem.solve(
                heights, force=force, length=LENGTH, e_star=E_STAR, tol=args.tol,
                windowed=windowed))
            stiffness, stiffness_seconds = best_of(args.repeat, lambda: bem.stiffness(state))
            timed[windowed] = (state, seconds, stiffness, stiffness_seconds)
        win, full = timed[True], timed[False]
        rows, cols = win[0].window
        size = f"{rows.stop - rows.start}x{cols.stop - cols.start}"
        print(f"{n:5d} {int(win[0].contact.sum()):6d} {size:>9} | {win[1]:10.4f} {win[0].iterations:4d} "
              f"{win[3]:8.4f} | {full[1]:8.4f} {full[0].iterations:4d} {full[3]:8.4f} | "
              f"{(full[1] + full[3]) / (win[1] + win[3]):8.1f} "
              f"{win[0].depth / full[0].depth - 1:9.1e} {win[2] / full[2] - 1:9.1e}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
