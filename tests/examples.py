"""The worked examples of ``docs/guide/extending/`` and the registries the tests run against.

:func:`loaded` loads an example in this process, as the module its first line names
(``# module: roughcontact.<dotted.path>``), so that the in-process tests of the registries run the
guide's own text; ``tests/test_extending.py`` copies the same files into a scratch copy of the
package and runs a study with them end to end.

:func:`scoped_registries` (and the autouse fixture :func:`scoped_registry`, imported by a test
module to give each of its tests a scope) snapshots the axes, models and claims registries with
their built-ins loaded and restores them afterwards: what a test registers or removes, it does in
its own copy, so an example loaded twice never meets itself and no result depends on the order
of the tests. The suite asserts that the built-ins are registered, in order (:func:`in_order`),
never that nothing else is: a module copied into a registry's package (as the guide says to) is
welcome.
"""
from __future__ import annotations

import contextlib
import importlib.util
import re
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "guide" / "extending"


def module_of(example: Path) -> str:
    """The dotted module an example goes to: its first line, ``# module: roughcontact.<path>``."""
    first = example.read_text().splitlines()[0]
    match = re.fullmatch(r"# module: (roughcontact(?:\.\w+)+)", first.strip())
    if not match:
        raise ValueError(f"{example.name}: first line {first!r} is not '# module: roughcontact.<dotted.path>'")
    return match.group(1)


def registries() -> dict:
    """``{"axes": AXES, "models": MODELS, "claims": CLAIMS, "claim tables": TABLES}``, the
    registries' own dicts, each with every module of its package imported (the built-ins and
    whatever else is there)."""
    from roughcontact.models import scorecard
    from roughcontact.study import claims
    from roughcontact.study.config import axes

    scorecard.models()
    claims.claims()
    return {"axes": axes.AXES, "models": scorecard.MODELS, "claims": claims.CLAIMS, "claim tables": claims.TABLES}


def target_of(example: Path) -> Path:
    """The file an example becomes, relative to the checkout: a module's (``# module: ...``,
    :func:`module_of`) under ``src/``, or the path a workflow file's first line names
    (``# file: workflow/<path>``)."""
    first = example.read_text().splitlines()[0].strip()
    match = re.fullmatch(r"# file: (workflow/[\w./-]+)", first)
    if match:
        return Path(match.group(1))
    return Path("src", *module_of(example).split(".")).with_suffix(".py")


def example_files() -> list:
    """Every worked example of :data:`EXAMPLES`: the new modules (``*_example.py``) and the rule's
    workflow files (``*_example.smk``, ``*_example_*.py``)."""
    return sorted({*EXAMPLES.glob("*_example.py"), *EXAMPLES.glob("*_example.smk"), *EXAMPLES.glob("*_example_*.py")})


def without_examples(root: Path):
    """An ``ignore`` for ``shutil.copytree`` of a folder of the checkout *root* (``src``, ``workflow``):
    caches, and every file an example becomes (:func:`target_of`) where it was copied in already, as
    the guide says to. A scratch copy made with it is the checkout without the examples, whether or
    not they were copied in: a test that copies some in finds no other (e.g. the rule's
    ``workflow/rules/extra/resolved_loads.smk`` without its module, which stops every ``snakemake``)."""
    copied = {root / target_of(example) for example in example_files()}

    def ignore(folder, names):
        return {name for name in names if name == "__pycache__" or name.endswith(".egg-info")
                or Path(folder, name) in copied}

    return ignore


def _forget_schema() -> None:
    """Drop the configuration schema built from the axes registry (it is rebuilt when read)."""
    from roughcontact.study.config import schema

    schema._package_schema.cache_clear()


@contextlib.contextmanager
def scoped_registries():
    """A scope in which the registries (:func:`registries`) may be changed: on leaving it, each
    holds again exactly what it held on entering (same entries, same order), and the schema built
    from the axes is rebuilt."""
    held = registries()
    saved = {name: dict(registry) for name, registry in held.items()}
    _forget_schema()
    try:
        yield held
    finally:
        for name, registry in held.items():
            registry.clear()
            registry.update(saved[name])
        _forget_schema()


@pytest.fixture(autouse=True)
def scoped_registry():
    """Every test of a module that imports this fixture runs in its own :func:`scoped_registries`."""
    with scoped_registries() as held:
        yield held


def in_order(expected, registered) -> bool:
    """Whether the names *expected* (the built-ins) are all in *registered*, in that order, with
    anything else (a module added to the registry's package) between or after them."""
    position = iter(registered)
    return all(name in position for name in expected)


@contextlib.contextmanager
def loaded(name: str, registry: dict, key: str, *, also: tuple = ()):
    """Import the example *name* (``model_example.py``) as its module, which registers one entry
    *key* in *registry*; yield the module; afterwards the registries and the module table are as
    before. Where the example is in the package already (copied in, as the guide says), its
    entry is replaced by the guide's text for the scope: loading it twice is no error. *also*:
    further ``(registry, key)`` the example registers (a claim's input table)."""
    path = EXAMPLES / name
    module = module_of(path)
    before = sys.modules.get(module)
    with scoped_registries():
        registry.pop(key, None)
        for other, other_key in also:
            other.pop(other_key, None)
        spec = importlib.util.spec_from_file_location(module, path)
        loaded_module = importlib.util.module_from_spec(spec)
        sys.modules[module] = loaded_module
        try:
            spec.loader.exec_module(loaded_module)
            _forget_schema()
            yield loaded_module
        finally:
            if before is None:
                sys.modules.pop(module, None)
            else:
                sys.modules[module] = before
