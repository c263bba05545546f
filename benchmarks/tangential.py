"""Tangential contact: the cost of the full-stick stiffness and of a partial-slip path, beside tamaas.

Builds one seeded rough sphere (the heights of ``benchmarks/run.py``) and times

1. the full-stick tangential stiffness :func:`roughcontact.bem.tangential_stiffness` at every load of
   a normal load path on the free half-space, against the normal stiffness
   :func:`roughcontact.bem.stiffness` of the same states (the issue asks for at most its cost);
2. the partial-slip path :func:`roughcontact.bem.partial_slip` at ``Q/μP = 1/21 … 20/21`` (20
   tangential loads) of one normal state on the periodic half-space, with two traction components
   (the default) and with one, and beside it tamaas' frictional solvers (``PolonskyKeerTan``,
   ``Kato``, ``Condat``; tamaas 2.9 solves friction only on the periodic ``surface_2d`` model) at
   chosen loads of the same path (same heights, ``μ`` and ``ν``), each solved on a fresh model.
   tamaas solves the normal and both tangential components together with the full
   Boussinesq–Cerruti kernel; at ``ν = 1/2`` (the default here) the normal–tangential coupling
   vanishes, so the pressures must agree, and the tractions ``(q_x, q_y)`` must agree with the
   two-component path to tamaas' convergence. ``--save`` keeps every traction field (npz).

Usage::

    python benchmarks/tangential.py [--n 513] [--loads 20] [--seed 0] [--force 1e-3]
                                    [--poisson 0.5] [--friction 0.5]
                                    [--tamaas pk,kato,condat|none] [--tamaas-loads 10]
                                    [--tamaas-maxiter 1000] [--tamaas-tol 1e-8] [--sections 1,2]
                                    [--save out.npz]
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
    """Seconds of bem.stiffness and bem.tangential_stiffness (one and two components) per state of a
    free-space load path (a second pass: the kernels' tables and spectra built)."""
    states = bem.load_path(heights, forces, length=LENGTH, e_star=E_STAR, tol=TOL)
    tick = time.perf_counter()
    for state in states:  # a first pass builds the operators' tables and spectra (timed apart)
        bem.stiffness(state)
    middle = time.perf_counter()
    for state in states:
        bem.tangential_stiffness(state, poisson=poisson)
        bem.tangential_stiffness(state, poisson=poisson, components=2)
    print(f"first pass (building the kernels): k_n {middle - tick:.3f} s, k_t (1 and 2 components) "
          f"{time.perf_counter() - middle:.3f} s")
    rows = []
    for state in states:
        ticks = [time.perf_counter()]
        k_n = bem.stiffness(state)
        ticks.append(time.perf_counter())
        k_t = bem.tangential_stiffness(state, poisson=poisson)
        ticks.append(time.perf_counter())
        k_t2 = bem.tangential_stiffness(state, poisson=poisson, components=2)
        ticks.append(time.perf_counter())
        rows.append((state.force, int(state.contact.sum()), k_n, k_t, k_t2, *np.diff(ticks)))
    return rows


def tamaas_path(heights, state, fractions, friction, poisson, name, maxiter, tol):
    """One tamaas solver at each fraction, each on a fresh model: (tractions (k, n, n, 3), seconds
    per load)."""
    import tamaas as tm

    n = heights.shape[0]
    tm.set_log_level(tm.LogLevel.error)  # tamaas prints its iteration table from C++
    mean = state.force / LENGTH**2
    tractions, seconds = [], []
    for fraction in fractions:
        model = tm.ModelFactory.createModel(tm.model_type.surface_2d, [LENGTH, LENGTH], [n, n])
        model.E, model.nu = E_STAR * (1 - poisson**2), poisson
        solver = getattr(tm, TAMAAS_SOLVERS[name])(model, -heights, tol, friction)
        solver.max_iter = maxiter
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
    parser.add_argument("--tamaas-loads", default="10",
                        help="the loads (1 … loads, comma-separated) solved in tamaas (default 10)")
    parser.add_argument("--tamaas-maxiter", type=int, default=1000, help="tamaas iterations per load")
    parser.add_argument("--tamaas-tol", type=float, default=TAMAAS_TOL, help="tamaas' tolerance")
    parser.add_argument("--sections", default="1,2", help="sections to run (default 1,2)")
    parser.add_argument("--save", default=None, help="save the traction fields to this npz file")
    args = parser.parse_args(argv)
    heights = surfaces.rough_sphere(args.n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH,
                                    seed=args.seed)
    force = args.force * E_STAR * LENGTH**2
    print("\n".join(machine_lines([])))
    print(f"{time.strftime('%Y-%m-%d %H:%M:%S %Z')}: {args.n}² rough sphere (H = {HURST}, h_rms = {H_RMS}, "
          f"R = {RADIUS}), nu = {args.poisson}, mu = {args.friction}, tol = {TOL}")

    if "1" in args.sections.split(","):
        print("\n1. full-stick k_t against the normal k_n, free half-space, 10 loads up to the force")
        rows = full_stick_cost(heights, force * np.geomspace(1e-2, 1, 10), args.poisson)
        print(f"{'F/(E*L²)':>10} {'cells':>7} {'k_t/k_n':>8} {'k_t2/k_t-1':>10} {'k_n s':>8} {'k_t s':>8} "
              f"{'k_t2 s':>8} {'ratio':>6}")
        for f, cells, k_n, k_t, k_t2, t_n, t_t, t_t2 in rows:
            print(f"{f / (E_STAR * LENGTH**2):10.3g} {cells:7d} {k_t / k_n:8.4f} {k_t2 / k_t - 1:10.2e} {t_n:8.3f} "
                  f"{t_t:8.3f} {t_t2:8.3f} {t_t / t_n:6.2f}")
        totals = [sum(r[i] for r in rows) for i in (5, 6, 7)]
        print(f"total: k_n {totals[0]:.2f} s, k_t {totals[1]:.2f} s (two components {totals[2]:.2f} s), "
              f"k_t/k_n time {totals[1] / totals[0]:.2f} ({totals[2] / totals[0]:.2f})")
    if "2" not in args.sections.split(","):
        return 0

    print(f"\n2. partial slip, periodic half-space, {args.loads} loads Q/(mu P) = 1/{args.loads + 1} … "
          f"{args.loads}/{args.loads + 1}")
    fractions = np.arange(1, args.loads + 1) / (args.loads + 1)
    tick = time.perf_counter()
    state = bem.solve(heights, force=force, length=LENGTH, e_star=E_STAR, periodic=True, tol=TOL)
    normal_seconds = time.perf_counter() - tick
    timings, paths = {}, {}
    for components in (2, 1):
        for with_k in (False, True):
            tick = time.perf_counter()
            path = bem.partial_slip(state, fractions, friction=args.friction, poisson=args.poisson, tol=TOL,
                                    stiffness=with_k, components=components)
            timings[components, with_k] = time.perf_counter() - tick
        paths[components] = path
    scale = args.friction * state.pressure.max()
    print(f"normal solve {normal_seconds:.2f} s, {int(state.contact.sum())} contact cells")
    for components, path in paths.items():
        print(f"roughcontact, {components} component(s): {timings[components, False]:.2f} s "
              f"({timings[components, True]:.2f} s with k_t(Q) at every load), "
              f"{sum(s.iterations for s in path.states)} products, max |q_y| / mu max p "
              f"{max(np.abs(s.traction_y).max() for s in path.states) / scale:.2e}")
    one, two = paths[1].states, paths[2].states
    print("one against two components, max over loads / mu max p: q_x "
          f"{max(np.abs(a.traction - b.traction).max() for a, b in zip(one, two)) / scale:.2e}; "
          f"delta_x {max(abs(a.displacement / b.displacement - 1) for a, b in zip(one, two)):.2e} relative, "
          f"k_t(Q) {max(abs(a / b - 1) for a, b in zip(paths[1].stiffnesses, paths[2].stiffnesses)):.2e}")
    saved = {"pressure": state.pressure, "fractions": fractions,
             **{f"q{c}": np.array([[s.traction, s.traction_y] for s in p.states]) for c, p in paths.items()}}
    ours = timings[2, False]
    if args.tamaas != "none":
        try:
            import tamaas  # noqa: F401
        except ImportError:
            print("tamaas not installed: no comparison")
            args.tamaas = "none"
    if args.tamaas != "none":
        loads = [int(k) - 1 for k in args.tamaas_loads.split(",")]
        print(f"tamaas at loads {[k + 1 for k in loads]}, its tolerance {args.tamaas_tol:g}, at most "
              f"{args.tamaas_maxiter} iterations; differences from the two-component path / mu max p")
        print(f"{'tamaas solver':>16} {'loads':>5} {'seconds':>9} {'per load':>9} {'speed-up':>8} "
              f"{'max|dp|/p':>10} {'max|dq_x|':>10} {'max|dq_y|':>10} {'1-comp dq_x':>11}")
        for name in args.tamaas.split(","):
            tractions, seconds = tamaas_path(heights, state, fractions[loads], args.friction, args.poisson,
                                             name, args.tamaas_maxiter, args.tamaas_tol)
            saved[f"tamaas_{name}"] = tractions
            dp = np.abs(tractions[..., 2] - state.pressure).max() / state.pressure.max()
            dq = [max(np.abs(t[..., i] - f).max() for t, f in zip(tractions, fields)) / scale
                  for i, fields in ((0, [two[k].traction for k in loads]), (1, [two[k].traction_y for k in loads]),
                                    (0, [one[k].traction for k in loads]))]
            speed = seconds.mean() / (ours / args.loads)
            print(f"{TAMAAS_SOLVERS[name]:>16} {len(loads):5d} {seconds.sum():9.2f} {seconds.mean():9.3f} "
                  f"{speed:8.1f} {dp:10.2e} {dq[0]:10.2e} {dq[1]:10.2e} {dq[2]:11.2e}")
        print("speed-up: tamaas' seconds per load over roughcontact's (two components, 20 loads) per load")
    if args.save:
        np.savez_compressed(args.save, **saved)
    return 0


if __name__ == "__main__":
    sys.exit(main())
