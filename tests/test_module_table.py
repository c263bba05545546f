"""The package guide's table of every module is generated when the documentation is built
(``docs/make_module_table.py``, called by ``docs/conf.py``) from the package's files: it lists
every module, a module added to the package included, and the guide includes it instead of a
hand-made copy that would go stale."""
from __future__ import annotations

import importlib.util
import pkgutil
import re
import shutil
import sys
import types
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _maker():
    return _load("make_module_table", ROOT / "docs" / "make_module_table.py")


def _listed(text: str) -> list[str]:
    return re.findall(r"^\| `([\w.]+)` \|", text, re.M)


def _walked(package: str = "roughcontact") -> list[str]:
    """Every module of *package* as Python's import system finds it (pkgutil, importing packages)."""
    found = [package]
    for info in pkgutil.walk_packages(importlib.import_module(package).__path__, package + "."):
        found.append(info.name)
    return sorted(found)


def test_the_table_lists_every_module_of_the_package():
    listed = [name if name == "roughcontact" else "roughcontact." + name for name in _listed(_maker().table())]
    expected = _walked()
    assert listed == expected, f"missing: {sorted(set(expected) - set(listed))}, stale: {sorted(set(listed) - set(expected))}"


def test_the_table_lists_the_tangential_axes_and_claims():
    listed = _listed(_maker().table())
    assert {"study.config.axes.tangential", "study.claims.tangential", "bem.tangential"} <= set(listed), listed


def test_a_module_added_to_the_package_is_listed(tmp_path):
    """The guide's claim example copied into a copy of the package's folder: one more row, its
    docstring's first sentence."""
    package = tmp_path / "roughcontact"
    shutil.copytree(ROOT / "src" / "roughcontact", package, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "docs" / "guide" / "extending" / "claim_example.py", package / "study" / "claims" / "stiffening.py")
    maker = _maker()
    rows = [line for line in maker.table(package).splitlines() if line.startswith("| `study.claims.stiffening`")]
    assert rows == ["| `study.claims.stiffening` | Claim (x): the ensemble-mean stiffness of every sphere combination "
                    "rises with the load. |"], rows


def test_the_guide_includes_the_generated_table():
    text = (ROOT / "docs" / "guide" / "package.md").read_text(encoding="utf-8")
    assert "```{include} ../_generated/package_modules.md\n```" in text, "docs/guide/package.md: no include of the table"
    by_hand = [name for name in _listed(text) if "." in name]     # the subpackages' summary aside
    assert not by_hand, f"docs/guide/package.md: a hand-made table of modules: {by_hand}"


def test_the_docs_build_writes_the_table(tmp_path, monkeypatch):
    """``docs/conf.py``'s ``setup`` connects the writer to ``builder-inited``; called as Sphinx
    calls it, it writes the table where the guide includes it from."""
    monkeypatch.setattr(sys, "path", list(sys.path))        # conf.py adds docs/ and src/ to the path
    conf = _load("docs_conf", ROOT / "docs" / "conf.py")
    hooks = []
    conf.setup(types.SimpleNamespace(connect=lambda event, hook: hooks.append((event, hook))))
    assert [event for event, _ in hooks] == ["builder-inited"], hooks
    hooks[0][1](types.SimpleNamespace(srcdir=str(tmp_path)))
    written = (tmp_path / "_generated" / "package_modules.md").read_text(encoding="utf-8")
    assert written == _maker().table(), "the table written by the docs build is not the module table"


def test_the_generated_table_is_no_page_of_its_own():
    monkeypatch_path = list(sys.path)
    try:
        conf = _load("docs_conf", ROOT / "docs" / "conf.py")
    finally:
        sys.path[:] = monkeypatch_path
    assert "_generated/package_modules.md" in conf.exclude_patterns, conf.exclude_patterns


def test_a_sentence_ends_at_a_full_stop_before_a_capital():
    source = ROOT / "src" / "roughcontact" / "study" / "claims" / "exponents.py"
    assert _maker().first_sentence(source).endswith("(2012)."), "abbreviations"


def test_a_reference_in_parentheses_ends_no_sentence():
    source = ROOT / "src" / "roughcontact" / "models" / "scorecard" / "persson.py"
    assert _maker().first_sentence(source).startswith("Persson's interfacial law (J. Chem. Phys. 115, 3840 (2001)"), \
        "an abbreviation after a parenthesis ended the sentence"
