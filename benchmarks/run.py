"""Load-path benchmark: roughcontact against ContactMechanics and tamaas.

Builds one rough sphere, solves a log-spaced force-controlled load path with the
stiffness at every force in roughcontact (``bem.load_path`` and the exact
tangent ``bem.stiffness``) and in each peer (warm-started solves and the
central difference quotient from two extra solves at ``F(1 ± 1e-3)``), all on
the same heights and tolerance, and prints one table with times, iterations
and the relative differences of depth and stiffness.

Usage::

    python benchmarks/run.py [--n 513] [--forces 20] [--peers cm,tamaas] [--seed 0]
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np
import scipy

sys.path.insert(0, str(Path(__file__).resolve().parent))

import peers  # noqa: E402
import roughcontact  # noqa: E402
from roughcontact import bem
from roughcontact import surfaces  # noqa: E402

LENGTH = 1.0
E_STAR = 1.0
RADIUS = 0.5
HURST = 0.7
H_RMS = 9e-3
FORCE_RANGE = (1e-7, 1e-2)     # F/(E* L²)
REL_STEP = 1e-3


def cpu_model() -> str:
    """CPU model name from /proc/cpuinfo (``"unknown"`` where it is not available)."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as cpuinfo:
            for line in cpuinfo:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def machine_lines(peer_names) -> list[str]:
    """Lines describing the machine and the versions of everything that was timed."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    lines = [
        f"machine: {cpu_model()}, {cores} usable cores, {platform.system()} {platform.release()}",
        f"python {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, "
        f"roughcontact {roughcontact.__version__}",
    ]
    if peer_names:
        versions = peers.peer_versions()
        lines.append("peers: " + ", ".join(f"{name} {v}" for name, v in versions.items()))
    return lines


def print_header(what: str) -> None:
    """Print the machine lines (:func:`machine_lines`, no peers) and ``started <UTC time> UTC; <what>``:
    the head of a benchmark's table."""
    for line in machine_lines([]):
        print(line)
    print(f"started {time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC; {what}")


def run_roughcontact(heights, forces, tol):
    """Load path and tangent stiffness in roughcontact; per-force times from the progress hook."""
    stamps = []
    start = time.perf_counter()
    states = bem.load_path(heights, forces, length=LENGTH, e_star=E_STAR, tol=tol,
                               progress=lambda i, total, state: stamps.append(time.perf_counter()))
    solve_seconds = np.diff([start] + stamps)
    stiffness, stiffness_seconds = [], []
    for state in states:
        tick = time.perf_counter()
        stiffness.append(bem.stiffness(state))
        stiffness_seconds.append(time.perf_counter() - tick)
    return states, solve_seconds, np.array(stiffness), np.array(stiffness_seconds)


def parse_peers(text: str) -> list[str]:
    """``"cm,tamaas"`` → ``["cm", "tamaas"]``; ``"none"`` → ``[]``."""
    names = [name.strip() for name in text.split(",") if name.strip()]
    if names == ["none"]:
        return []
    unknown = [name for name in names if name not in peers.PEER_NAMES]
    if unknown:
        raise argparse.ArgumentTypeError(
            f"unknown peer(s) {unknown}; choose from {peers.PEER_NAMES} or 'none'")
    return names


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=513, help="grid points per side (default 513)")
    parser.add_argument("--forces", type=int, default=20,
                        help="number of log-spaced forces from 1e-7 to 1e-2 E*L² (default 20)")
    parser.add_argument("--peers", type=parse_peers, default=["cm", "tamaas"],
                        help="comma-separated peers among cm,tamaas, or 'none' (default cm,tamaas)")
    parser.add_argument("--seed", type=int, default=0, help="roughness seed (default 0)")
    parser.add_argument("--tol", type=float, default=1e-8, help="solver tolerance (default 1e-8)")
    parser.add_argument("--cm-solver", choices=("bugnicourt", "polonsky_keer"), default="polonsky_keer",
                        help="ContactMechanics solver (default polonsky_keer; bugnicourt breaks down on a one-cell contact)")
    args = parser.parse_args(argv)

    forces = np.logspace(np.log10(FORCE_RANGE[0]), np.log10(FORCE_RANGE[1]), args.forces)
    forces *= E_STAR * LENGTH**2
    heights = surfaces.rough_sphere(args.n, radius=RADIUS, hurst=HURST, h_rms=H_RMS,
                                    length=LENGTH, seed=args.seed)

    for line in machine_lines(args.peers):
        print(line)
    print(f"problem: n={args.n}, L={LENGTH:g}, R={RADIUS:g}, H={HURST:g}, h_rms={H_RMS:g}, "
          f"E*={E_STAR:g}, seed={args.seed}, tol={args.tol:g}, {args.forces} forces "
          f"{FORCE_RANGE[0]:g}..{FORCE_RANGE[1]:g} E*L²; peer stiffness: central difference "
          f"at F(1±{REL_STEP:g})")
    print("note: wall times on a shared machine; other processes add noise", flush=True)

    states, solve_seconds, stiffness, stiffness_seconds = run_roughcontact(heights, forces, args.tol)
    if not all(state.converged for state in states):
        print("warning: roughcontact did not converge at some force", file=sys.stderr)

    results = {}
    for name in args.peers:
        if name == "cm":
            peer = peers.ContactMechanicsPeer(heights, length=LENGTH, e_star=E_STAR, tol=args.tol,
                                              solver=args.cm_solver)
        else:
            peer = peers.make_peer(name, heights, length=LENGTH, e_star=E_STAR, tol=args.tol)
        print(f"running {peer.name} ...", file=sys.stderr, flush=True)
        results[name] = (peer, peers.load_path(peer, forces, rel_step=REL_STEP))

    header = f"{'F/E*L²':>9} {'cells':>6} | {'ours s':>8} {'(solve':>8} {'stiff)':>8} {'it':>5}"
    for name, (peer, _) in results.items():
        header += f" | {name + ' s':>8} {'it':>5} {'Δd/d':>9} {'Δk/k':>9}"
    print(header)
    print("-" * len(header))
    for i, state in enumerate(states):
        ours_total = solve_seconds[i] + stiffness_seconds[i]
        row = (f"{forces[i]:9.3g} {int(state.contact.sum()):6d} | {ours_total:8.4f} "
               f"{solve_seconds[i]:8.4f} {stiffness_seconds[i]:8.4f} {state.iterations:5d}")
        for name, (peer, points) in results.items():
            point = points[i]
            depth_difference = (point.depth - state.depth) / state.depth
            stiffness_difference = (point.stiffness - stiffness[i]) / stiffness[i]
            row += (f" | {point.solve_seconds + point.stiffness_seconds:8.3f} "
                    f"{point.iterations:5d} {depth_difference:9.1e} {stiffness_difference:9.1e}")
        print(row)
    print("-" * len(header))

    ours_total = float(solve_seconds.sum() + stiffness_seconds.sum())
    print(f"roughcontact: total {ours_total:.3f} s (solves {solve_seconds.sum():.3f} s, "
          f"tangent stiffness {stiffness_seconds.sum():.3f} s), "
          f"{sum(state.iterations for state in states)} iterations")
    for name, (peer, points) in results.items():
        solve_total = sum(point.solve_seconds for point in points)
        stiffness_total = sum(point.stiffness_seconds for point in points)
        total = solve_total + stiffness_total
        depth_max = max(abs(point.depth / state.depth - 1) for point, state in zip(points, states))
        stiffness_max = max(abs(point.stiffness / k - 1) for point, k in zip(points, stiffness))
        label = peer.name + (f" ({args.cm_solver})" if name == "cm" else "")
        print(f"{label}: total {total:.3f} s (solves {solve_total:.3f} s, difference-quotient "
              f"stiffness {stiffness_total:.3f} s), "
              f"{sum(p.iterations + p.stiffness_iterations for p in points)} iterations; "
              f"time ratio {label}/roughcontact = {total / ours_total:.1f}; "
              f"max |Δd/d| = {depth_max:.1e}, max |Δk/k| = {stiffness_max:.1e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
