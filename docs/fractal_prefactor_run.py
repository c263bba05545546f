"""Run the measurements of ``docs/make_fractal_prefactor.py`` (one case at a time, appended).

    PYTHONPATH=src nice -n 10 python docs/fractal_prefactor_run.py OUT.csv [CASE ...] [--grids 2048]
        [--seeds 12:48] [--summits]

Writes one row per (case, seed, grid, load) (:data:`fractal_prefactor_measure.COLUMNS`); a case
already in OUT.csv is skipped, so an interrupted run resumes. ``--grids``/``--seeds`` choose the
grids and seeds (more seeds on the finest grid alone, once the ladder has shown the branch's
loads converged); ``--summits`` writes instead one row per (case, seed): where the body first
touches on the finest grid and how high the roughness stands there (no contact solve).
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fractal_prefactor_measure import COLUMNS, measure, summit  # noqa: E402

from roughcontact.models import paper  # noqa: E402
from roughcontact.models.zeta_law import zeta_law  # noqa: E402

GRIDS = (512, 1024, 2048)
SEEDS = tuple(range(12))
LOADS = 12
#: largest load (E* L²): the fractal branch lies far below it, and it keeps the 2048² contacts small
F_CAP = 2e-4
BASE = dict(hurst=0.7, radius=0.5, h_rms=9e-3, period=1.0, rolloff=None)
CASES = {"base": {}}
CASES.update({f"H{h}": dict(hurst=h) for h in (0.3, 0.4, 0.5, 0.6, 0.8, 0.9)})
CASES.update({f"R{r}": dict(radius=r) for r in (0.1, 0.2, 1.0, 2.0, 4.0)})
CASES.update({f"h{h:g}": dict(h_rms=h) for h in (3e-3, 2.7e-2, 8.1e-2)})
CASES.update({f"P{p:g}": dict(period=p) for p in (0.5, 0.25)})
#: a roll-off (plateau below 2π/λ_r) with the power law's amplitude kept (:func:`rolloff_h_rms`)
CASES.update({f"r{r:g}": dict(rolloff=r) for r in (0.5, 0.25)})
#: nominally flat surfaces (periodic), the same spectra and grids: the flat ζ(H) these spheres compare with
CASES.update({f"flatH{h}": dict(hurst=h, radius=float("inf")) for h in (0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)})
#: the flat surfaces' loads (E* L²): the range of the spheres' fractal branches
FLAT_FORCES = np.geomspace(1e-6, 1e-4, 7)


def rolloff_h_rms(h_rms: float, hurst: float, rolloff: float, n: int = max(GRIDS)) -> float:
    """The rms height of the spectrum with a plateau below ``q_r = 2π/rolloff`` whose power law
    ``q^(−2H−2)`` above ``q_r`` is that of the pure self-affine spectrum of rms *h_rms* (L = 1),
    summed over the n-grid's modes (:func:`roughcontact.surfaces.self_affine`)."""
    k = np.fft.fftfreq(n, 1.0 / n)
    q = np.hypot(k[:, None], k[None, :])
    q[0, 0] = np.inf
    pure = q ** (-2.0 - 2.0 * hurst)
    flat = np.where(q < 1.0 / rolloff, (1.0 / rolloff) ** (-2.0 - 2.0 * hurst), pure)
    return h_rms * float(np.sqrt(flat.sum() / pure.sum()))


def case_parameters(name: str) -> dict:
    params = {**BASE, **CASES[name]}
    if params["rolloff"] is not None:
        params["h_rms"] = rolloff_h_rms(params["h_rms"], params["hurst"], params["rolloff"])
    return params


def case_forces(params: dict) -> np.ndarray:
    """Loads from 3·10⁻⁴ F_tr to min(F_tr, F_CAP), F_tr of eq. 17 with the flat ζ law
    (:data:`FLAT_FORCES` for a flat surface; for a roll-off, those of the base case's h_rms)."""
    if np.isinf(params["radius"]):
        return FLAT_FORCES
    # a roll-off keeps the power law's amplitude: the loads of the surface without it
    h_rms = BASE["h_rms"] if params["rolloff"] is not None else params["h_rms"]
    f_tr = float(paper.crossover_force(params["radius"], hurst=params["hurst"], h_rms=h_rms,
                                       length=1.0, e_star=1.0, zeta=float(zeta_law(params["hurst"]))))
    top = min(f_tr, F_CAP)
    return np.geomspace(3e-4 * f_tr, top, LOADS)


def main(out: str, names, grids=GRIDS, seeds=SEEDS, summits: bool = False) -> None:
    path = Path(out)
    done = set(pd.read_csv(path)["case"]) if path.exists() else set()
    for name in names or CASES:
        if name in done:
            continue
        params = case_parameters(name)
        forces = case_forces(params)
        start = time.time()
        rows = []
        for seed in seeds:
            if summits:
                rows.append(dict(case=name, **summit(seed=seed, n=max(grids), **params)))
            else:
                rows += measure(name, forces=forces, grids=grids, seed=seed, **params)
        frame = pd.DataFrame(rows, columns=None if summits else COLUMNS)
        frame.to_csv(path, mode="a", header=not path.exists(), index=False, float_format="%.6g")
        print(f"{name}: {time.time() - start:.1f} s", flush=True)


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser()
    parser.add_argument("out")
    parser.add_argument("cases", nargs="*")
    parser.add_argument("--grids", type=int, nargs="+", default=list(GRIDS))
    parser.add_argument("--seeds", default=f"{SEEDS[0]}:{SEEDS[-1] + 1}", help="first:stop")
    parser.add_argument("--summits", action="store_true")
    args = parser.parse_args()
    first, stop = (int(v) for v in args.seeds.split(":"))
    main(args.out, args.cases, grids=tuple(args.grids), seeds=tuple(range(first, stop)), summits=args.summits)
