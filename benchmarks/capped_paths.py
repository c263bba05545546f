"""Hardness-capped load paths drawn at random: how many converge, in how many iterations and how
much CPU (issue 47; the kernel :func:`roughcontact.bem.bounded.bounded_cg`).

Each path is a rough sphere (H 0.1–0.9, R 0.25–1 L, h_rms 3·10⁻³–2·10⁻² L, hardness 0.005–0.2 E*,
n 128–257 odd and even, the 12 loads 10⁻⁵ … 1.9·10⁻³ E*L² of ``presets/plastic.yaml``) or a
nominally flat periodic surface (n 33–129, 8 loads 10⁻⁴ … min(H/2, 0.05) E*L²), solved as drawn
and again with its heights multiplied by ``1 + 10⁻¹⁵ ξ`` (``ξ`` a seeded standard normal field).
A path whose contact reaches the edge of the free grid is counted apart (not a solver failure).

To compare with another version of the package, run the same command with that version first on
``PYTHONPATH`` (e.g. a ``git worktree`` of an older commit: ``PYTHONPATH=/tmp/old/src python
benchmarks/capped_paths.py``): the draws depend only on ``--seed``.

Usage::

    python benchmarks/capped_paths.py [--spheres 61] [--flats 40] [--seed 1]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import print_header  # noqa: E402

from roughcontact import bem, surfaces  # noqa: E402
from roughcontact.errors import DomainTooSmallError  # noqa: E402


def _log_uniform(rng, low, high):
    return float(10 ** rng.uniform(np.log10(low), np.log10(high)))


def sphere_draw(rng):
    """One rough-sphere path: (heights, forces, keyword arguments of bem.load_path, label)."""
    hurst, radius = rng.uniform(0.1, 0.9), rng.uniform(0.25, 1.0)
    h_rms, hardness = _log_uniform(rng, 3e-3, 2e-2), _log_uniform(rng, 5e-3, 0.2)
    n, seed = int(rng.integers(128, 258)), int(rng.integers(0, 1000))
    z = surfaces.rough_sphere(n, radius=radius, hurst=hurst, h_rms=h_rms, length=1.0, seed=seed)
    label = f"sphere H={hurst:.2f} R={radius:.2f} h={h_rms:.2g} hard={hardness:.3g} n={n} seed={seed}"
    return z, np.geomspace(1e-5, 1.9e-3, 12), {"hardness": hardness}, label, seed


def flat_draw(rng):
    """One nominally flat periodic path."""
    hurst, h_rms = rng.uniform(0.1, 0.9), _log_uniform(rng, 3e-3, 2e-2)
    hardness = _log_uniform(rng, 5e-3, 0.2)
    n, seed = int(rng.integers(33, 130)), int(rng.integers(0, 1000))
    z = surfaces.self_affine(n, hurst=hurst, h_rms=h_rms, length=1.0, seed=seed)
    label = f"flat H={hurst:.2f} h={h_rms:.2g} hard={hardness:.3g} n={n} seed={seed}"
    forces = np.geomspace(1e-4, min(0.5 * hardness, 0.05), 8)
    return z, forces, {"hardness": hardness, "periodic": True}, label, seed


def solve(z, forces, kwargs):
    """(states or None if the contact reached the edge, CPU seconds)."""
    start = time.process_time()
    try:
        states = bem.load_path(z, forces, length=1.0, e_star=1.0, **kwargs)
    except DomainTooSmallError:
        states = None
    return states, time.process_time() - start


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--spheres", type=int, default=61, help="sphere draws (each solved twice)")
    parser.add_argument("--flats", type=int, default=40, help="flat periodic draws (each solved twice)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the draws")
    args = parser.parse_args(argv)
    print_header(f"capped_paths: {args.spheres} sphere and {args.flats} flat draws, seed {args.seed}")
    rng = np.random.default_rng(args.seed)
    print(f"{'kind':<7}{'paths':>7}{'failed':>8}{'edge':>6}{'loads':>7}{'it/load':>9}{'max it':>8}{'CPU s':>8}")
    for kind, draw, count in (("sphere", sphere_draw, args.spheres), ("flat", flat_draw, args.flats)):
        paths = failed = edge = 0
        iterations, cpu = [], 0.0
        for _ in range(count):
            z, forces, kwargs, label, seed = draw(rng)
            noise = 1.0 + 1e-15 * np.random.default_rng(seed).standard_normal(z.shape)
            for heights, how in ((z, "as drawn"), (z * noise, "perturbed")):
                states, seconds = solve(heights, forces, kwargs)
                paths += 1
                cpu += seconds
                if states is None:
                    edge += 1
                    continue
                iterations += [s.iterations for s in states]
                bad = [i for i, s in enumerate(states) if not s.converged]
                if bad:
                    failed += 1
                    why = getattr(states[bad[0]], "diagnosis", "")
                    print(f"  FAILED {label} ({how}) at load {bad[0] + 1}: {why}", file=sys.stderr)
        print(f"{kind:<7}{paths:>7}{failed:>8}{edge:>6}{len(iterations):>7}{np.mean(iterations):>9.1f}"
              f"{max(iterations):>8}{cpu:>8.1f}")


if __name__ == "__main__":
    main()
