"""Config validation: every bad config stops with one line naming the key,
before any job runs (config.resolve_config directly, and through snakemake)."""
from __future__ import annotations

import copy
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from roughcontact import cli
from roughcontact import errors
from roughcontact.study.config import resolve as config
from roughcontact.study.runs import naming as runs
from roughcontact.study.config import schema

ROOT = Path(__file__).resolve().parents[1]
TINY = yaml.safe_load((ROOT / "presets/tiny.yaml").read_text())


def _with(path: str, value):
    """TINY with config key *path* ('a.b' or 'a.b=DELETE') set to *value*."""
    cfg = copy.deepcopy(TINY)
    keys = path.split(".")
    node = cfg
    for key in keys[:-1]:
        node = node[key]
    if value is DELETE:
        del node[keys[-1]]
    else:
        node[keys[-1]] = value
    return cfg


DELETE = object()

# (id, config, text the one-line message must contain)
BAD = [
    ("unknown key", {**TINY, "hurts": [0.5]}, "'hurts'"),
    ("unknown nested key", _with("grid.size", 3), "'grid.size'"),
    ("negative radius", _with("radius", [0.5, -1.0]), "radius[1]"),
    ("zero radius", _with("radius", [0.0]), "radius[0]"),
    ("H = 0", _with("hurst", [0.0, 0.5]), "hurst[0]"),
    ("H = 2", _with("hurst", [0.5, 2.0]), "hurst[1]"),
    ("empty seed list", _with("seeds", []), "seeds"),
    ("zero seed count", _with("seeds", 0), "seeds"),
    ("duplicate seeds", _with("seeds", [1, 1]), "seeds"),
    ("sphere from > to", _with("forces.sphere", {"from": 1e-2, "to": 1e-5, "count": 5}), "forces.sphere"),
    ("flat from > to", _with("forces.flat", {"from": 1e-3, "to": 1e-5, "count": 5}), "forces.flat"),
    ("non-positive force", _with("forces.sphere", {"from": 0, "to": 1e-5, "count": 5}), "forces.sphere.from"),
    ("h_rms <= 0", _with("h_rms", [-1e-3]), "h_rms[0]"),
    ("empty H list", _with("hurst", []), "hurst"),
    ("n too small", _with("grid.n", 8), "grid.n"),
    ("n not an integer", _with("grid.n", "many"), "grid.n"),
    ("bad stiffness method", _with("solver.stiffness", "secant"), "solver.stiffness"),
    ("missing hurst", _with("hurst", DELETE), "hurst"),
    ("missing seeds", _with("seeds", DELETE), "seeds"),
    ("flat range near full contact", _with("forces.flat", {"from": 1e-5, "to": 0.5, "count": 5}), "forces.flat.to"),
    ("even slope window", _with("fit.slopes.window", 4), "fit.slopes.window"),
    ("sphere contact beyond the grid", _with("forces.sphere", {"from": 1e-5, "to": 0.2, "count": 5}),
     "forces.sphere.to"),
]


@pytest.mark.parametrize("cfg, needle", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_config_one_line_naming_the_key(cfg, needle):
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config(cfg)
    msg = str(info.value)
    assert "\n" not in msg
    assert needle in msg
    assert "allowed" in msg


def test_good_configs_resolve():
    for path in [ROOT / "config.yaml", *sorted((ROOT / "presets").glob("*.yaml"))]:
        raw = config.load_config(path)
        inputs = [e if isinstance(e, str) else e["file"] for e in raw.get("topography", []) + raw.get("spectrum", [])]
        if not all((path.parent / f).is_file() for f in inputs):
            continue  # a measured preset without ../shared/topographies (tests/test_measured_pipeline.py)
        cfg = config.resolve_config(raw, base_dir=path.parent)  # measured inputs: relative to the preset
        seeds = cfg.get("seeds", [])  # none in a preset of measured scans only
        assert seeds == sorted(set(seeds))
        assert all(isinstance(s, int) for s in seeds)


@pytest.mark.parametrize("preset", sorted(p.name for p in (ROOT / "presets").glob("*.yaml")))
def test_presets_resolve_on_their_own(preset):
    """`snakemake --configfile presets/NAME.yaml` reads the preset over the schema's defaults, not over
    config.yaml (one YAML, one study, with or without --directory): every preset resolves so, and its
    grid-error companion is the one it names, else (n + 1)/2."""
    from roughcontact.study.config.companions import default_coarse

    raw = config.load_config(ROOT / "presets" / preset)
    inputs = [e if isinstance(e, str) else e["file"] for e in raw.get("topography", []) + raw.get("spectrum", [])]
    if not all((ROOT / "presets" / f).is_file() for f in inputs):
        pytest.skip("a measured preset without ../shared/topographies")
    cfg = config.resolve_config(raw, base_dir=ROOT / "presets")
    grid = raw.get("grid") or {}
    own = grid["coarse"] if "coarse" in grid else default_coarse(cfg["grid"]["n"])
    assert cfg["grid"]["coarse"] == own


def test_default_config_sweeps_every_axis():
    cfg = config.resolve_config(config.load_config(ROOT / "config.yaml"))
    for axis in ("hurst", "radius", "h_rms", "seeds"):
        assert len(cfg[axis]) >= 2, axis
    assert any(math.isinf(r) for r in cfg["radius"]) and any(math.isfinite(r) for r in cfg["radius"])


def test_command_line_strings_are_coerced():
    # `--config hurst=[0.5,0.8]` arrives as a string; PyYAML reads 1e-5 as a string
    cfg = _with("hurst", "[0.5, 0.8]")
    cfg["forces"]["sphere"]["from"] = "1e-5"
    cfg["radius"] = ["0.5", "inf"]
    out = config.resolve_config(cfg)
    assert out["hurst"] == [0.5, 0.8] and out["forces"]["sphere"]["from"] == 1e-5
    assert math.isinf(out["radius"][1])


def _snakemake(args, cwd, timeout=120):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    return subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), *args],
                          cwd=cwd, capture_output=True, text=True, timeout=timeout, env=env)


SPEC_BAD = [b for b in BAD if b[0] in ("unknown key", "negative radius", "H = 0", "empty seed list",
                                       "sphere from > to")]


@pytest.mark.parametrize("cfg, needle", [b[1:] for b in SPEC_BAD], ids=[b[0] for b in SPEC_BAD])
def test_snakemake_stops_before_any_job(tmp_path, cfg, needle):
    (tmp_path / "bad.yaml").write_text(yaml.safe_dump(cfg))
    proc = _snakemake(["--configfile", "bad.yaml", "--cores", "1"], tmp_path)
    assert proc.returncode != 0
    lines = [l for l in proc.stderr.splitlines() if "Invalid configuration" in l]
    assert len(lines) == 1 and needle in lines[0], proc.stderr
    assert not (tmp_path / "results").exists()
    assert not (tmp_path / "logs").exists()


def test_lint_is_clean(tmp_path):
    proc = _snakemake(["--lint"], ROOT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "Lints for" not in proc.stdout + proc.stderr


def test_snakefmt_is_clean():
    """The workflow catalog's second check: every Snakemake file formatted by snakefmt."""
    files = [ROOT / "Snakefile", *sorted((ROOT / "workflow/rules").rglob("*.smk"))]   # workflow/rules/extra/ too
    proc = subprocess.run([sys.executable, "-m", "snakefmt", "--check", *map(str, files)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_paper_preset_plans_50_runs_per_combination(tmp_path):
    # the job blocks (what the workflow profile's quiet console leaves out) list the outputs
    proc = _snakemake(["-n", "--workflow-profile", "none", "--configfile", str(ROOT / "presets/paper.yaml")], tmp_path)
    assert proc.returncode == 0, proc.stderr
    out = proc.stdout + proc.stderr
    cfg = config.resolve_config(config.load_config(ROOT / "presets/paper.yaml"))
    assert cfg["grid"]["n"] == 513 and cfg["hurst"] == [0.7] and 0.5 in cfg["radius"]
    assert cfg["h_rms"] == [9e-3] and len(cfg["seeds"]) == 50
    assert cfg["forces"]["sphere"]["from"] <= 1e-7 and cfg["forces"]["sphere"]["to"] >= 1e-2
    for combo in runs.combinations(cfg):
        prefix = f"results/runs/H{runs.format_value(combo['hurst'])}_R{runs.format_value(combo['radius'])}" \
                 f"_h{runs.format_value(combo['h_rms'])}/"
        planned = {seed for line in out.splitlines() if "output:" in line
                   for seed in re.findall(re.escape(prefix) + r"(seed\d+\.nc)", line)}
        assert len(planned) == 50, (prefix, len(planned))


def test_cli_check_config(tmp_path):


    assert cli.main(["check-config", str(ROOT / "config.yaml")]) == 0
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(_with("hurst", [0.0])))
    assert cli.main(["check-config", str(bad)]) == 2


def test_conda_env_files_exist():
    """A `conda:` directive whose file is missing breaks a real run after each job."""
    import re

    for smk in (ROOT / "workflow/rules").glob("*.smk"):
        for rel in re.findall(r'conda:\s*\n\s*"([^"]+)"', smk.read_text()):
            assert (smk.parent / rel).resolve().is_file(), (smk.name, rel)


def test_a_config_of_only_the_sweep_axes_takes_every_default_of_the_schema():
    """Defaults are defaults: the four sweep axes alone resolve, and every other key equals
    the schema's ``default`` (the same numbers as ``config.yaml`` for the keys it sets)."""
    minimal = {"hurst": [0.7], "radius": [0.5, math.inf], "h_rms": [9e-3], "seeds": 2}
    resolved = config.resolve_config(minimal)
    root = schema.load_schema(None)
    for path in (["grid", "n"], ["grid", "length"], ["e_star"], ["forces", "sphere"], ["forces", "flat"],
                 ["solver", "tol"], ["solver", "stiffness"], ["solver", "rel_step"], ["fit", "resolved_cells"],
                 ["fit", "zeta", "max_area_fraction"], ["fit", "bootstrap"], ["fit", "confidence"], ["fit", "slopes", "window"],
                 ["exponent"], ["rolloff"], ["cutoff"], ["hardness"]):
        value = resolved
        for key in path:
            value = value[key]
        assert value == schema.default_of(root, path), f"{'.'.join(path)} = {value!r} is not the schema's default"
    full = config.resolve_config(config.load_config(ROOT / "config.yaml"))
    assert resolved["grid"]["coarse"] == 193   # absent: (n + 1)/2, the companion config.yaml spells out
    assert {k: full[k] for k in ("grid", "e_star", "forces", "solver", "fit")} == \
        {k: resolved[k] for k in ("grid", "e_star", "forces", "solver", "fit")}, \
        "the schema's defaults differ from the values config.yaml spells out"


def test_a_scalar_is_a_one_element_list_for_every_list_valued_key():
    """``hurst: 0.7`` is ``hurst: [0.7]``: every key whose schema is a list only (the sweep axes,
    fields.at, stickiness.hurst, ...) or a list or null (tangential.at) takes one value as a
    one-element list; a key that also takes the scalar (seeds: 6, tangential.at: null) keeps it."""
    root = schema.load_schema(None)
    listed = {"hurst": 0.7, "radius": 0.5, "h_rms": 9e-3, "exponent": 2.0, "rolloff": None, "cutoff": None,
              "hardness": None, "work_of_adhesion": 0.0, "poisson": 0.3, "friction": 0.5}
    from roughcontact.study.config.axes import AXES

    # an axis added to the registry (the guide's worn plateau, copied in) is tried at its paper value
    listed.update({name: spec.paper for name, spec in AXES.items() if name not in listed})
    for name in root["properties"]:
        node = schema.deref(root["properties"][name], root)
        if node.get("type") == "array" and name not in ("topography", "spectrum"):
            assert name in listed, f"{name}: a list-valued key this test does not try"
    scalars = {**TINY, **listed, "fields": {"at": 1e-3}, "tangential": {"at": 2e-5}}
    as_lists = {**TINY, **{k: [v] for k, v in listed.items()}, "fields": {"at": [1e-3]},
                "tangential": {"at": [2e-5]}}
    assert config.resolve_config(scalars) == config.resolve_config(as_lists)
    kept = config.resolve_config({**TINY, "seeds": 3, "poisson": 0.3, "tangential": {"at": None}})
    assert kept["seeds"] == [0, 1, 2] and kept["tangential"]["at"] is None
    # a scalar of the wrong kind is still refused, naming the key's element
    with pytest.raises(errors.ConfigError, match=r"hurst\[0\]"):
        config.resolve_config({**TINY, "hurst": 2.5})


def test_cli_check_config_names_every_swept_axis(tmp_path, capsys):
    """check-config counts the combinations by the axis registry: an optional axis swept is named."""
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text(yaml.safe_dump({"hurst": [0.5, 0.7], "radius": [0.5], "h_rms": [9e-3], "seeds": 2,
                                      "grid": {"n": 129, "coarse": None}, "hardness": [None, 0.5]}))
    assert cli.main(["check-config", str(sweep)]) == 0
    assert "4 combinations of 2 hurst, 2 hardness x 2 seeds" in capsys.readouterr().out
