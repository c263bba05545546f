"""What the study's registries hold, and the fingerprint of the code of what they register.

:func:`listing` is what ``roughcontact list axes|models|area-models|claims|quantities`` prints: the
registered sweep axes (:mod:`roughcontact.study.config.axes`), models of the stiffness scorecard
(:mod:`roughcontact.models.scorecard`), models of the area scorecard (:mod:`roughcontact.models.area`),
claims (:mod:`roughcontact.study.claims`) and per-load quantities of a run
(:mod:`roughcontact.study.quantities`), one record each.

:func:`code_fingerprint` hashes the source of the modules an analysis rule runs, so that the
workflow gives it as a ``params`` value: adding or changing a model, a claim or their code makes
Snakemake (its default ``params`` rerun trigger) run that analysis again in an existing results
directory, while the runs, whose ``params`` are their own settings and
:data:`roughcontact.bem.SOLVER_VERSION`, are left as they are.
"""
from __future__ import annotations

import ast
import functools
import hashlib
import math
from pathlib import Path

__all__ = ["REGISTRIES", "listing", "code_fingerprint", "ANALYSIS_CODE"]

#: the registries ``roughcontact list`` knows
REGISTRIES = ("axes", "models", "area-models", "claims", "quantities")

#: the entry modules of each analysis rule, for :func:`code_fingerprint` (which follows their imports)
ANALYSIS_CODE = {
    "models": ("roughcontact.study.rules.models", "roughcontact.study.rules.measured_spectrum",
               "roughcontact.study.rules.measured_scorecard"),
    "claims": ("roughcontact.study.rules.claims",),
    "area": ("roughcontact.study.rules.area",),
    "histograms_figure": ("roughcontact.study.rules.histograms_figure",),
    "figures": ("roughcontact.study.rules.figures",),
    "model_curves": ("roughcontact.study.rules.model_curves",),
    "summary": ("roughcontact.study.rules.summary",),
    "grid_error": ("roughcontact.study.rules.grid_error",),
    "fine_reference": ("roughcontact.study.rules.fine_reference",),
}


def _number(value):
    """A JSON-safe number: ``inf`` as the string ``"inf"``, ``None`` as it is."""
    if value is None:
        return None
    value = float(value)
    return value if math.isfinite(value) else ("inf" if value > 0 else "-inf")


def listing(kind: str) -> list[dict]:
    """The registered *kind* (one of :data:`REGISTRIES`), in the registry's order, one dict each:

    - axes: ``name``, ``unit``, ``paper`` (the paper's setting; ``None``: a nullable axis's
      ``null``; required axes have none), ``optional``, ``role``, ``tag``, ``kinds``;
    - models: ``name``, ``axes`` (the optional axes it models), ``summary``, ``reference``;
    - area-models: ``name``, ``summary``, ``reference``;
    - claims: ``name`` (its letter), ``statement``;
    - quantities: ``name``, ``units``, ``long_name``, ``dtype``, ``option`` (the configuration key
      that turns it on; ``None``: the run's kind), ``family``.

    ``ValueError`` for another *kind*."""
    if kind == "axes":
        from .config import axes

        return [{"name": a.name, "unit": a.unit, "paper": _number(a.paper) if a.optional else None,
                 "optional": a.optional, "role": a.role, "tag": a.tag, "kinds": list(a.kinds)}
                for a in axes.AXES.values()]
    if kind == "models":
        from ..models import scorecard

        return [{"name": m.name, "axes": list(getattr(m, "axes", ()) or ()), "summary": m.summary,
                 "reference": m.reference} for m in scorecard.models().values()]
    if kind == "area-models":
        from ..models import area

        return [{"name": m.name, "summary": m.summary, "reference": m.reference} for m in area.models().values()]
    if kind == "claims":
        from .claims import claims

        return [{"name": c.letter, "statement": c.statement} for c in claims().values()]
    if kind == "quantities":
        from .quantities import QUANTITIES

        return [{"name": q.name, "units": q.units, "long_name": q.long_name, "dtype": q.dtype, "option": q.option,
                 "family": q.family} for q in QUANTITIES.values()]
    raise ValueError(f"no registry {kind!r}; allowed: {', '.join(REGISTRIES)}")


#: the packages whose modules are imported by discovery (the registries), not by name: every module
#: of their folder counts where the package is imported
DISCOVERED = ("roughcontact.models.scorecard", "roughcontact.models.area", "roughcontact.study.claims",
              "roughcontact.study.config.axes",
              "roughcontact.study.quantities")

#: the folder of the ``roughcontact`` package (this file is ``roughcontact/study/registries.py``)
PACKAGE = Path(__file__).resolve().parents[1]


@functools.lru_cache(maxsize=1)
def _modules() -> dict[str, Path]:
    """``{dotted name: source file}`` of every module of the package (a package by its
    ``__init__.py``), read from the folder: nothing is imported."""
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


@functools.lru_cache(maxsize=None)
def _imports(module: str) -> frozenset:
    """The modules of the package that *module* imports (anywhere in it: a lazy import inside a
    function counts); ``from package import name`` counts the submodule ``package.name`` where
    there is one, else the package."""
    modules = _modules()
    path = modules[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names if alias.name in modules)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[:len(parts) - node.level + 1])
                source = f"{base}.{node.module}" if node.module else base
            else:
                source = node.module or ""
            out.update(f"{source}.{alias.name}" if f"{source}.{alias.name}" in modules else source
                       for alias in node.names)
    return frozenset(name for name in out if name in modules)


def _closure(entries) -> set[Path]:
    """The source files of *entries* and of every module of the package they import, transitively;
    a registry's package (:data:`DISCOVERED`) with every module of its folder."""
    modules = _modules()
    seen, todo = set(), list(entries)
    while todo:
        module = todo.pop()
        if module in seen or module not in modules:
            continue
        seen.add(module)
        if module in DISCOVERED:   # every module of the registry's package: found by discovery
            todo += [name for name in modules if name.rpartition(".")[0] == module]
        todo += sorted(_imports(module))
    return {modules[name] for name in seen}


def code_fingerprint(rule: str) -> str:
    """The SHA-256 (16 hex digits) of the source the analysis *rule* runs: its entry modules
    (:data:`ANALYSIS_CODE`; a rule not listed there, e.g. one of ``workflow/rules/extra/``, its
    module ``roughcontact.study.rules.<rule>``) and every ``roughcontact`` module they import,
    transitively (a package with all the modules of its folder, so a new model or claim module
    counts), by path relative to the package and content; ``ValueError`` for a rule with neither."""
    entries = ANALYSIS_CODE.get(rule)
    if entries is None and f"roughcontact.study.rules.{rule}" in _modules():
        entries = (f"roughcontact.study.rules.{rule}",)
    if entries is None:
        raise ValueError(f"no analysis rule {rule!r} to fingerprint (known: {', '.join(ANALYSIS_CODE)}) and no "
                         f"module roughcontact.study.rules.{rule}")
    digest = hashlib.sha256()
    for path in sorted(_closure(entries)):
        digest.update(str(path.relative_to(PACKAGE)).encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()[:16]
