"""Every preset's load paths converge at a reduced size.

For ``config.yaml`` and every YAML in ``presets/``: the configuration read and resolved by the
package's own loader (:func:`roughcontact.study.config.resolve.load_config`,
:func:`~roughcontact.study.config.resolve.study_settings`) with the grid reduced to the smallest of
:data:`GRIDS` that the preset's checks accept (65 unless, e.g., a cutoff of L/64 needs two cells:
129), its grid-error companions reduced alike (``grid.coarse`` to ``(n + 1)/2``, ``grid.fine`` to
``2n − 1``), and everything else as the preset has it. Then the sweep's first combination
(:func:`roughcontact.study.runs.naming.combinations`) at its first two seeds, and, so that every
kernel a preset selects is pressed, the first combination of every other surface kind and of every
value of the axes that select a kernel (:data:`KERNEL_AXES`: ``hardness``, ``work_of_adhesion``,
``poisson``, ``friction``; e.g. each hardness of ``presets/plastic.yaml`` on the sphere and on the
flat surface), each through what the pipeline's ``indent`` job runs
(:func:`roughcontact.study.runs.indent.compute_run`: the warm-started load path, an adhesive run's
loading and retract, the tangential stiffness and partial-slip paths), which raises
:class:`~roughcontact.errors.IndentError` at the first load that does not converge; the test also
reads its ``converged`` column. The companions' first combination the same way. A measured preset
runs its first tile of each scan at each radius through the ``measured_surface`` and
``measured_indent`` jobs' functions (:func:`roughcontact.study.runs.measured.prepare_surface`,
:func:`~roughcontact.study.runs.measured.run_job`) at the preset's own tile (a smaller tile is a
different problem: the sphere's radius in units of the tile grows and the contact reaches its edge);
a scan that is not on this machine skips, naming it. A ``stickiness`` section runs its first job
(:func:`roughcontact.study.runs.stickiness.stickiness_run`, the Maugis–Dugdale path on a flat
surface) on a grid of :data:`STICKINESS_GRID`.
"""
from __future__ import annotations

import copy
import math
import os
from pathlib import Path

import numpy as np
import pytest

from roughcontact.errors import ConfigError
from roughcontact.study.config import axes, resolve
from roughcontact.study.config.companions import coarse_config, default_coarse, fine_config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.config.stickiness import StickinessSettings
from roughcontact.study.runs import indent, jobs, naming

ROOT = Path(__file__).resolve().parents[1]
#: the shared measured scans (a clone of the repository elsewhere is not beside shared/)
SHARED = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES", ROOT.parent / "shared" / "topographies"))
CONFIGS = [ROOT / "config.yaml", *sorted((ROOT / "presets").glob("*.yaml"))]
#: The reduced grids, smallest first: a preset runs on the first its checks accept.
GRIDS = (65, 129, 257)
#: The optional axes whose values select a kernel (or switch one on): each value's first combination runs.
KERNEL_AXES = tuple(name for name in ("hardness", "work_of_adhesion", "poisson", "friction") if name in axes.AXES)
#: Seeds of the sweep's first combination that run (the first ones of the preset's seeds).
FIRST_SEEDS = 2
#: Grid of a stickiness section's first run (its preset's is 512: five octaves of roughness above a
#: cutoff of 16 cells; 64 keeps two).
STICKINESS_GRID = 64


def reduced(path: Path) -> tuple[dict, int]:
    """The resolved configuration of *path* on the smallest of :data:`GRIDS` it accepts, with its
    grid's companions reduced alike, and that grid."""
    raw = resolve.load_config(path)
    for entry in raw.get("topography") or []:   # a scan beside the preset, else in SHARED, else skip
        if isinstance(entry, dict) and "file" in entry:
            here = (path.parent / entry["file"]).resolve()
            there = SHARED / Path(entry["file"]).name
            if not (here.is_file() or there.is_file()):
                pytest.skip(f"{path.name}: the scan {entry['file']} is not on this machine (the shared "
                            "topographies; ROUGHCONTACT_TOPOGRAPHIES)")
            entry["file"] = str(here if here.is_file() else there)
    grid = dict(raw.get("grid") or {})
    full = resolve.resolve_config(copy.deepcopy(raw), base_dir=path.parent)
    refused = []
    for n in GRIDS:
        small = {**grid, "n": n,
                 "coarse": None if full["grid"].get("coarse") is None else default_coarse(n)}
        if full["grid"].get("fine") is not None:
            small["fine"] = 2 * n - 1
        elif "fine" in small:
            small.pop("fine"), small.pop("fine_to", None)
        if small.get("realization_of") is not None:
            small["realization_of"] = max(int(small["realization_of"]), n)
        raw_small = {**copy.deepcopy(raw), "grid": small}
        if isinstance(raw_small.get("stickiness"), dict):
            raw_small["stickiness"] = {**raw_small["stickiness"], "n": STICKINESS_GRID}
        try:
            return resolve.resolve_config(raw_small, base_dir=path.parent), n
        except ConfigError as err:
            refused.append(f"{n}: {err}")
    pytest.fail(f"{path.name}: no reduced grid accepted ({'; '.join(refused)})")


def chosen_runs(study: StudySettings) -> list[dict]:
    """The sweep's first combination at its first :data:`FIRST_SEEDS` seeds, then the first combination
    of every other surface kind and of every value of :data:`KERNEL_AXES` (first seed), once each."""
    combos = naming.combinations(study)
    if not combos:
        return []
    seeds = list(study.seeds)
    runs = [{**combos[0], "seed": seed} for seed in seeds[:FIRST_SEEDS]]
    keys = {("kind", combos[0]["kind"])} | {(name, combos[0].get(name)) for name in KERNEL_AXES}
    for combo in combos[1:]:
        new = {("kind", combo["kind"])} | {(name, combo.get(name)) for name in KERNEL_AXES}
        if not new <= keys:
            runs.append({**combo, "seed": seeds[0]})
            keys |= new
    return runs


def assert_paths_converge(study: StudySettings, what: str) -> int:
    """Run :func:`chosen_runs` of *study* through the indent job's :func:`compute_run`; the number run."""
    runs = chosen_runs(study)
    for run in runs:
        job = jobs.job_settings(study, run)
        out = indent.compute_run(job)      # IndentError at the first load that does not converge
        converged = np.asarray(out["converged"])
        assert converged.size == job.force_count and converged.all(), \
            f"{what}: {job.describe()}: loads {np.flatnonzero(~converged.astype(bool)).tolist()} not converged"
    return len(runs)


@pytest.mark.parametrize("path", CONFIGS, ids=[p.name for p in CONFIGS])
def test_preset_load_paths_converge(path, tmp_path):
    cfg, n = reduced(path)
    study = StudySettings.of(cfg)
    ran = assert_paths_converge(study, f"{path.name} on {n}²")
    if study.grid.coarse is not None and any(math.isfinite(r) for r in study.radius):
        ran += assert_paths_converge(StudySettings.of(coarse_config(cfg)),
                                     f"{path.name}, grid.coarse {study.grid.coarse}²")
    if study.grid.fine is not None:
        ran += assert_paths_converge(StudySettings.of(fine_config(cfg)), f"{path.name}, grid.fine {study.grid.fine}²")
    ran += measured_paths(study, cfg, tmp_path, path.name)
    stickiness = StickinessSettings.of(cfg)
    if stickiness is not None:
        from roughcontact.study.runs.stickiness import stickiness_run

        stickiness_run(stickiness.jobs()[0])     # ConvergenceError where a settle fails
        ran += 1
    assert ran, f"{path.name}: no load path to run"


def measured_paths(study: StudySettings, cfg: dict, tmp_path: Path, name: str) -> int:
    """The first tile of every scan (and the first seed of every spectrum) at every radius, through
    the measured jobs' functions; the number run."""
    from roughcontact.study.runs import measured

    ran = 0
    for entry in study.topography:
        if not os.path.exists(entry.file):
            pytest.skip(f"{name}: the scan {entry.file} is not on this machine (the shared topographies)")
        pytest.importorskip("SurfaceTopography", reason="the measured extra reads the scans")
        surface = tmp_path / f"{entry.name}.nc"
        measured.prepare_surface(entry, surface, length_unit=study.units.length, tile=study.tile)
        for radius in study.radius:
            job = measured.job_of(study, "topography", entry.name, radius, 0)
            out = measured.run_job(job, surface, tmp_path / f"{entry.name}_R{radius:g}.nc")
            assert np.asarray(out["converged"]).all(), f"{name}: {job.describe()} not converged"
            ran += 1
    for entry in study.spectrum:
        for radius in study.radius:
            job = measured.job_of(study, "spectrum", entry.name, radius, 0)
            out = measured.run_job(job, entry.file, tmp_path / f"{entry.name}_R{radius:g}.nc")
            assert np.asarray(out["converged"]).all(), f"{name}: {job.describe()} not converged"
            ran += 1
    return ran
