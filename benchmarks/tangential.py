"""Tangential contact: the cost of the full-stick stiffness and of a partial-slip path, beside tamaas.

Builds one seeded rough sphere (the heights of ``benchmarks/run.py``) and times

1. the full-stick tangential stiffness :func:`roughcontact.bem.tangential_stiffness` at every load of
   a normal load path on the free half-space, against the normal stiffness
   :func:`roughcontact.bem.stiffness` of the same states (the issue asks for at most its cost);
2. the partial-slip path :func:`roughcontact.bem.partial_slip` at ``Q/μP = 1/21 … 20/21`` (20
   tangential loads) of one normal state on the periodic half-space, and beside it tamaas'
   frictional solvers (``PolonskyKeerTan``, ``Kato``, ``Condat``; tamaas 2.9 solves friction only
   on the periodic ``surface_2d`` model) at the same loads, heights and ``μ``, each load solved on
   the same model one after the other. tamaas solves the normal and both tangential components
   together with the full Boussinesq–Cerruti kernel; at ``ν = 1/2`` (the default here) the
   normal–tangential coupling vanishes, so the pressures must agree, and the tractions ``q_x``
   differ by this package's one-component simplification (``q_y = 0``) and by tamaas' tolerance.

Usage::

    python benchmarks/tangential.py [--n 513] [--loads 20] [--seed 0] [--force 1e-3]
                                    [--poisson 0.5] [--friction 0.5]
                                    [--tamaas pk,kato,condat|none] [--tamaas-loads 20]
                                    [--tamaas-maxiter 1000]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import E_STAR, H_RMS, HURST, LENGTH, RADIUS, machine_lines  # noqa: E402

from roughcontact import bem, surfaces  # noqa: E402

#: The solver's tolerance (its default) and tamaas' (its own error measure, as in run.py).
TOL = 1e-8
TAMAAS_TOL = 1e-8
TAMAAS_SOLVERS = {"pk": "PolonskyKeerTan", "kato": "Kato", "condat": "Condat"}


def full_stick_cost(heights, forces, poisson):
    """Seconds of bem.stiffness and bem.tangential_stiffness per state of a free-space load path
    (a second pass: the kernels' tables and spectra built)."""
    states = bem.load_path(heights, forces, length=LENGTH, e_star=E_STAR, tol=TOL)
    tick = time.perf_counter()
    for state in states:  # a first pass builds the operators' tables and spectra (timed apart)
        bem.stiffness(state)
    middle = time.perf_counter()
    for state in states:
        bem.tangential_stiffness(state, poisson=poisson)
    print(f"first pass (building the kernels): k_n {middle - tick:.3f} s, k_t {time.perf_counter() - middle:.3f} s")
    rows = []
    for state in states:
        tick = time.perf_counter()
        k_n = bem.stiffness(state)
        middle = time.perf_counter()
        k_t = bem.tangential_stiffness(state, poisson=poisson)
        rows.append((state.force, int(state.contact.sum()), k_n, k_t, middle - tick,
                     time.perf_counter() - middle))
    return rows


def tamaas_path(heights, state, fractions, friction, poisson, name, maxiter):
    """One tamaas solver along the fractions: (tractions (k, n, n, 3), seconds per load)."""
    import tamaas as tm

    n = heights.shape[0]
    model = tm.ModelFactory.createModel(tm.model_type.surface_2d, [LENGTH, LENGTH], [n, n])
    model.E, model.nu = E_STAR * (1 - poisson**2), poisson
    solver = getattr(tm, TAMAAS_SOLVERS[name])(model, -heights, TAMAAS_TOL, friction)
    solver.max_iter = maxiter
    tm.set_log_level(tm.LogLevel.error)  # tamaas prints its iteration table from C++
    mean = state.force / LENGTH**2
    tractions, seconds = [], []
    for fraction in fractions:
        tick = time.perf_counter()
        solver.solve([fraction * friction * mean, 0.0, mean])
        seconds.append(time.perf_counter() - tick)
        tractions.append(np.array(model.traction))
    return np.array(tractions), np.array(seconds)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=513, help="grid points per side (default 513)")
    parser.add_argument("--loads", type=int, default=20, help="tangential loads (default 20)")
    parser.add_argument("--seed", type=int, default=0, help="roughness seed (default 0)")
    parser.add_argument("--force", type=float, default=1e-3, help="normal force / (E* L²) (default 1e-3)")
    parser.add_argument("--poisson", type=float, default=0.5, help="Poisson ratio (default 0.5)")
    parser.add_argument("--friction", type=float, default=0.5, help="friction coefficient (default 0.5)")
    parser.add_argument("--tamaas", default="pk,kato,condat", help="tamaas solvers, or none")
    parser.add_argument("--tamaas-loads", type=int, default=None,
                        help="solve only the first k loads in tamaas (default: all)")
    parser.add_argument("--tamaas-maxiter", type=int, default=1000, help="tamaas iterations per load")
    args = parser.parse_args(argv)
    heights = surfaces.rough_sphere(args.n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH,
                                    seed=args.seed)
    force = args.force * E_STAR * LENGTH**2
    print("\n".join(machine_lines([])))
    print(f"{time.strftime('%Y-%m-%d %H:%M:%S %Z')}: {args.n}² rough sphere (H = {HURST}, h_rms = {H_RMS}, "
          f"R = {RADIUS}), nu = {args.poisson}, mu = {args.friction}, tol = {TOL}")

    print("\n1. full-stick k_t against the normal k_n, free half-space, 10 loads up to the force")
    rows = full_stick_cost(heights, force * np.geomspace(1e-2, 1, 10), args.poisson)
    print(f"{'F/(E*L²)':>10} {'cells':>7} {'k_t/k_n':>8} {'k_n s':>8} {'k_t s':>8} {'ratio':>6}")
    for f, cells, k_n, k_t, t_n, t_t in rows:
        print(f"{f / (E_STAR * LENGTH**2):10.3g} {cells:7d} {k_t / k_n:8.4f} {t_n:8.3f} {t_t:8.3f} {t_t / t_n:6.2f}")
    total_n, total_t = sum(r[4] for r in rows), sum(r[5] for r in rows)
    print(f"total: k_n {total_n:.2f} s, k_t {total_t:.2f} s, k_t/k_n time {total_t / total_n:.2f}")

    print(f"\n2. partial slip, periodic half-space, {args.loads} loads Q/(mu P) = 1/{args.loads + 1} … "
          f"{args.loads}/{args.loads + 1}")
    fractions = np.arange(1, args.loads + 1) / (args.loads + 1)
    tick = time.perf_counter()
    state = bem.solve(heights, force=force, length=LENGTH, e_star=E_STAR, periodic=True, tol=TOL)
    normal_seconds = time.perf_counter() - tick
    tick = time.perf_counter()
    path = bem.partial_slip(state, fractions, friction=args.friction, poisson=args.poisson, tol=TOL,
                            stiffness=False)
    ours = time.perf_counter() - tick
    tick = time.perf_counter()
    bem.partial_slip(state, fractions, friction=args.friction, poisson=args.poisson, tol=TOL)
    ours_with_k = time.perf_counter() - tick
    print(f"normal solve {normal_seconds:.2f} s, {int(state.contact.sum())} contact cells")
    print(f"roughcontact: {ours:.2f} s ({ours_with_k:.2f} s with k_t(Q) at every load), "
          f"{sum(s.iterations for s in path.states)} products")
    if args.tamaas == "none":
        return 0
    try:
        import tamaas  # noqa: F401
    except ImportError:
        print("tamaas not installed: no comparison")
        return 0
    k = args.loads if args.tamaas_loads is None else min(args.tamaas_loads, args.loads)
    scale = args.friction * state.pressure.max()
    print(f"{'tamaas solver':>16} {'loads':>5} {'seconds':>9} {'per load':>9} {'speed-up':>8} "
          f"{'max|dp|/p':>10} {'max|dq_x|':>10} {'max|q_y|':>9}  (tractions / mu max p)")
    for name in args.tamaas.split(","):
        tractions, seconds = tamaas_path(heights, state, fractions[:k], args.friction, args.poisson, name,
                                         args.tamaas_maxiter)
        dp = np.abs(tractions[..., 2] - state.pressure).max() / state.pressure.max()
        dq = max(np.abs(t[..., 0] - s.traction).max() for t, s in zip(tractions, path.states)) / scale
        qy = np.abs(tractions[..., 1]).max() / scale
        speed = seconds.sum() / k / (ours / args.loads)
        print(f"{TAMAAS_SOLVERS[name]:>16} {k:5d} {seconds.sum():9.2f} {seconds.mean():9.3f} {speed:8.1f} "
              f"{dp:10.2e} {dq:10.2e} {qy:9.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
