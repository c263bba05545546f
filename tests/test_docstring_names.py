"""Every ``roughcontact.…`` target of a Sphinx role (``:mod:``, ``:func:``, ``:class:``,
``:meth:``, ``:attr:``, ``:data:``, ``:exc:``) in the package's source resolves: its longest
importable module prefix imports and the rest is found by ``getattr``. A renamed or moved
module or function then fails here, not in a reader's browser."""
from __future__ import annotations

import dataclasses
import importlib
import re
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "roughcontact"
ROLE = re.compile(r":(?:mod|func|class|meth|attr|data|exc|obj):`~?(roughcontact(?:\.\w+)+)`")


def _targets() -> list[tuple[str, str]]:
    """``(file, target)`` of every role naming ``roughcontact.…`` in the package."""
    out = []
    for path in sorted(SRC.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        out += [(str(path.relative_to(SRC.parent)), name) for name in sorted(set(ROLE.findall(text)))]
    return out


def _resolve(name: str):
    parts = name.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ModuleNotFoundError:
            continue
        for attr in parts[cut:]:
            fields = {f.name for f in dataclasses.fields(obj)} if dataclasses.is_dataclass(obj) else set()
            obj = attr if attr in fields and not hasattr(obj, attr) else getattr(obj, attr)  # a field's default
        return obj
    raise ModuleNotFoundError(name)


def test_the_scan_finds_the_targets():
    """The pattern finds a known target (roughcontact.bem.solve is named in study/runs/indent.py): at
    least 100 in the package (there were 300+ on 2026-11-27)."""
    targets = _targets()
    assert ("roughcontact/study/runs/indent.py", "roughcontact.bem.solve") in targets, targets[:5]
    assert len(targets) >= 100, len(targets)


@pytest.mark.parametrize("where, name", _targets())
def test_every_named_target_exists(where, name):
    try:
        _resolve(name)
    except (ImportError, AttributeError) as exc:
        pytest.fail(f"{where}: {name} does not resolve ({type(exc).__name__}: {exc})")
