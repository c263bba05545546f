"""One entry point per Snakemake rule, in one predictable place (issue #42): the script of every
``script:`` directive of ``workflow/rules/**/*.smk`` imports, of the package's entry points, only
``roughcontact.study.rules.<script's stem>`` (beside :mod:`roughcontact.study.files.logs`' ``log_to``),
and that module has a documented ``run``. The script is named after its rule, or the rule is a
named variant of a rule whose script it shares (:data:`VARIANTS`). The test reads the files with
:mod:`ast` and regular expressions; it imports only the rule modules.
"""
from __future__ import annotations

import ast
import importlib
import importlib.util
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
RULE_FILES = sorted((ROOT / "workflow" / "rules").rglob("*.smk"))

#: rules that run the script of another rule (its stem): the grid error's and the fine reference's
#: companions, the indent jobs of a block of seeds (``{block}``: ``seeds0_5``, ...), a measured
#: spectrum's runs and merge beside a scan's, the partial-slip figures beside the full-stick one
VARIANTS = {
    "merge_coarse": "merge", "merge_fine": "merge",
    "indent_coarse": "indent", "indent_fine": "indent",
    "indent_{block}": "indent", "indent_coarse_{block}": "indent", "indent_fine_{block}": "indent",
    "spectrum_indent": "measured_indent", "spectrum_merge": "measured_merge",
    "partial_slip_figures": "tangential_figures",
}

#: rules whose scripts still call the layers directly (none since 2026-11-29: every rule follows the
#: convention; a rule added here must say why)
NOT_YET: set = set()

#: the package modules a script may import beside its rule's module (not an entry point)
HELPERS = {"roughcontact.study.files.logs"}

_RULE = re.compile(r"^\s*(?:rule|checkpoint)\s+(\w+)\s*:", re.M)
_NAME = re.compile(r"""^\s*name:\s*\n\s*f?["']([^"']+)["']""", re.M)
_SCRIPT = re.compile(r"""^\s*script:\s*\n\s*["']([^"']+)["']""", re.M)


def _rules_and_scripts(path: Path) -> list[tuple[str, Path]]:
    """``(rule name, script path)`` of every ``script:`` of the Snakemake file *path*: the rule is the
    nearest ``rule NAME:``/``checkpoint NAME:`` above it, or the ``name:`` of an anonymous ``rule:``
    (an f-string's fields written as ``{field}``, ``.name`` left out)."""
    text = path.read_text(encoding="utf-8")
    heads = sorted([(m.start(), m.group(1)) for m in _RULE.finditer(text)]
                   + [(m.start(), re.sub(r"\{(\w+)(?:\.\w+)*\}", r"{\1}", m.group(1))) for m in _NAME.finditer(text)])
    out = []
    for m in _SCRIPT.finditer(text):
        rule = [name for start, name in heads if start < m.start()][-1]
        out.append((rule, (path.parent / m.group(1)).resolve()))
    return out


PAIRS = [pair for path in RULE_FILES for pair in _rules_and_scripts(path)]


def _package_imports(script: Path) -> set[str]:
    """The ``roughcontact`` modules *script* imports (``from a import b`` counts as ``a.b``)."""
    out = set()
    for node in ast.walk(ast.parse(script.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            for alias in node.names:
                name = f"{node.module}.{alias.name}"
                out.add(name if importlib.util.find_spec(node.module) and _is_module(name) else node.module)
    return {name for name in out if name.split(".")[0] == "roughcontact"}


def _is_module(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except ModuleNotFoundError:
        return False


def test_the_workflow_has_scripts_to_check():
    """The parser finds the rules (a change of the Snakemake files' layout fails here, not silently)."""
    names = {rule for rule, _ in PAIRS}
    assert {"merge", "claims", "indent", "indent_{block}", "measured_surface", "partial_slip_figures"} <= names, names


def test_the_exceptions_are_rules_of_the_workflow():
    names = {rule for rule, _ in PAIRS}
    assert NOT_YET <= names and set(VARIANTS) <= names, (NOT_YET | set(VARIANTS)) - names


@pytest.mark.parametrize("rule, script", PAIRS, ids=[rule for rule, _ in PAIRS])
def test_the_script_is_named_after_its_rule(rule, script):
    assert script.exists(), f"rule {rule}: no script {script}"
    assert script.stem == VARIANTS.get(rule, rule), f"rule {rule} runs {script.name}"


@pytest.mark.parametrize("rule, script", [p for p in PAIRS if p[0] not in NOT_YET],
                         ids=[rule for rule, _ in PAIRS if rule not in NOT_YET])
def test_the_script_calls_only_its_rules_module(rule, script):
    entry = f"roughcontact.study.rules.{script.stem}"
    assert _package_imports(script) - HELPERS == {entry}, f"{script.name} imports {sorted(_package_imports(script))}"


@pytest.mark.parametrize("stem", sorted({s.stem for r, s in PAIRS if r not in NOT_YET}))
def test_the_rules_module_has_a_documented_run(stem):
    module = importlib.import_module(f"roughcontact.study.rules.{stem}")
    assert callable(getattr(module, "run", None)) and module.run.__doc__, f"{module.__name__}.run"
