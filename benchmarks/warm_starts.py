"""Warm starts of the normal solver measured: which start cuts the iterations on large grids?

Issue 41 asks for a normal solver whose iterations per load do not grow with the grid and names
three routes; this benchmark measures the starts that the routes differ in, on one seed of the
default sphere of ``benchmarks/large_grid.py`` (R = 0.5 L, H = 0.7, h_rms = 9·10⁻³ L, seed 0,
non-periodic, the 27 loads 10⁻⁷ … 2·10⁻² E*L², tol 10⁻⁸), with today's preconditioned
constrained CG (:func:`roughcontact.bem.solver.polonsky_keer`) as the kernel of every start:

``previous``
    the previous load's pressure, rescaled to the new force (what ``bem.iter_load_path`` does);
``nested``
    nested grids (Bemporad & Paggi, Int. J. Solids Struct. 69–70, 94 (2015)): every load is
    first solved on the grids ``n → (n+1)/2 → …`` (heights sampled on every other node, each
    level warm-started from its own previous load), and the coarse pressure, interpolated
    bilinearly, starts the fine solve; its cost counts the coarse iterations at their share of
    the fine grid's cells (``work``);
``tangent``
    the previous pressure plus a tangent increment: the flat-punch pressure on the previous
    contact set (the stiffness problem ``K_cc p = 1``, three preconditioned CG steps in single
    precision; each costs a convolution, counted in ``work``), scaled to the new force, so that
    the gap on the old contact set starts uniform.

``--trace`` also prints, for the largest load of the ``previous`` start, the contact cells, the
penetrating free cells and the error at each iteration (the phases of a warm-started solve).

Usage::

    python benchmarks/warm_starts.py [--n 513 1025 2049] [--trace]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
from scipy.sparse.linalg import LinearOperator, cg

sys.path.insert(0, str(Path(__file__).resolve().parent))

from large_grid import FORCES, TOL  # noqa: E402
from run import E_STAR, HURST, H_RMS, LENGTH, RADIUS, print_header  # noqa: E402

from roughcontact import surfaces  # noqa: E402
from roughcontact.bem import contact, solver  # noqa: E402
from roughcontact.bem.active_sets import bounding_box  # noqa: E402
from roughcontact.bem.preconditioner import fourier_inverse  # noqa: E402

#: Preconditioned CG steps of the tangent start's flat-punch pressure.
TANGENT_STEPS = 3


def _bound(previous, force):
    """The depth bound of ``bem.iter_load_path``: ``d(F) ≤ d(F₀)·max(1, F/F₀)``."""
    return None if previous is None else previous.depth * max(1.0, force / previous.force)


def _solve(heights, length, force, initial=None, bound=None):
    state = contact._solve(heights, force, length, E_STAR, False, TOL, contact.DEFAULT_MAXITER, initial,
                           bound, False)
    if not state.converged:
        raise RuntimeError(f"n = {heights.shape[0]}: the load {force:g} did not converge")
    return state


def _prolong(coarse: np.ndarray, n: int) -> np.ndarray:
    """Bilinear interpolation of a pressure on the nodes ``0, 2, 4, …`` of an ``n``-grid onto all
    its nodes (zero beyond the last coarse node), C order."""
    def along_rows(values):
        fine = np.zeros((n,) + values.shape[1:])
        fine[::2] = values[: (n + 1) // 2]
        half = n // 2
        right = np.concatenate([values[1:], np.zeros((1,) + values.shape[1:])])[:half]
        fine[1::2] = 0.5 * (values[:half] + right)
        return fine
    return np.ascontiguousarray(along_rows(along_rows(coarse).T).T)


def previous_start(heights, forces):
    states, previous = [], None
    for force in forces:
        previous = _solve(heights, LENGTH, force, None if previous is None else previous.pressure,
                          _bound(previous, force))
        states.append(previous.iterations)
    return states, float(sum(states))


def nested_start(heights, forces, coarsest=129):
    grids = [(heights, LENGTH)]
    while (grids[-1][0].shape[0] + 1) // 2 >= coarsest:
        fine, length = grids[-1]
        coarse = fine[::2, ::2]
        grids.append((coarse, length / fine.shape[0] * 2 * coarse.shape[0]))
    previous = [None] * len(grids)
    fine_iterations, work = [], 0.0
    for force in forces:
        start = None
        for level in range(len(grids) - 1, -1, -1):
            z, length = grids[level]
            last = previous[level]
            initial = None if last is None else last.pressure
            if start is not None:  # the coarser level's solution starts this one
                initial = _prolong(start, z.shape[0])
            state = _solve(z, length, force, initial, _bound(last, force))
            previous[level] = state
            start = state.pressure
            work += state.iterations * (z.shape[0] / heights.shape[0]) ** 2
        fine_iterations.append(previous[0].iterations)
    return fine_iterations, work


def _tangent(previous, force, operator, n):
    window = bounding_box(previous.contact)
    window = tuple(slice(max(0, s.start - 4), min(n, s.stop + 4)) for s in window)
    footprint = previous.contact[window]
    cells, shape = np.flatnonzero(footprint), footprint.shape
    field = np.zeros(shape)
    inverse = fourier_inverse(operator)

    def product(values):
        field.reshape(-1)[:] = 0.0
        field.reshape(-1)[cells] = values
        return operator.single(field).reshape(-1)[cells]

    system = LinearOperator((cells.size,) * 2, matvec=product, dtype=float)
    preconditioner = LinearOperator((cells.size,) * 2, dtype=float,
                                    matvec=lambda v: inverse(shape, cells, v, deflate=False))
    punch, _ = cg(system, np.ones(cells.size), M=preconditioner, maxiter=TANGENT_STEPS, rtol=1e-12)
    increment = np.zeros(shape)
    increment.reshape(-1)[cells] = np.maximum(punch, 0.0)
    pressure = previous.pressure.copy()
    total = force / (LENGTH / n) ** 2
    pressure[window] += increment * (total - pressure.sum()) / increment.sum()
    return pressure


def tangent_start(heights, forces):
    n = heights.shape[0]
    operator = contact.operator_for(n, LENGTH, E_STAR, False)
    previous, iterations, work = None, [], 0.0
    for force in forces:
        start = None
        if previous is not None:
            start = _tangent(previous, force, operator, n)
            work += TANGENT_STEPS
        previous = _solve(heights, LENGTH, force, start, _bound(previous, force))
        iterations.append(previous.iterations)
        work += previous.iterations
    return iterations, work


def trace_largest(heights, forces):
    """Contact cells, penetrating free cells and error per iteration of the largest load."""
    previous = None
    for force in forces[:-1]:
        previous = _solve(heights, LENGTH, force, None if previous is None else previous.pressure,
                          _bound(previous, force))
    rows, original = [], solver._gap_state

    def recording(gap, pressure, support):
        depth, error, below = original(gap, pressure, support)
        rows.append((support.size, below.size, error))
        return depth, error, below

    solver._gap_state = recording
    try:
        _solve(heights, LENGTH, forces[-1], previous.pressure, _bound(previous, forces[-1]))
    finally:
        solver._gap_state = original
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[513, 1025, 2049])
    parser.add_argument("--trace", action="store_true", help="the iterations of the largest load")
    args = parser.parse_args(argv)
    print_header(f"one process; fine-grid "
          f"iterations over all {FORCES[2]} loads (largest load), work in fine-grid convolutions, wall")
    forces = np.geomspace(*FORCES[:2], FORCES[2]) * E_STAR * LENGTH**2
    print(f"{'n':>5} | {'start':>8} | {'iterations':>10} {'largest':>7} {'work':>8} | {'wall s':>7}")
    for n in args.n:
        heights = surfaces.rough_sphere(n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, seed=0)
        for name, method in (("previous", previous_start), ("nested", nested_start), ("tangent", tangent_start)):
            tick = time.perf_counter()
            iterations, work = method(heights, forces)
            print(f"{n:5d} | {name:>8} | {sum(iterations):10d} {max(iterations):7d} {work:8.1f} | "
                  f"{time.perf_counter() - tick:7.1f}", flush=True)
        if args.trace:
            rows = trace_largest(heights, forces)
            print(f"n = {n}, largest load: iteration, contact cells, penetrating free cells, error")
            for i, (cells, below, error) in enumerate(rows):
                print(f"  {i:3d} {cells:8d} {below:8d} {error:9.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
