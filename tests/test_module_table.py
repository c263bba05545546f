"""The package guide's table of the study's modules is what ``docs/make_module_table.py`` writes
from the modules themselves: a module added, moved or removed without the guide fails here."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _maker():
    spec = importlib.util.spec_from_file_location("make_module_table", ROOT / "docs" / "make_module_table.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _listed(text: str) -> list[str]:
    return re.findall(r"^\| `(study\.[\w.]+)` \|", text, re.M)


def test_the_guide_lists_every_module_of_the_study():
    maker = _maker()
    listed = _listed(maker.GUIDE.read_text(encoding="utf-8"))
    expected = [name.removeprefix("roughcontact.") for name in maker.modules()]
    assert listed == expected, f"missing: {sorted(set(expected) - set(listed))}, stale: {sorted(set(listed) - set(expected))}"


def test_the_guide_holds_the_generated_table():
    maker = _maker()
    text = maker.GUIDE.read_text(encoding="utf-8")
    assert maker.written(text) == text, "docs/guide/package.md: run python docs/make_module_table.py"


def test_a_sentence_ends_at_a_full_stop_before_a_capital():
    assert _maker().first_sentence("roughcontact.study.claims.exponents").endswith("(2012)."), "abbreviations"
