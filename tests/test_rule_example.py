"""The guide's rule of one's own and its claim that reads the rule's table, done
(``docs/guide/extending/rule_example.smk``, ``rule_example_script.py``, ``rule_example.py`` and
``table_claim_example.py``).

In this process: the rule's table against counts and eq. 17 written out here, and the claim's
verdicts on a table of known ratios. End to end (``-m workflow``, about 2 minutes on 2 cores): in a
scratch copy of the checkout where a study ran first, the rule's three files copied where their
first lines say (no other edit: the Snakefile includes ``workflow/rules/extra/``) make
``results/resolved_loads.csv`` on request and rerun nothing; the claim copied in next makes the
``claims`` rule ask for that table, so that ``snakemake`` reruns the claims (no run, no merge) and
``claims.csv`` gains one row (y) per sphere combination, its value the table's, every other row
as it was; an edit of the rule's module then plans the rule again (its code fingerprint) and no run.
"""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
import yaml
from examples import (EXAMPLES, loaded, module_of, scoped_registry,  # noqa: F401 -- scoped_registry: autouse
                      target_of, without_examples)

ROOT = Path(__file__).resolve().parents[1]
RULE_FILES = ("rule_example.smk", "rule_example_script.py", "rule_example.py")
CLAIM = "table_claim_example.py"

FORCE = np.geomspace(1e-5, 1e-2, 6)


def _sphere(cells: np.ndarray, *, hurst=0.7, radius=0.5, h_rms=2e-2) -> xr.Dataset:
    """A merged sphere group of one combination whose two seeds have *cells* contact cells per load."""
    axes = {"hurst": [hurst], "radius": [radius], "h_rms": [h_rms]}
    dims = (*axes, "seed", "force")
    per_seed = np.stack([cells, cells]).astype(float)
    shape = (1, 1, 1) + per_seed.shape
    return xr.Dataset({"stiffness": (dims, np.ones(shape)), "contact_cells": (dims, per_seed.reshape(shape))},
                      coords={**axes, "seed": [0, 1], "force": FORCE, "force_normalized": ("force", FORCE)})


def _eq17(hurst, radius, h_rms, length=1.0):
    """Eq. 17 with ζ = 1.7/(H+1) (eq. 13), written out: F_tr/E* = [ζ^(3H+3) h^-3 L^(3H) (6R)^(-H-1)]^(1/(H-2))."""
    zeta = 1.7 / (hurst + 1)
    return (zeta ** (3 * hurst + 3) * h_rms ** -3 * length ** (3 * hurst) * (6 * radius) ** (-hurst - 1)) \
        ** (1 / (hurst - 2)) / length**2


@pytest.fixture(scope="module")
def rule_module():
    """The rule example's module, loaded from the guide's text."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(module_of(EXAMPLES / "rule_example.py"), EXAMPLES / "rule_example.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def study():
    from roughcontact.study.config import load_config, study_settings

    return study_settings(load_config(ROOT / "presets" / "tiny.yaml"))   # fit.resolved_cells = 10


def test_the_table_counts_the_resolved_loads(rule_module, study):
    """Cells 2, 5, 10, 40, 90, 300 with resolved_cells 10: the last four loads are resolved."""
    table = rule_module.resolved_loads_table(_sphere(np.array([2, 5, 10, 40, 90, 300])), study)
    assert table["resolved_loads"].tolist() == [4]


def test_the_table_gives_the_smallest_resolved_load(rule_module, study):
    table = rule_module.resolved_loads_table(_sphere(np.array([2, 5, 10, 40, 90, 300])), study)
    assert table["first_resolved_force"].iloc[0] == FORCE[2]


def test_the_table_gives_eq17(rule_module, study):
    """Its crossover force is eq. 17 with ζ of eq. 13 to round-off (1e-12)."""
    table = rule_module.resolved_loads_table(_sphere(np.full(6, 100), hurst=0.5, radius=1.0, h_rms=9e-3), study)
    assert table["crossover_force_eq17"].iloc[0] == pytest.approx(_eq17(0.5, 1.0, 9e-3), rel=1e-12)


def test_a_combination_without_a_resolved_load_has_no_ratio(rule_module, study):
    table = rule_module.resolved_loads_table(_sphere(np.full(6, 3)), study)
    assert math.isnan(table["first_resolved_ratio"].iloc[0])


def _claim_rows(table: pd.DataFrame | None, study) -> list:
    from roughcontact.study.claims import CLAIMS, TABLES, ClaimInputs, table_rows

    with loaded(CLAIM, CLAIMS, "y", also=((TABLES, "resolved_loads"),)):
        inputs = ClaimInputs(cross=None, replicates=None, zeta=None, study=study,
                             tables={} if table is None else {"resolved_loads": table})
        if any(inputs.get(need) is None for need in CLAIMS["y"].needed):
            return []
        return table_rows(CLAIMS["y"], inputs)


def test_the_claim_judges_each_row_of_the_table(study):
    """Intervals [0.25, 0.5], [1.5, 2] and none: consistent, differs, untested (unresolved)."""
    table = pd.DataFrame({"hurst": [0.7] * 3, "radius": [0.5, 1.0, 2.0], "h_rms": [0.02] * 3, "loads": [8] * 3,
                          "resolved_loads": [4, 4, 0], "first_resolved_force": [1e-4, 4e-4, math.nan],
                          "crossover_force_eq17": [2e-4] * 3, "first_resolved_ratio": [0.5, 2.0, math.nan],
                          "previous_ratio": [0.25, 1.5, math.nan]})
    rows = _claim_rows(table, study)
    assert [(r["radius"], r["verdict"]) for r in rows] == [(0.5, "consistent"), (1.0, "differs"),
                                                           (2.0, "untested")]


def test_the_claim_has_no_row_without_its_table(study):
    assert _claim_rows(None, study) == []


def test_the_rule_example_passes_snakefmt():
    done = subprocess.run([sys.executable, "-m", "snakefmt", "--check", str(EXAMPLES / "rule_example.smk")],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


def _fingerprint(src: Path) -> str:
    code = "from roughcontact.study.registries import code_fingerprint; print(code_fingerprint('resolved_loads'))"
    done = subprocess.run([sys.executable, "-c", code], env={**os.environ, "PYTHONPATH": str(src)},
                          capture_output=True, text=True, timeout=120, check=True)
    return done.stdout.strip()


@pytest.fixture(scope="module")
def fingerprints(tmp_path_factory):
    """The rule's code fingerprint (its params' ``code``) in a scratch copy of the package with the
    rule's module copied in: as copied, after an edit of the module, after an edit of a module the
    rule does not import (the claims' page)."""
    src = tmp_path_factory.mktemp("fingerprint") / "src"
    shutil.copytree(ROOT / "src", src, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    module = src / target_of(EXAMPLES / "rule_example.py").relative_to("src")
    shutil.copy(EXAMPLES / "rule_example.py", module)
    steps = [_fingerprint(src)]
    module.write_text(module.read_text() + "\n# edited\n")
    steps.append(_fingerprint(src))
    page = src / "roughcontact" / "study" / "report" / "claims.py"
    page.write_text(page.read_text() + "\n# edited\n")
    steps.append(_fingerprint(src))
    return steps


def test_a_scratch_copy_leaves_out_the_rule_copied_in(tmp_path):
    """The guide followed (the rule's three files copied into a checkout): a scratch copy of its
    src/ and workflow/ made with examples.without_examples holds none of them, so the study of
    tests/test_extending.py runs before the examples as in a checkout without them (with the rule's
    .smk kept and its module left out, every snakemake of that test stopped at code_fingerprint)."""
    root = tmp_path / "checkout"
    for name in RULE_FILES:
        target = root / target_of(EXAMPLES / name)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(EXAMPLES / name, target)
    (root / "workflow" / "rules" / "common.smk").write_text("# kept\n")
    copy = tmp_path / "copy"
    for folder in ("src", "workflow"):
        shutil.copytree(root / folder, copy / folder, ignore=without_examples(root))
    assert sorted(str(p.relative_to(copy)) for p in copy.rglob("*") if p.is_file()) == ["workflow/rules/common.smk"]


def test_the_guide_copies_each_rule_file_where_its_first_line_says():
    """The guide's copy commands ("Adding a rule"): the folder workflow/rules/extra/ made first (it is
    not in the repository), then each of the rule's three files to the place its first line names."""
    guide = (ROOT / "docs" / "guide" / "package.md").read_text()
    block = guide.split("### Adding a rule", 1)[1].split("```bash\n", 1)[1].split("```", 1)[0].splitlines()
    assert block == ["mkdir -p workflow/rules/extra",
                     *(f"cp docs/guide/extending/{name} {target_of(EXAMPLES / name)}" for name in RULE_FILES)]


def test_the_rule_passes_its_modules_fingerprint():
    assert 'code=code_fingerprint("resolved_loads")' in (EXAMPLES / "rule_example.smk").read_text()


def test_an_edit_of_the_rules_module_changes_its_fingerprint(fingerprints):
    assert fingerprints[1] != fingerprints[0], fingerprints


def test_an_edit_of_a_module_it_does_not_import_keeps_its_fingerprint(fingerprints):
    assert fingerprints[2] == fingerprints[1], fingerprints


# ------------------------------------------------------------------------------------------------
# end to end, in a scratch copy of the checkout
# ------------------------------------------------------------------------------------------------
#: two sphere combinations (two radii), one H and h_rms, on a small grid (as tests/test_extending.py)
BASE = {"grid": {"n": 65, "length": 1.0, "coarse": None}, "e_star": 1.0, "hurst": [0.7], "radius": [0.5, 1.0],
        "h_rms": [2.0e-2], "seeds": 2,
        "forces": {"sphere": {"from": 1.0e-5, "to": 1.0e-2, "count": 8}},
        "solver": {"tol": 1.0e-8, "stiffness": "punch"},
        "fit": {"resolved_cells": 10, "bootstrap": 100}}


def _snakemake(where: Path, *args: str) -> str:
    env = {**os.environ, "PYTHONPATH": str(where / "src")}
    # the study in the scratch checkout's results/ (a --configfile run there would go to studies/base/)
    done = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", *args, "--configfile", "base.yaml",
                           "--directory", str(where)],
                          cwd=where, env=env, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, f"snakemake failed:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done.stdout + done.stderr


def _runs(where: Path) -> dict:
    return {str(p.relative_to(where)): p.read_bytes() for p in sorted((where / "results" / "runs").rglob("*.nc"))}


def _copy_in(where: Path, example: str) -> None:
    target = where / target_of(EXAMPLES / example)
    assert not target.exists(), f"{example}: {target} exists already (an example is a new file)"
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy(EXAMPLES / example, target)


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    """The study BASE run in a scratch checkout without the examples; then the rule's files copied
    in (a dry run, the table made), then the claim (a dry run, the study run again), then an edit of
    the rule's module (a dry run). Yields the directory, the run files and claims.csv of the first
    study, and the three dry runs' texts."""
    examples = {ROOT / target_of(EXAMPLES / name) for name in (*RULE_FILES, CLAIM)}
    where = tmp_path_factory.mktemp("rule")
    ignore = (lambda folder, names: {n for n in names if n == "__pycache__" or n.endswith(".egg-info")
                                     or Path(folder, n) in examples})
    for folder in ("src", "workflow", "envs"):
        shutil.copytree(ROOT / folder, where / folder, ignore=ignore)
    shutil.copy(ROOT / "Snakefile", where / "Snakefile")
    (where / "base.yaml").write_text(yaml.safe_dump(BASE))
    _snakemake(where, "-q")
    runs, claims = _runs(where), pd.read_csv(where / "results" / "claims.csv")
    for name in RULE_FILES:
        _copy_in(where, name)
    planned = {"rule": _snakemake(where, "-n")}
    _snakemake(where, "results/resolved_loads.csv", "-q")
    _copy_in(where, CLAIM)
    planned["claim"] = _snakemake(where, "-n")
    _snakemake(where, "-q")
    module = where / target_of(EXAMPLES / "rule_example.py")
    module.write_text(module.read_text() + "\n# edited\n")
    planned["edit"] = _snakemake(where, "-n")
    return where, runs, claims, planned


#: the end-to-end tests run the Snakemake workflow (left out of the quick subset: -m "not workflow")
workflow = pytest.mark.workflow


@workflow
def test_the_rule_alone_plans_nothing(scratch):
    """Asked for nothing, a study with the new rule has nothing to do (no target of `all` needs it)."""
    assert "Nothing to be done" in scratch[3]["rule"], scratch[3]["rule"][-2000:]


@workflow
def test_the_rules_table_has_a_row_per_sphere_combination(scratch):
    table = pd.read_csv(scratch[0] / "results" / "resolved_loads.csv")
    assert sorted(table["radius"]) == BASE["radius"], table.to_string()


@workflow
def test_the_rules_table_counts_the_merged_runs_resolved_loads(scratch):
    """Its counts are those of stiffness.nc, recounted here: mean contact cells >= fit.resolved_cells."""
    from roughcontact.study.files.io import read_groups

    where = scratch[0]
    sphere = read_groups(where / "results" / "stiffness.nc")["sphere"]
    table = pd.read_csv(where / "results" / "resolved_loads.csv").set_index("radius")
    for radius in BASE["radius"]:
        cells = sphere["contact_cells"].sel(radius=radius).squeeze().mean("seed").values
        assert table.loc[radius, "resolved_loads"] == int((cells >= BASE["fit"]["resolved_cells"]).sum()), radius


@workflow
def test_the_claim_reruns_the_claims_and_no_run(scratch):
    planned = scratch[3]["claim"]
    assert "claims" in planned and "indent" not in planned and "merge " not in planned, planned[-2000:]


@workflow
def test_an_edit_of_the_rules_module_reruns_the_rule_and_no_run(scratch):
    """Its params carry its module's fingerprint: no --forcerun needed."""
    planned = scratch[3]["edit"]
    assert "resolved_loads" in planned and "indent" not in planned, planned[-2000:]


@workflow
def test_the_rule_and_the_claim_recompute_no_run(scratch):
    where, runs, _, _ = scratch
    assert _runs(where) == runs


@workflow
def test_the_claim_has_the_tables_value_per_sphere_combination(scratch):
    where = scratch[0]
    claims = pd.read_csv(where / "results" / "claims.csv")
    y = claims[claims["claim"] == "y"].set_index("radius")
    table = pd.read_csv(where / "results" / "resolved_loads.csv").set_index("radius")
    assert sorted(y.index) == BASE["radius"], claims[["claim", "radius", "verdict"]].to_string()
    np.testing.assert_allclose(y.loc[BASE["radius"], "measured"], table.loc[BASE["radius"], "first_resolved_ratio"],
                               rtol=1e-12)


@workflow
def test_the_claims_verdict_follows_its_interval(scratch):
    claims = pd.read_csv(scratch[0] / "results" / "claims.csv")
    y = claims[claims["claim"] == "y"]
    expected = np.where(y["ci_high"] < 1, "consistent", np.where(y["ci_low"] > 1, "differs", "untested"))
    assert (y["verdict"] == expected).all(), y.to_string()


@workflow
def test_every_other_claim_row_is_as_it_was(scratch):
    where, _, before, _ = scratch
    after = pd.read_csv(where / "results" / "claims.csv")
    after = after[after["claim"] != "y"].reset_index(drop=True)
    pd.testing.assert_frame_equal(after, before, check_exact=False, rtol=1e-12)
