"""Write the table of the study's modules into the package guide, from the modules themselves.

    python docs/make_module_table.py

Each module of :mod:`roughcontact.study` (subpackages included) is one row: its dotted name and
the first sentence of its docstring. The table stands between the markers of
``docs/guide/package.md``; ``tests/test_module_table.py`` checks that it is what this script
writes, so a module added, moved or removed without the guide fails there.
"""
from __future__ import annotations

import importlib
import pkgutil
import re
from pathlib import Path

GUIDE = Path(__file__).resolve().parent / "guide" / "package.md"
#: words ending in a full stop that end no sentence
ABBREVIATIONS = {"Phys.", "Rev.", "Lett.", "Appl.", "Mech.", "al.", "e.g.", "i.e.", "cf.", "eq.", "eqs.", "Fig."}
BEGIN, END = "<!-- study-modules: begin (docs/make_module_table.py) -->", "<!-- study-modules: end -->"


def modules(package: str = "roughcontact.study") -> list[str]:
    """Every module of *package* and its subpackages, by dotted name, in name order."""
    out = []
    for info in pkgutil.iter_modules(importlib.import_module(package).__path__):
        name = f"{package}.{info.name}"
        out.append(name)
        if info.ispkg:
            out += modules(name)
    return sorted(out)


def first_sentence(module: str) -> str:
    """The first sentence of *module*'s docstring as Markdown (reST roles and double backquotes
    made plain code)."""
    text = " ".join((importlib.import_module(module).__doc__ or "").strip().split("\n\n")[0].split())
    text = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", text).replace("``", "`")
    for end in re.finditer(r"\.(?=\s+[A-Z(`]|$)", text):   # a full stop before a capital, or the end
        sentence = text[:end.end()]
        if sentence.rsplit(" ", 1)[-1] not in ABBREVIATIONS:
            return sentence
    return text.rstrip(".") + "."


def table() -> str:
    """The Markdown table of :func:`modules`, between the markers."""
    rows = [f"| `{name.removeprefix('roughcontact.')}` | {first_sentence(name).replace('|', '/')} |"
            for name in modules()]
    return "\n".join([BEGIN, "", "| module | what it holds |", "| --- | --- |", *rows, "", END])


def written(text: str) -> str:
    """*text* (the guide) with the table between its markers replaced by :func:`table`."""
    start, stop = text.index(BEGIN), text.index(END) + len(END)
    return text[:start] + table() + text[stop:]


if __name__ == "__main__":
    GUIDE.write_text(written(GUIDE.read_text(encoding="utf-8")), encoding="utf-8")
    print(f"wrote the study's module table into {GUIDE}")
