"""Adhesive load–unload path: roughcontact's cohesive zone against tamaas' Maugis functional.

Builds one seeded rough sphere and a Maugis–Dugdale interaction (``λ = 0.5``; the length
``ℓ = (πwR²/K)^{1/3}`` fixed in units of L, 32 cells at n = 513), and runs the same
displacement-controlled path — approach from ``−0.5`` to ``1`` ``ℓ²/R``, then retract to ``−1``
``ℓ²/R``, past the loss of contact — with :func:`roughcontact.bem.cohesive.cohesive_path` and with
tamaas' Polonsky–Keer–Rey solver plus ``MaugisAdhesionFunctional``
(``benchmarks/peers.py``, :class:`TamaasAdhesionPeer`). tamaas adds adhesion only on the periodic
half-space, so the like-for-like comparison is roughcontact's ``periodic=True`` with the
``"metastable"`` edge rule (the literal Dugdale law, tamaas' functional); the default
``"energy"`` rule and the default free half-space are timed beside it.

Each run is a fresh interpreter (``--worker``), so that its peak memory can be read: the growth
of the peak resident set (``ru_maxrss``) over the resident set just before the call, per grid
cell; the heights (8 B/cell) are loaded before and not counted. ``--tracemalloc`` adds, for this
project's runs, a second call under tracemalloc (numpy and Python allocations only).

Usage::

    python benchmarks/adhesion.py [--n 513] [--loads 40] [--seed 0] [--peer tamaas|none]
                                  [--ours periodic:metastable,periodic:energy,free:energy]
                                  [--lam 0.5] [--ell 0.0625]
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from run import E_STAR, HURST, LENGTH, RADIUS, machine_lines  # noqa: E402

#: Roughness of the sphere: small, so that the adhesive contact is one patch, up to 91 cells across at
#: n = 513 (the rms is mostly that of the longest wavelengths; 0.13 ℓ²/R).
H_RMS = 1e-3
#: Maugis' parameter and length ``ℓ = (πwR²/K)^{1/3}``, ``K = 4E*/3``, in units of L (32 cells at n = 513).
#: The discrete Dugdale law leaves an edge cell two consistent states within ``s_c = K_ii σ₀`` of
#: ``δ_t`` (``roughcontact.bem.cohesive``), and each code picks its own: ``s_c/δ_t`` grows as
#: ``λ² Δx/ℓ``, 7 % of the range at λ = 1, ℓ = 16 cells, where the two codes' pull-offs differed by
#: 4·10⁻³, 0.9 % here (RESULTS.md §7).
LAMBDA = 0.5
ELL = 1.0 / 16
#: The path in units of ``ℓ²/R``: approach from FIRST to TOP (a quarter of the loads), retract to
#: BOTTOM (the rest).
FIRST, TOP, BOTTOM = -0.5, 1.0, -1.0
#: Solver tolerances: roughcontact's gap tolerance (its default); tamaas' own error measure, 1e-8 as in
#: run.py (at 1e-10 it stalls at 1e-10 to 2e-9 on contacts of a few tens of cells, with the same states).
TOL = 1e-10
TAMAAS_TOL = 1e-8


def interaction(length: float = LENGTH, e_star: float = E_STAR, radius: float = RADIUS,
                ell: float = ELL, lam: float = LAMBDA) -> tuple[float, float, float]:
    """``(w, σ₀, ℓ²/R)``: the work of adhesion and cohesive stress of Maugis' ``λ`` at ``ℓ``."""
    from roughcontact.models.adhesion import maugis_cohesive_stress, maugis_work_of_adhesion

    w = maugis_work_of_adhesion(ell * length, radius=radius, e_star=e_star)
    sigma = maugis_cohesive_stress(lam, radius=radius, e_star=e_star, work_of_adhesion=w)
    return w, sigma, (ell * length) ** 2 / radius


def path_depths(loads: int, unit: float) -> np.ndarray:
    """The approaches: a quarter of *loads* from FIRST to TOP, the rest retracting to BOTTOM."""
    up = max(2, loads // 4)
    down = loads - up
    return np.concatenate([np.linspace(FIRST, TOP, up), np.linspace(TOP, BOTTOM, down + 1)[1:]]) * unit


# --------------------------------------------------------------------------------------- worker

def _rss_bytes() -> int:
    import resource

    with open("/proc/self/statm", encoding="ascii") as statm:
        return int(statm.read().split()[1]) * resource.getpagesize()


def _peak_rss_bytes() -> int:
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024


def worker(spec: dict) -> dict:
    """One run in this interpreter: *spec* names the code, mode and files; returns the results."""
    heights = np.load(spec["heights"])
    depths = np.load(spec["depths"])
    n = heights.shape[0]
    w, sigma = spec["work_of_adhesion"], spec["cohesive_stress"]
    if spec["code"] == "tamaas":
        import peers

        before = _rss_bytes()
        start = time.perf_counter()
        peer = peers.TamaasAdhesionPeer(heights, length=LENGTH, e_star=E_STAR, work_of_adhesion=w,
                                        cohesive_stress=sigma, tol=TAMAAS_TOL, max_iter=spec["max_iter"])
        path = peer.path(depths)
        seconds = time.perf_counter() - start
        result = dict(force=path.force, contact_cells=path.contact_cells, zone_cells=path.zone_cells,
                      iterations=path.iterations, converged=path.converged, law_residual=path.law_residual,
                      error=path.error, step_seconds=path.seconds)
    else:
        from roughcontact.bem import operators
        from roughcontact.bem.cohesive import cohesive_path

        counts = {"window": 0, "grid": 0}
        for cls, kind in ((operators.FreeSpaceOperator, "window"), (operators.PeriodicOperator, "grid")):
            def counted(self, pressure, _call=cls.__call__, _kind=kind):
                counts[_kind] += 1
                return _call(self, pressure)
            cls.__call__ = counted

        def run():
            return cohesive_path(heights, depths, length=LENGTH, e_star=E_STAR, work_of_adhesion=w,
                                 cohesive_stress=sigma, periodic=spec["mode"] == "periodic",
                                 edge_rule=spec["rule"], tol=TOL)

        before = _rss_bytes()
        start = time.perf_counter()
        path = run()
        seconds = time.perf_counter() - start
        result = dict(force=path.force, contact_cells=path.contact_cells, zone_cells=path.zone_cells,
                      iterations=path.iterations, fallback=path.fallback)
        result.update(convolutions=dict(counts))
    result = {key: value if isinstance(value, dict) else np.asarray(value).tolist() for key, value in result.items()}
    result.update(seconds=seconds, rss_growth_per_cell=(_peak_rss_bytes() - before) / n**2)
    if spec["code"] != "tamaas" and spec.get("tracemalloc"):
        import tracemalloc

        del path
        tracemalloc.start()
        run()
        result["traced_peak_per_cell"] = tracemalloc.get_traced_memory()[1] / n**2
        tracemalloc.stop()
    return result


def launch(spec: dict) -> dict:
    """Run :func:`worker` on *spec* in a fresh interpreter."""
    done = subprocess.run([sys.executable, __file__, "--worker", json.dumps(spec)], check=True,
                          stdout=subprocess.PIPE, text=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


# ---------------------------------------------------------------------------------------- report

TAMAAS = "tamaas periodic PKR+Maugis"
LIKE = "roughcontact periodic metastable"


def report(runs: dict, depths: np.ndarray, w: float, unit: float, cell: float) -> None:
    """Print the per-approach table and the summary of *runs* (the numbers of :func:`worker`);
    *cell* is one cell's tension ``σ₀Δx²``."""
    scale = math.pi * w * RADIUS
    reference, like = runs.get(TAMAAS), runs.get(LIKE)
    if reference is not None:
        ok = np.asarray(reference["converged"])
        reference_pull = min(f for f, good in zip(reference["force"], ok) if good)
    same = []
    if reference is not None and like is not None:
        same = [reference["contact_cells"][i] == like["contact_cells"][i]
                and reference["zone_cells"][i] == like["zone_cells"][i] for i in range(len(depths))]

    print()
    print("per approach: F/(πwR), contact cells, zone cells" + (
        "; tamaas: its iterations (* = above its tolerance at the cap: not a solution)" if reference else ""))
    header = f"{'d/(ℓ²/R)':>9} |" + "".join(f" {name.replace('roughcontact ', 'ours '):>33} |" for name in runs)
    if same:
        header += f" {'ΔF/|F_po|':>9} {'same n':>6}"
    print(header)
    print("-" * len(header))
    for i, d in enumerate(depths):
        row = f"{d / unit:9.3f} |"
        for name, run in runs.items():
            extra = ""
            if run is reference:
                extra = f"{run['iterations'][i]:d}{'' if run['converged'][i] else '*'}"
            row += (f" {run['force'][i] / scale:+9.5f} {run['contact_cells'][i]:6d} "
                    f"{run['zone_cells'][i]:5d} {extra:>7} |")
        if same:
            difference = ((reference["force"][i] - like["force"][i]) / abs(min(like["force"]))
                          if reference["converged"][i] else math.nan)
            row += f" {difference:+9.1e} {'yes' if same[i] else 'no':>6}"
        print(row)
    print("-" * len(header))
    if same:
        print("ΔF: tamaas − ours periodic metastable, over |pull-off|; same n: the same contact and zone "
              "cell counts")

    print()
    summary = (f"{'code':<34} {'loads':>5} {'wall s':>8} {'s/load':>7} {'iterations':>18} "
               f"{'pull-off F':>12} {'F/(πwR)':>8} {'ΔF/F tamaas':>11} {'B/cell':>6}")
    print(summary)
    print("-" * len(summary))
    for name, run in runs.items():
        if run is reference:
            pull = reference_pull
            counted = f"{sum(run['iterations']):d} PKR"
        else:
            pull = min(run["force"])
            counted = f"{sum(run['iterations']):d} S / {sum(run['convolutions'].values()):d} conv"
        difference = (f"{pull / reference_pull - 1:+11.2e}" if reference is not None and run is not reference
                      else f"{'':>11}")
        print(f"{name:<34} {len(run['force']):5d} {run['seconds']:8.2f} {run['seconds'] / len(run['force']):7.3f} "
              f"{counted:>18} {pull:12.5e} {pull / scale:8.4f} {difference} {run['rss_growth_per_cell']:6.1f}")
    print("-" * len(summary))
    print("iterations: tamaas' Polonsky–Keer–Rey iterations (one grid-sized convolution each); "
          "roughcontact's updates of the zone S (one constrained-CG contact solve each) / its "
          "convolutions (FFT on windows, or on the grid). B/cell: peak memory, the growth of ru_maxrss "
          "over the RSS just before the call, per cell (the heights, 8 B/cell, not counted).")
    if reference is not None:
        print("tamaas' pull-off: over the approaches where it converged.")
    for name, run in runs.items():
        notes = []
        if "traced_peak_per_cell" in run:
            notes.append(f"tracemalloc peak {run['traced_peak_per_cell']:.1f} B/cell")
        if "convolutions" in run:
            notes.append(f"convolutions {run['convolutions']['window']} on windows, {run['convolutions']['grid']} "
                         f"on the grid")
        if any(run.get("fallback", [])):
            notes.append(f"{sum(run['fallback'])} approaches settled by the metastable fallback")
        if notes:
            print(f"{name}: " + "; ".join(notes))
    if reference is None:
        return
    capped = [i for i, good in enumerate(ok) if not good]
    kept = sum(s for s, good in zip(reference["step_seconds"], ok) if good)
    residual = max(r for r, good in zip(reference["law_residual"], ok) if good)
    print(f"tamaas: {len(capped)} of {len(ok)} approaches above its tolerance at the cap (approaches "
          f"{capped}; {sum(reference['step_seconds']) - kept:.1f} s); {kept:.1f} s on the others, whose states "
          f"satisfy the Dugdale law to {residual:.1e} σ₀")
    for name, run in runs.items():
        if run is not reference:
            print(f"time ratio tamaas / {name}: {reference['seconds'] / run['seconds']:.1f} "
                  f"(tamaas without its capped approaches: {kept / run['seconds']:.1f})")
    if same:
        matched = [i for i in range(len(depths)) if same[i] and ok[i] and like["force"][i] != 0.0]
        agreement = max((abs(reference["force"][i] / like["force"][i] - 1) for i in matched), default=math.nan)
        apart = max(abs(reference["force"][i] - like["force"][i]) / cell for i in range(len(depths)) if ok[i])
        print(f"tamaas and ours periodic metastable: the same contact and zone cell counts at {sum(same)} of "
              f"{len(depths)} approaches, where the forces agree to {agreement:.1e} (converged, attached ones); "
              f"elsewhere within {apart:.1f} cells' tension σ₀Δx²")


# ------------------------------------------------------------------------------------------ main

def parse_ours(text: str) -> list[tuple[str, str]]:
    """``"periodic:metastable,free:energy"`` → ``[("periodic", "metastable"), ("free", "energy")]``."""
    runs = []
    for item in filter(None, (part.strip() for part in text.split(","))):
        mode, _, rule = item.partition(":")
        if mode not in ("periodic", "free") or rule not in ("metastable", "energy"):
            raise argparse.ArgumentTypeError(f"bad run {item!r}: use periodic|free:metastable|energy")
        runs.append((mode, rule))
    return runs


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=513, help="grid points per side (default 513)")
    parser.add_argument("--loads", type=int, default=40, help="approaches of the path (default 40)")
    parser.add_argument("--seed", type=int, default=0, help="roughness seed (default 0)")
    parser.add_argument("--peer", choices=("tamaas", "none"), default="tamaas", help="peer (default tamaas)")
    parser.add_argument("--ours", type=parse_ours,
                        default=parse_ours("periodic:metastable,periodic:energy,free:energy"),
                        help="this project's runs, mode:edge_rule, comma-separated "
                             "(default periodic:metastable,periodic:energy,free:energy)")
    parser.add_argument("--lam", type=float, default=LAMBDA, help=f"Maugis' parameter λ (default {LAMBDA:g})")
    parser.add_argument("--ell", type=float, default=ELL,
                        help=f"Maugis' length ℓ = (πwR²/K)^(1/3) in units of L (default {ELL:g})")
    parser.add_argument("--max-iter", type=int, default=2000,
                        help="tamaas' iteration cap per approach (default 2000)")
    parser.add_argument("--tracemalloc", action="store_true",
                        help="also the tracemalloc peak of this project's runs (a second call each)")
    parser.add_argument("--json", help="also write every run's numbers to this file")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        print(json.dumps(worker(json.loads(args.worker))))
        return 0

    from roughcontact import surfaces

    w, sigma, unit = interaction(ell=args.ell, lam=args.lam)
    depths = path_depths(args.loads, unit)
    heights = surfaces.rough_sphere(args.n, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH,
                                    seed=args.seed)
    spacing = LENGTH / args.n
    for line in machine_lines(["tamaas"] if args.peer == "tamaas" else []):
        print(line)
    print(f"problem: n={args.n}, L={LENGTH:g}, R={RADIUS:g}, H={HURST:g}, h_rms={H_RMS:g}, E*={E_STAR:g}, "
          f"seed={args.seed}; Maugis λ={args.lam:g}, ℓ={args.ell * LENGTH:.5g} "
          f"({args.ell * LENGTH / spacing:.1f} cells), "
          f"w={w:.4g}, σ₀={sigma:.4g}, δ_t=w/σ₀={w / sigma:.4g} ({w / sigma / unit:.3f} ℓ²/R); "
          f"{depths.size} approaches {FIRST:g} → {TOP:g} → {BOTTOM:g} ℓ²/R (ℓ²/R = {unit:.4g})")
    print(f"tolerances: roughcontact gap tol {TOL:g}; tamaas PKR tol {TAMAAS_TOL:g} (its error measure), "
          f"cap {args.max_iter} iterations per approach")
    print("note: wall times on a shared machine; every run in a fresh interpreter, one after the other", flush=True)

    runs = {}
    with tempfile.TemporaryDirectory() as scratch:
        files = {"heights": str(Path(scratch) / "heights.npy"), "depths": str(Path(scratch) / "depths.npy")}
        np.save(files["heights"], heights)
        np.save(files["depths"], depths)
        del heights
        base = dict(files, work_of_adhesion=w, cohesive_stress=sigma)
        for mode, rule in args.ours:
            label = f"roughcontact {mode} {rule}"
            print(f"running {label} ...", file=sys.stderr, flush=True)
            runs[label] = launch(dict(base, code="roughcontact", mode=mode, rule=rule,
                                      tracemalloc=args.tracemalloc))
        if args.peer == "tamaas":
            label = "tamaas periodic PKR+Maugis"
            print(f"running {label} ...", file=sys.stderr, flush=True)
            runs[label] = launch(dict(base, code="tamaas", max_iter=args.max_iter))

    if args.json:
        Path(args.json).write_text(json.dumps(dict(n=args.n, depths=depths.tolist(), work_of_adhesion=w,
                                                   cohesive_stress=sigma, unit=unit, runs=runs)))
    report(runs, depths, w, unit, sigma * spacing**2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
