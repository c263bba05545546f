"""Every sweep the schema accepts runs to a report (issue 40): small sweeps drawn from the schema's
space, and presets shrunk, through the real ``snakemake`` on grids of at most 65².

:func:`test_drawn_sweeps_run_to_a_report` draws sweeps with hypothesis (sphere only, flat only or
both; one or two seeds; two or five loads per branch, two being about one on each side of the
crossover; the optional axes at one and two values; adhesion, hardness, tangential (poisson,
friction), fields, the grid-error companions (grid.coarse by default, grid.fine, none)); its five
explicit examples (the zoo: flat only with one seed and a scan, one load per branch with adhesion,
sphere and flat with hardness, cones and a roll-off, tangential with a cutoff, a sphere with one
seed) take every one of these, and a measured scan, through the workflow at least once,
the drawn ones (``ROUGHCONTACT_SWEEP_EXAMPLES``, default 1) add combinations, derandomized (the same
sweeps on every machine). :func:`test_preset_runs_to_a_report` runs the presets of :data:`PRESETS`
shrunk by :func:`shrink` (one per shape the examples do not take; ``ROUGHCONTACT_ALL_PRESETS=1``:
every preset, about 40 s each). Each run must end in ``results/summary.html`` (with generated
surfaces) and the report's landing page (``snakemake --report``) with every table readable (a
table without a row: its header, and why in its sidecar, :func:`roughcontact.study.files.io.read_csv`)
and the truth of what its landing page says (``tests/report_truth.py``: no verdict on a point
interval, tallies and counts that are the tables', the grid error as its table states it, the
recommended models' holds as models.csv's), or stop before its first solve with one line naming the key. About 40 s per sweep on 2 busy cores.
"""
from __future__ import annotations

import copy
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from report_truth import check_report_truth  # noqa: E402
from roughcontact.study.config import axes, load_config, resolve_config  # noqa: E402
from roughcontact.study.files import io as study_io  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
INF = math.inf
SHARED = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES", ROOT.parent / "shared" / "topographies"))


# --------------------------------------------------------------------------
# running a sweep
# --------------------------------------------------------------------------
def _snakemake(work: Path, *args, timeout=600):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    return subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), *args], cwd=work,
                          capture_output=True, text=True, timeout=timeout, env=env)


def run_to_report(cfg: dict, work: Path) -> str:
    """Run *cfg* in *work* and its report; assert it ends in a report with readable tables, or stops
    before its first solve with one line naming the key. The outcome: ``"report"`` or ``"refused"``."""
    work.mkdir(parents=True, exist_ok=True)
    (work / "cfg.yaml").write_text(yaml.safe_dump(cfg, sort_keys=False))
    proc = _snakemake(work, "--configfile", "cfg.yaml", "--cores", "2")
    out = proc.stdout + proc.stderr
    cfg_text = yaml.safe_dump(cfg, sort_keys=False)
    if proc.returncode != 0:
        refused = [line for line in out.splitlines() if line.startswith("Invalid configuration")]
        assert refused and not (work / "results" / "runs").exists(), (
            f"the sweep crashed:\n{cfg_text}\n{out[-4000:]}")
        assert "config key" in refused[0], refused[0]
        return "refused"
    assert "Traceback" not in out, f"{cfg_text}\n{out[-4000:]}"
    summary = work / "results" / "summary.html"
    if cfg.get("hurst"):   # a study of measured scans only has no summary (its pages are the scans')
        assert summary.is_file() and summary.stat().st_size > 100, f"no landing fragment:\n{cfg_text}"
    for csv in sorted((work / "results").rglob("*.csv")):
        assert csv.stat().st_size > 1, f"{csv.relative_to(work)} is {csv.stat().st_size} byte(s):\n{cfg_text}"
        table = study_io.read_csv(csv)
        assert len(table.columns), f"{csv.relative_to(work)} has no header"
        if not len(table) and not csv.name.endswith(".reason.csv"):
            assert table.attrs[study_io.REASON] != study_io.NO_ROW, f"{csv.relative_to(work)}: empty, no reason"
    report = _snakemake(work, "--configfile", "cfg.yaml", "--report", "results/report.html")
    assert report.returncode == 0, f"{cfg_text}\n{(report.stdout + report.stderr)[-4000:]}"
    assert (work / "results" / "report.html").stat().st_size > 1000
    # truth as a property: what the pages say is what the tables hold (tests/report_truth.py)
    resolved = resolve_config(load_config(work / "cfg.yaml"), base_dir=work)
    check_report_truth(work, coarse=resolved.get("grid", {}).get("coarse"))
    return "report"


# --------------------------------------------------------------------------
# a table without a row
# --------------------------------------------------------------------------
def test_a_table_without_a_row_is_its_header_and_why(tmp_path):
    """files.io.write_csv: no row -> the header (pandas reads an empty table with the columns) and
    the reason beside it; rows again -> the reason is gone; an older one-byte table reads empty."""
    import pandas as pd

    path = tmp_path / "crossover.csv"
    study_io.write_csv(pd.DataFrame(), path, columns=("hurst", "Ftr_measured"), reason="the sweep has no sphere")
    table = pd.read_csv(path)
    assert list(table.columns) == ["hurst", "Ftr_measured"] and len(table) == 0
    assert study_io.read_csv(path).attrs[study_io.REASON] == "the sweep has no sphere"
    assert study_io.empty_reason(path) == "the sweep has no sphere"
    study_io.write_csv(pd.DataFrame({"hurst": [0.7], "Ftr_measured": [1e-4]}), path, reason="unused")
    assert len(study_io.read_csv(path)) == 1 and study_io.empty_reason(path) is None
    assert not Path(study_io.reason_path(path)).exists()
    old = tmp_path / "models.csv"
    old.write_text("\n")
    assert study_io.read_csv(old).empty and study_io.read_csv(old).attrs[study_io.REASON] == study_io.NO_ROW


def test_no_sphere_tables_have_their_columns():
    """crossover.csv and models.csv of a sweep without a sphere: the sweep axes and the tables' columns."""
    import pandas as pd

    from roughcontact.study.analysis import crossover, scorecard
    from roughcontact.study.config import resolve
    from roughcontact.study.runs import naming as runs

    cfg = resolve.resolve_config(_base("flat"))
    cross, reps = crossover.crossover_table({}, pd.DataFrame(), cfg)
    assert list(cross.columns) == [*runs.AXES["sphere"], *crossover.CROSSOVER_COLUMNS] and not len(cross)
    models, curves = scorecard.scorecard({}, pd.DataFrame(), cfg)
    assert {"model", "combination", "max_rel_dev", *runs.AXES["sphere"]} <= set(models.columns) and not curves
    assert "no sphere" in scorecard.empty_reason(cfg)


# --------------------------------------------------------------------------
# the drawn sweeps
# --------------------------------------------------------------------------
FIT = {"resolved_cells": 4, "bootstrap": 50}


def _base(shape="sphere", *, n=33, seeds=2, count=5, hurst=(0.7,), h_rms=(0.01,)) -> dict:
    radius = {"sphere": [0.5], "flat": [INF], "both": [0.5, INF]}[shape]
    return {"grid": {"n": n, "length": 1.0}, "e_star": 1.0, "hurst": list(hurst), "radius": radius,
            "h_rms": list(h_rms), "seeds": seeds,
            "forces": {"sphere": {"from": 1e-5, "to": 1e-2, "count": count},
                       "flat": {"from": 1e-4, "to": 3e-3, "count": count}},
            "fit": copy.deepcopy(FIT)}


#: one or two values of each optional axis
OPTIONAL = {"exponent": ([1.0], [1.0, 2.0]), "rolloff": ([0.5], [None, 0.5]), "cutoff": ([0.125], [None, 0.125])}

#: what a feature adds to a sweep with a sphere
FEATURES = {
    "adhesion": {"work_of_adhesion": [1.0e-3], "forces": {"sphere": {"from": 1e-4, "to": 1.6e-2}}},
    "hardness": {"hardness": [None, 0.2]},
    "tangential": {"poisson": [0.3], "friction": [0.5], "tangential": {"steps": 3}},
    "fields": {"fields": {"patches": True, "at": [1e-3]}},
    "fine": {"grid": {"fine": 65}},
    "no coarse": {"grid": {"coarse": None}},
}


def _merge(a: dict, b: dict) -> dict:
    out = copy.deepcopy(a)
    for key, value in b.items():
        out[key] = _merge(out[key], value) if isinstance(value, dict) and isinstance(out.get(key), dict) else value
    return out


@st.composite
def sweeps(draw):
    """A small sweep of the schema's space (module docstring)."""
    shape = draw(st.sampled_from(["sphere", "flat", "both"]))
    cfg = _base(shape, n=draw(st.sampled_from([33, 65])), seeds=draw(st.sampled_from([1, 2])),
                count=draw(st.sampled_from([2, 5])), hurst=draw(st.sampled_from([(0.7,), (0.5, 0.8)])),
                h_rms=draw(st.sampled_from([(0.01,), (0.005, 0.02)])))
    for name in draw(st.sets(st.sampled_from(sorted(OPTIONAL)), max_size=2)):
        cfg[name] = draw(st.sampled_from(OPTIONAL[name]))
    if shape != "flat":
        chosen = draw(st.sets(st.sampled_from(sorted(FEATURES)), max_size=2))
        if {"adhesion", "fields"} <= chosen:   # refused: an adhesive run keeps its retract path instead
            chosen.discard("fields")
        for name in chosen:
            if name == "fine" and cfg["grid"]["n"] > 33:
                continue
            cfg = _merge(cfg, FEATURES[name])
    return cfg


def _with(cfg, *names, **keys):
    for name in names:
        cfg = _merge(cfg, FEATURES[name])
    return _merge(cfg, keys)


def _measured_scan(directory: Path) -> Path | None:
    """A 64² synthetic scan of 0.1 µm pixels (SurfaceTopography's NetCDF), or ``None`` without
    SurfaceTopography."""
    try:
        import SurfaceTopography as ST
    except ImportError:
        return None
    from roughcontact import surfaces

    path = directory / "scan.nc"
    if not path.exists():
        h = surfaces.self_affine(64, hurst=0.8, h_rms=0.01, length=6.4, seed=3)
        ST.Topography(h, (6.4, 6.4), unit="µm").to_netcdf(str(path))
    return path


#: a measured scan beside the generated surfaces (lengths in µm, E* in GPa; forces F/(E* L^2)):
#: its tiles of 32² pressed by the flat, its spectrum fitted, its scorecard
MEASURED = {"units": {"length": "um", "e_star": "GPa"}, "e_star": 100.0, "tile": 32,
            "fit": {"spectrum": {"band": [1.6, 0.25]}}}

EXAMPLES = [
    _merge(_base("flat", seeds=1, hurst=(0.5, 0.8)), MEASURED),            # flat only, one seed, a scan
    _with(_base("sphere", seeds=1, count=2, n=65), "adhesion"),             # one load per branch
    _with(_base("both"), "hardness", "fine", "fields", exponent=[1.0, 2.0], rolloff=[0.5]),
    _with(_base("sphere"), "tangential", cutoff=[None, 0.125], h_rms=[0.005, 0.02]),
    _base("sphere", seeds=1),                                                # one seed: no verdict at all
]

#: drawn sweeps beyond the explicit examples (each about 40 s on 2 busy cores)
DRAWN = int(os.environ.get("ROUGHCONTACT_SWEEP_EXAMPLES", "1"))


@pytest.mark.workflow
@settings(max_examples=DRAWN, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture,
                                 HealthCheck.data_too_large])
@given(cfg=sweeps())
@example(cfg=EXAMPLES[0])
@example(cfg=EXAMPLES[1])
@example(cfg=EXAMPLES[2])
@example(cfg=EXAMPLES[3])
@example(cfg=EXAMPLES[4])
def test_drawn_sweeps_run_to_a_report(tmp_path_factory, cfg):
    work = tmp_path_factory.mktemp("sweep")
    if "units" in cfg:   # the measured scan: where SurfaceTopography is installed, else without it
        scan = _measured_scan(work)
        cfg = _merge(cfg, {"topography": [{"file": str(scan)}]}) if scan else {
            k: v for k, v in cfg.items() if k not in MEASURED} | {"e_star": 1.0}
    # a drawn sweep may be one the schema accepts and the checks beyond it refuse; an example may not
    assert run_to_report(cfg, work) in (("report",) if cfg in EXAMPLES or "units" in cfg else ("report", "refused"))


# --------------------------------------------------------------------------
# the presets, shrunk
# --------------------------------------------------------------------------
#: the grid of a shrunk preset and its companions
SMALL = {"n": 33, "coarse": 17, "fine": 65, "realization_of": 65}


def shrink(cfg: dict, base_dir: Path) -> dict:
    """*cfg* (a preset) at a size for a test: 33² (65² where a cutoff needs it; its companions 17² and
    65², the surfaces of 65² where it presses another grid's), two seeds, at most two values per axis (a sphere and the flat
    surface where it has both), at most four loads per branch, 50 bootstrap resamples; the
    stickiness section on 64² with two seeds; its scans' paths absolute."""
    cfg = copy.deepcopy(cfg)
    grid = cfg.setdefault("grid", {}) if "topography" not in cfg else cfg.get("grid", {})
    if "topography" not in cfg:
        # 33², or 65² where a cutoff is shorter than 2 cells of 33² (the shortest wavelength a grid holds)
        length = float(grid.get("length", 1.0))
        cutoffs = [float(c) for c in cfg.get("cutoff") or [] if c is not None]
        grid["n"] = SMALL["n"] if all(c >= 2 * length / SMALL["n"] for c in cutoffs) else SMALL["fine"]
        for key in ("coarse", "fine", "realization_of"):
            if grid.get(key) is not None:
                grid[key] = SMALL[key]
    if "seeds" in cfg:
        cfg["seeds"] = cfg["seeds"][:2] if isinstance(cfg["seeds"], list) else min(int(cfg["seeds"]), 2)
    for name in axes.AXES:
        values = cfg.get(name)
        if isinstance(values, list) and len(values) > 2:
            if name == "radius":
                finite = [v for v in values if math.isfinite(float(v))]
                flat = [v for v in values if not math.isfinite(float(v))]
                values = finite[:1] + flat[:1]
            cfg[name] = values[:2]
    for rng in cfg.get("forces", {}).values():
        rng["count"] = min(int(rng["count"]), 4)
    fit = cfg.setdefault("fit", {})
    fit["bootstrap"] = min(int(fit.get("bootstrap", 1000)), 50)
    if "topography" not in cfg:
        fit["resolved_cells"] = min(int(fit.get("resolved_cells", 20)), 4)
    if "tangential" in cfg:
        tangential = cfg["tangential"]
        if isinstance(tangential.get("at"), list):
            tangential["at"] = tangential["at"][:2]
        tangential["steps"] = 3
    if "stickiness" in cfg:
        sticky = cfg["stickiness"]
        sticky.update(n=64, seeds=2, steps=8)
        sticky["hurst"], sticky["number"] = sticky["hurst"][:1], sticky["number"][:2]
    for entry in cfg.get("topography", []):
        if isinstance(entry, dict) and "file" in entry:
            entry["file"] = str(_scan_file(base_dir, entry["file"]))
    return cfg


def _scan_file(base_dir: Path, name: str) -> Path:
    """A preset's scan: beside the preset as it names it, else in ``ROUGHCONTACT_TOPOGRAPHIES``
    (a worktree of the repository is not beside ``shared/``)."""
    here = (base_dir / name).resolve()
    return here if here.is_file() else SHARED / Path(name).name


def _shape(cfg: dict) -> tuple:
    """What a preset sweeps, beyond sizes: its keys, the grid companions it names, sphere and flat."""
    grid = cfg.get("grid") or {}
    radius = [float(r) for r in cfg.get("radius", [])]
    return (tuple(sorted(k for k in cfg if k not in ("grid", "seeds", "e_star", "solver", "fit", "forces"))),
            tuple(sorted(k for k in ("coarse", "fine", "realization_of") if grid.get(k) is not None)),
            any(map(math.isfinite, radius)), any(map(math.isinf, radius)))


#: the presets run by default, one per shape (:func:`_shape`) that the drawn sweeps' examples do not
#: already take through the workflow: the other shapes are a sphere and/or flat sweep without
#: companions (calibration, convergence, crossover, paper, tiny, validation, zeta-law: the examples,
#: and tiny in test_pipeline.py), hardness (plastic), the optional axes (generality, finite-size) and
#: the coarse companion alone (heldout: every drawn sweep's default grid.coarse)
PRESETS = ("zeta",                      # the issue's own: flat only
           "adhesion",                  # adhesion and the stickiness section
           "tangential",                # the partial-slip paths at tangential.at
           "measured",                  # the real scan of ../shared/topographies, no generated surface
           "heldout-branches-a",        # grid.coarse and grid.fine
           "grid-error-validation")     # grid.realization_of


def _presets() -> list[Path]:
    every = sorted((ROOT / "presets").glob("*.yaml"))
    if os.environ.get("ROUGHCONTACT_ALL_PRESETS", "") not in ("", "0"):
        return every
    return [ROOT / "presets" / f"{name}.yaml" for name in PRESETS]


def test_the_presets_run_by_default_cover_a_shape_each():
    """Every preset named in :data:`PRESETS` exists and has a shape of its own."""
    shapes = [_shape(yaml.safe_load(path.read_text())) for path in _presets()[:len(PRESETS)]]
    assert len(set(shapes)) == len(PRESETS)


@pytest.mark.workflow
@pytest.mark.parametrize("preset", _presets(), ids=lambda p: p.stem)
def test_preset_runs_to_a_report(tmp_path, preset):
    cfg = yaml.safe_load(preset.read_text())
    if "topography" in cfg:
        missing = [e["file"] for e in cfg["topography"] if not _scan_file(preset.parent, e["file"]).is_file()]
        if missing:
            pytest.skip(f"{preset.name}: its scan {missing[0]} is not here (ROUGHCONTACT_TOPOGRAPHIES)")
        pytest.importorskip("SurfaceTopography")
    assert run_to_report(shrink(cfg, preset.parent), tmp_path / preset.stem) == "report"
