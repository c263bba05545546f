"""Large grids: one seed of the default sphere over the default loads, n = 513 … 4097 (8193).

One rough sphere (R = 0.5 L, H = 0.7, h_rms = 9·10⁻³ L, L = 1, E* = 1, seed 0, non-periodic) is
pressed along the default 27 log-spaced loads F/(E* L²) = 10⁻⁷ … 2·10⁻² with tolerance 10⁻⁸ by
:func:`roughcontact.bem.iter_load_path`, as an indent job does (each state dropped once recorded).
Every grid runs in a fresh interpreter, so that its peak resident set size (``ru_maxrss``) is its
own. Prints, per n: the conjugate-gradient iterations over all loads and of the most expensive
load, the wall time of the load path (and of the surface), the peak RSS and the time of one
padded FFT pair (a real forward and inverse transform on ``next_fast_len(2n − 1)²``, the
convolution of a whole grid), then the ratios that issue 41 sets targets for.

Usage::

    python benchmarks/large_grid.py [--n 513 1025 2049 4097] [--huge] [--stiffness]

``--huge`` adds n = 8193 (about 3 GB); ``--stiffness`` also computes the punch stiffness of every
state (``bem.stiffness``, as an indent job does) and reports its time separately. The 4097² grid
takes minutes: run it in the background on a shared machine.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import E_STAR, HURST, H_RMS, LENGTH, RADIUS, print_header  # noqa: E402

#: The default load path of issue 41: 27 loads, F/(E* L²).
FORCES = (1e-7, 2e-2, 27)
TOL = 1e-8


def child(n: int, stiffness: bool) -> dict:
    """Solve the load path on an ``n × n`` grid in this process; the numbers of one row."""
    import resource

    import numpy as np
    import scipy.fft

    from roughcontact import bem, surfaces

    tick = time.perf_counter()
    heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, seed=0)
    surface_seconds = time.perf_counter() - tick
    forces = np.geomspace(*FORCES[:2], FORCES[2]) * E_STAR * LENGTH**2
    iterations, cells, stiffness_seconds = [], [], 0.0
    tick = time.perf_counter()
    for state in bem.iter_load_path(heights, forces, length=LENGTH, e_star=E_STAR, tol=TOL):
        if not state.converged:
            raise RuntimeError(f"n = {n}: the load {state.force:g} did not converge")
        iterations.append(state.iterations)
        cells.append(int(np.count_nonzero(state.contact)))
        if stiffness:
            start = time.perf_counter()
            bem.stiffness(state)
            stiffness_seconds += time.perf_counter() - start
        del state
    seconds = time.perf_counter() - tick
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    size = scipy.fft.next_fast_len(2 * n - 1, real=True)
    field = np.random.default_rng(0).random((size, size))
    pair = np.inf
    for _ in range(3):
        start = time.perf_counter()
        scipy.fft.irfft2(scipy.fft.rfft2(field), s=field.shape)
        pair = min(pair, time.perf_counter() - start)
    return dict(n=n, iterations=sum(iterations), largest=max(iterations), per_load=iterations,
                cells=cells[-1], seconds=seconds - stiffness_seconds, stiffness_seconds=stiffness_seconds,
                surface_seconds=surface_seconds, peak_bytes=peak, fft_pair=pair, padded=size)


def measure(n: int, stiffness: bool) -> dict:
    """:func:`child` in a fresh interpreter (its own peak RSS)."""
    command = [sys.executable, __file__, "--child", str(n)] + (["--stiffness"] if stiffness else [])
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[513, 1025, 2049, 4097],
                        help="grid sizes (default 513 1025 2049 4097)")
    parser.add_argument("--huge", action="store_true", help="add n = 8193")
    parser.add_argument("--stiffness", action="store_true", help="also the punch stiffness of every state")
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        print(json.dumps(child(args.child, args.stiffness)))
        return 0
    sizes = args.n + ([8193] if args.huge and 8193 not in args.n else [])
    print_header(f"rough sphere R={RADIUS:g}, "
          f"H={HURST:g}, h_rms={H_RMS:g}, L={LENGTH:g}, seed 0, non-periodic; {FORCES[2]} loads "
          f"F/(E*L²) = {FORCES[0]:g} … {FORCES[1]:g}, tol {TOL:g}; bem.iter_load_path, one fresh process per n")
    header = (f"{'n':>5} | {'iterations':>10} {'largest':>7} {'cells':>8} | {'wall s':>8} {'stiff s':>8} "
              f"{'surface s':>9} | {'peak GB':>7} | {'padded':>6} {'FFT pair s':>10}")
    print(header)
    print("-" * len(header))
    rows = {}
    for n in sizes:
        row = rows[n] = measure(n, args.stiffness)
        stiff = f"{row['stiffness_seconds']:8.2f}" if args.stiffness else f"{'—':>8}"
        print(f"{n:5d} | {row['iterations']:10d} {row['largest']:7d} {row['cells']:8d} | {row['seconds']:8.2f} "
              f"{stiff} {row['surface_seconds']:9.2f} | {row['peak_bytes'] / 1e9:7.2f} | {row['padded']:6d} "
              f"{row['fft_pair']:10.4f}", flush=True)
    print("-" * len(header))
    for n, row in rows.items():
        print(f"n = {n}: iterations per load {row['per_load']}")
    if 513 in rows and 4097 in rows:
        print(f"iterations(4097)/iterations(513) = {rows[4097]['iterations'] / rows[513]['iterations']:.2f} "
              f"(target ≤ 1.2)")
    if 1025 in rows and 4097 in rows:
        print(f"wall(4097)/wall(1025) = {rows[4097]['seconds'] / rows[1025]['seconds']:.1f} (target ≤ 20; "
              f"FFT pair {rows[4097]['fft_pair'] / rows[1025]['fft_pair']:.1f})")
    if 4097 in rows:
        print(f"peak RSS(4097) = {rows[4097]['peak_bytes'] / 1e9:.2f} GB (target ≤ 1.5)")
    if 8193 in rows and 4097 in rows:
        print(f"peak RSS(8193) = {rows[8193]['peak_bytes'] / 1e9:.2f} GB (target ≤ 6); wall(8193)/wall(4097) = "
              f"{rows[8193]['seconds'] / rows[4097]['seconds']:.1f} (target ≤ 5)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
