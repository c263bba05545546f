"""What the study's registries hold, and the fingerprint of the code of what they register.

:func:`listing` is what ``roughcontact list axes|models|claims`` prints: the registered sweep
axes (:mod:`roughcontact.study.axes`), models of the scorecard (:mod:`roughcontact.models.scorecard`)
and claims (:mod:`roughcontact.study.claims`), one record each.

:func:`code_fingerprint` hashes the source of the modules an analysis rule runs, so that the
workflow gives it as a ``params`` value: adding or changing a model, a claim or their code makes
Snakemake (its default ``params`` rerun trigger) run that analysis again in an existing results
directory, while the runs, whose ``params`` are their own settings and
:data:`roughcontact.bem.SOLVER_VERSION`, are left as they are.
"""
from __future__ import annotations

import hashlib
import importlib.util
import math
from pathlib import Path

__all__ = ["REGISTRIES", "listing", "code_fingerprint", "ANALYSIS_CODE"]

#: the registries ``roughcontact list`` knows
REGISTRIES = ("axes", "models", "claims")

#: the modules (or packages) each analysis rule runs, for :func:`code_fingerprint`
ANALYSIS_CODE = {
    "models": ("roughcontact.models", "roughcontact.study.scorecard", "roughcontact.study.statistics",
               "roughcontact.study.grid_error", "roughcontact.study.axes"),
    "claims": ("roughcontact.study.claims", "roughcontact.study.statistics", "roughcontact.study.verdicts",
               "roughcontact.study.axes", "roughcontact.models.paper"),
    "figures": ("roughcontact.study.figures", "roughcontact.study.plotting", "roughcontact.models.paper"),
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
        from . import axes

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


def _sources(module: str) -> list[Path]:
    """The ``.py`` files of *module* (every file below a package's folder)."""
    spec = importlib.util.find_spec(module)
    if spec is None or spec.origin is None:
        raise ValueError(f"no module {module!r} to fingerprint")
    origin = Path(spec.origin)
    if spec.submodule_search_locations:   # a package: all of its folder
        return sorted(p for p in origin.parent.rglob("*.py"))
    return [origin]


def code_fingerprint(rule: str) -> str:
    """The SHA-256 (16 hex digits) of the source of the modules the analysis *rule* runs
    (:data:`ANALYSIS_CODE`, a new module in one of their packages included), by path relative to
    the package and content; ``ValueError`` for a rule it does not know."""
    if rule not in ANALYSIS_CODE:
        raise ValueError(f"no analysis rule {rule!r} to fingerprint; known: {', '.join(ANALYSIS_CODE)}")
    digest = hashlib.sha256()
    root = Path(importlib.util.find_spec("roughcontact").origin).parent
    files = sorted({path for module in ANALYSIS_CODE[rule] for path in _sources(module)})
    for path in files:
        digest.update(str(path.relative_to(root)).encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()[:16]
