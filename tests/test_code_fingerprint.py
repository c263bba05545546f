"""The fingerprint of the code each analysis rule runs (roughcontact.study.registries): a new module
in a registry's package changes the fingerprints of the rules that read that registry and no other;
it is the params value that makes Snakemake rerun those rules (tests/test_extending.py runs that)."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PRINT = ("import json; from roughcontact.study.registries import ANALYSIS_CODE, code_fingerprint; "
         "print(json.dumps({rule: code_fingerprint(rule) for rule in ANALYSIS_CODE}))")


def _fingerprints(src: Path) -> dict:
    done = subprocess.run([sys.executable, "-c", PRINT], env={**os.environ, "PYTHONPATH": str(src)},
                          capture_output=True, text=True, timeout=120, check=True)
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def changes(tmp_path_factory):
    """Fingerprints of a scratch copy of the package before and after each of two additions: a
    module in the models' registry, then one in the claims' registry (each an empty module)."""
    src = tmp_path_factory.mktemp("fingerprint") / "src"
    shutil.copytree(ROOT / "src", src, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    steps = [_fingerprints(src)]
    for package in ("models/scorecard", "study/claims"):
        (src / "roughcontact" / package / "added_in_test.py").write_text('"""Nothing yet."""\n')
        steps.append(_fingerprints(src))
    return steps


def test_the_rules_have_distinct_fingerprints(changes):
    assert len(set(changes[0].values())) == len(changes[0]), changes[0]


def test_a_new_model_module_changes_the_models_fingerprint(changes):
    assert changes[1]["models"] != changes[0]["models"], changes


@pytest.mark.parametrize("rule", ["claims", "figures"])
def test_a_new_model_module_keeps_the_other_fingerprints(changes, rule):
    assert changes[1][rule] == changes[0][rule], changes


def test_a_new_claim_module_changes_the_claims_fingerprint(changes):
    assert changes[2]["claims"] != changes[1]["claims"], changes


@pytest.mark.parametrize("rule", ["models", "figures"])
def test_a_new_claim_module_keeps_the_other_fingerprints(changes, rule):
    assert changes[2][rule] == changes[1][rule], changes


def test_an_unknown_rule_is_named():
    from roughcontact.study.registries import code_fingerprint

    with pytest.raises(ValueError, match="'no_such_rule'"):
        code_fingerprint("no_such_rule")
