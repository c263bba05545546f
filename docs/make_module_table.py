"""The table of the package's modules, from the modules themselves, written when the documentation
is built.

    python docs/make_module_table.py [OUT]

Each module of the ``roughcontact`` package (subpackages and their modules included, every file
of its folder: a module copied into a registry's package, such as the worked examples of
``docs/guide/extending/``, is one more row) is one row: its dotted name and the first sentence of
its docstring, read from the source without importing it. ``docs/conf.py`` writes the table into
``docs/_generated/package_modules.md`` when Sphinx starts (event ``builder-inited``) and the
package guide (``docs/guide/package.md``) includes that file, so the guide cannot list a module
that is gone or miss one that was added; ``tests/test_module_table.py`` checks the table and the
hook.
"""
from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
#: the folder of the package the table lists
PACKAGE = DOCS.parent / "src" / "roughcontact"
#: where the documentation build writes the table (``docs/_generated/`` is ignored by git)
GENERATED = Path("_generated") / "package_modules.md"
#: words ending in a full stop that end no sentence
ABBREVIATIONS = {"Phys.", "Rev.", "Lett.", "Appl.", "Mech.", "al.", "e.g.", "i.e.", "cf.", "eq.", "eqs.", "Fig.",
                 "Proc.", "Soc.", "Sci.", "Int.", "Res.", "vs.", "No.", "Trib.", "Math.", "Comput.", "Chem."}


def modules(package: Path = PACKAGE) -> dict[str, Path]:
    """``{dotted name: source file}`` of every module of the package in the folder *package*
    (a package by its ``__init__.py``), in name order; nothing is imported."""
    out = {}
    for path in package.rglob("*.py"):
        parts = path.relative_to(package.parent).with_suffix("").parts
        if "__pycache__" in parts or not all((package.parent / Path(*parts[:i]) / "__init__.py").exists()
                                             for i in range(1, len(parts))):
            continue        # a file outside the package's importable tree
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return dict(sorted(out.items()))


def first_sentence(source: Path) -> str:
    """The first sentence of the module docstring of the file *source* as Markdown (reST roles
    and double backquotes made plain code; ``|`` made ``/``, for the table); ``""`` without one."""
    doc = ast.get_docstring(ast.parse(source.read_text(encoding="utf-8"))) or ""
    text = " ".join(doc.strip().split("\n\n")[0].split())
    text = re.sub(r":\w+:`~?([^`]+)`", r"`\1`", text).replace("``", "`").replace("|", "/")
    if not text:
        return ""
    for end in re.finditer(r"\.(?=\s+[A-Z(`]|$)", text):   # a full stop before a capital, or the end
        sentence = text[:end.end()]
        word = sentence.rsplit(" ", 1)[-1].lstrip("([")
        if word not in ABBREVIATIONS and not re.fullmatch(r"[A-Z]\.", word):   # nor an initial
            return sentence
    return text.rstrip(".") + "."


def table(package: Path = PACKAGE) -> str:
    """The Markdown table of :func:`modules`: one row per module, its name without the
    package's and the first sentence of its docstring."""
    prefix = package.name + "."
    rows = [f"| `{name.removeprefix(prefix)}` | {first_sentence(path)} |" for name, path in modules(package).items()]
    return "\n".join(["| module | what it holds |", "| --- | --- |", *rows, ""])


def write(out: Path, package: Path = PACKAGE) -> Path:
    """Write :func:`table` to the file *out* (its folder made), unless it holds that already (so
    Sphinx does not rebuild the guide for nothing); *out*."""
    out.parent.mkdir(parents=True, exist_ok=True)
    text = table(package)
    if not out.exists() or out.read_text(encoding="utf-8") != text:
        out.write_text(text, encoding="utf-8")
    return out


def on_builder_inited(app) -> None:
    """The Sphinx hook of ``docs/conf.py``: the table into ``<srcdir>/_generated/package_modules.md``."""
    write(Path(app.srcdir) / GENERATED)


if __name__ == "__main__":
    print(f"wrote the package's module table to {write(Path(sys.argv[1]) if len(sys.argv) > 1 else DOCS / GENERATED)}")
