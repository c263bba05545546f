"""What the study's registries hold, and the fingerprint of the code of what they register.

:func:`listing` is what ``roughcontact list axes|models|claims`` prints: the registered sweep
axes (:mod:`roughcontact.study.config.axes`), models of the scorecard (:mod:`roughcontact.models.scorecard`)
and claims (:mod:`roughcontact.study.claims`), one record each.

:func:`code_fingerprint` hashes the source of the modules an analysis rule runs, so that the
workflow gives it as a ``params`` value: adding or changing a model, a claim or their code makes
Snakemake (its default ``params`` rerun trigger) run that analysis again in an existing results
directory, while the runs, whose ``params`` are their own settings and
:data:`roughcontact.bem.SOLVER_VERSION`, are left as they are.
"""
from __future__ import annotations

import ast
import hashlib
import importlib.util
import math
from pathlib import Path

__all__ = ["REGISTRIES", "listing", "code_fingerprint", "ANALYSIS_CODE"]

#: the registries ``roughcontact list`` knows
REGISTRIES = ("axes", "models", "claims")

#: the entry modules of each analysis rule, for :func:`code_fingerprint` (which follows their imports)
ANALYSIS_CODE = {
    "models": ("roughcontact.study.analysis.scorecard", "roughcontact.study.analysis.measured_scorecard",
               "roughcontact.study.analysis.measured_spectrum"),
    "claims": ("roughcontact.study.claims",),
    "figures": ("roughcontact.study.report.figures",),
    "summary": ("roughcontact.study.report.summary",),
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
    - claims: ``name`` (its letter), ``statement``.

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
    if kind == "claims":
        from .claims import claims

        return [{"name": c.letter, "statement": c.statement} for c in claims().values()]
    raise ValueError(f"no registry {kind!r}; allowed: {', '.join(REGISTRIES)}")


def _file_of(module: str) -> Path | None:
    """The source file of *module* (a package's ``__init__.py``), ``None`` where there is none."""
    spec = importlib.util.find_spec(module)
    return None if spec is None or spec.origin is None else Path(spec.origin)


def _imports(path: Path, module: str) -> set[str]:
    """The ``roughcontact`` modules the source *path* of *module* imports (anywhere in it: a lazy
    import inside a function counts), by name; ``from package import name`` counts the submodule
    ``package.name`` where there is one, else the package."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names if alias.name.startswith("roughcontact"))
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[:len(parts) - node.level + 1])
                source = f"{base}.{node.module}" if node.module else base
            else:
                source = node.module or ""
            if not source.startswith("roughcontact"):
                continue
            for alias in node.names:
                name = f"{source}.{alias.name}"
                out.add(name if importlib.util.find_spec(source) and _is_module(name) else source)
    return out


def _is_module(name: str) -> bool:
    try:
        return importlib.util.find_spec(name) is not None
    except (ImportError, ValueError):   # a name that is not a module (a function of the package)
        return False


#: the packages whose modules are imported by discovery (the registries), not by name: every module
#: of their folder counts where the package is imported
DISCOVERED = ("roughcontact.models.scorecard", "roughcontact.study.claims", "roughcontact.study.config.axes")


def _closure(entries) -> set[Path]:
    """The source files of *entries* and of every ``roughcontact`` module they import, transitively;
    a registry's package (:data:`DISCOVERED`) with every module of its folder."""
    seen, files, todo = set(), set(), list(entries)
    while todo:
        module = todo.pop()
        if module in seen:
            continue
        seen.add(module)
        path = _file_of(module)
        if path is None:
            continue
        files.add(path)
        if module in DISCOVERED:   # every module of the registry's package: found by discovery
            todo += [f"{module}.{p.stem}" for p in path.parent.glob("*.py") if p.name != "__init__.py"]
        todo += sorted(_imports(path, module))
    return files


def code_fingerprint(rule: str) -> str:
    """The SHA-256 (16 hex digits) of the source the analysis *rule* runs: its entry modules
    (:data:`ANALYSIS_CODE`) and every ``roughcontact`` module they import, transitively (a
    package with all the modules of its folder, so a new model or claim module counts), by path
    relative to the package and content; ``ValueError`` for a rule it does not know."""
    if rule not in ANALYSIS_CODE:
        raise ValueError(f"no analysis rule {rule!r} to fingerprint; known: {', '.join(ANALYSIS_CODE)}")
    digest = hashlib.sha256()
    root = _file_of("roughcontact").parent
    for path in sorted(_closure(ANALYSIS_CODE[rule])):
        digest.update(str(path.relative_to(root)).encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()[:16]
