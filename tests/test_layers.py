"""The package's import layers: no cycle, and no import that runs up the layers.

Layers, bottom up: ``_validate`` and ``errors`` → ``surfaces`` → ``bem`` and ``models`` (which
do not import each other) → ``study`` → ``cli``; inside ``study``: ``files`` → ``quantities`` →
``config`` → ``runs`` → ``analysis`` → ``claims`` → ``report`` → ``rules`` (→ ``registries``). Every import
statement counts, also one inside a function. The test reads the sources with :mod:`ast` and imports nothing.
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "roughcontact"

#: layer of each top-level part of the package; a part may import its own layer or lower ones
LAYER = {"_validate": 0, "_registry": 0, "_defaults": 0, "errors": 0, "surfaces": 1, "bem": 2, "models": 2, "study": 3, "cli": 4}
#: parts of one layer that must not import each other
SEPARATE = {("bem", "models"), ("models", "bem"), ("bem", "surfaces")}


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def _resolve(module: str, is_package: bool, level: int, target: str | None) -> str:
    base = module.split(".") if is_package else module.split(".")[:-1]
    if level:
        base = base[: len(base) - (level - 1)]
        return ".".join(base + ([target] if target else []))
    return target or ""


def _imports(module: str) -> set[str]:
    """The package modules *module* imports (``from a import b`` counts as ``a.b`` where that is a module)."""
    path = MODULES[module]
    tree = ast.parse(path.read_text(encoding="utf-8"))
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            source = _resolve(module, path.name == "__init__.py", node.level, node.module)
            names = [f"{source}.{alias.name}" if f"{source}.{alias.name}" in MODULES else source
                     for alias in node.names]
        else:
            continue
        out |= {name for name in names if name.startswith("roughcontact.") and name in MODULES}
    return out


GRAPH = {module: _imports(module) for module in MODULES}


def _part(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else None


def test_the_package_has_the_layers_it_is_tested_for():
    parts = {_part(m) for m in MODULES} - {None}
    assert parts == set(LAYER), f"top-level parts {sorted(parts)} differ from the layers {sorted(LAYER)}"


def _imported_parts(module: str, part_of):
    """``(target, its part)`` of every module *module* imports that lies in a part (*part_of* not None)."""
    return [(target, part_of(target)) for target in sorted(GRAPH[module]) if part_of(target) is not None]


@pytest.mark.parametrize("module", sorted(m for m in MODULES if _part(m) is not None))
def test_no_import_runs_up_the_layers(module):
    mine = _part(module)
    for target, theirs in _imported_parts(module, _part):
        assert LAYER[theirs] <= LAYER[mine], f"{module} imports {target}: {theirs} is above {mine}"
        assert (mine, theirs) not in SEPARATE, f"{module} imports {target}: {mine} must not use {theirs}"


def test_no_import_cycle():
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(module):
        state[module] = 1
        path.append(module)
        for target in sorted(GRAPH[module]):
            if target == "roughcontact":  # the parent package is imported first anyway
                continue
            if state.get(target) == 1:
                cycle = path[path.index(target):] + [target]
                raise AssertionError("import cycle: " + " -> ".join(cycle))
            if target not in state:
                visit(target)
        path.pop()
        state[module] = 2

    for module in sorted(MODULES):
        if module not in state:
            visit(module)


def test_the_top_level_import_leaves_the_study_out():
    """``import roughcontact`` needs only numpy and scipy: the face imports no study module."""
    reached, todo = set(), ["roughcontact"]
    while todo:
        module = todo.pop()
        if module in reached:
            continue
        reached.add(module)
        todo += sorted(GRAPH[module])
    study = sorted(m for m in reached if _part(m) in ("study", "cli"))
    assert not study, f"import roughcontact also imports {study}"


#: the sub-layers inside ``study/``, bottom up: the run file's data model, the per-load quantities,
#: the configuration, the runs, the analysis, the claims, the report, the rules' entry points; ``registries`` reads them all
STUDY_LAYER = {"files": 0, "quantities": 1, "config": 2, "runs": 3, "analysis": 4, "claims": 5, "report": 6,
               "rules": 7, "registries": 8}


def _study_part(module: str) -> str | None:
    parts = module.split(".")
    return parts[2] if len(parts) > 2 and parts[1] == "study" else None


def test_the_study_has_the_sub_layers_it_is_tested_for():
    parts = {_study_part(m) for m in MODULES} - {None}
    assert parts == set(STUDY_LAYER), f"study's parts {sorted(parts)} differ from {sorted(STUDY_LAYER)}"


@pytest.mark.parametrize("module", sorted(m for m in MODULES if _study_part(m) is not None))
def test_no_import_runs_up_the_study_sub_layers(module):
    mine = _study_part(module)
    for target, theirs in _imported_parts(module, _study_part):
        assert STUDY_LAYER[theirs] <= STUDY_LAYER[mine], f"{module} imports {target}: {theirs} is above {mine}"
