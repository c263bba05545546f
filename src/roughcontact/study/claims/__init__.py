"""The paper's claims as a table (``claims.csv``): one row per quantitative claim
and per combination it is tested on, with the measured value, its 95 %
interval, the paper's value, the verdict (:mod:`roughcontact.study.analysis.statistics`), why it is untested
(``untested_because``, a word of :data:`roughcontact.study.analysis.statistics.UNTESTED_BECAUSE`, empty on the
other rows) and the sweep and loads it rests on. A row's note says what its measured or paper value
is and states no verdict: claim (b) with the fitted ζ and the slopes of eq. 16 itself ((d), (e))
are rows of their own. Rows (a)–(f) of a combination off the paper's setting of an
optional axis (:func:`roughcontact.study.config.axes.off_paper`; the body's exponent
aside) keep their measured values but say ``untested`` and name the axis: the
paper's equations are for an elastic, purely self-affine surface, and claims
(i)–(k) test those axes against the same seeds without them; (g), (h) and (l)
leave such combinations out.

Claims (Pohrt & Popov 2013): (a) eq. 16 describes the BEM ensemble; (b) the
crossover force of eq. 17; (c) ζ(H) ≈ 1.7/(H+1) (eq. 13); (d) the low-force
slope 1/(H+1) and (e) the high-force slope 1/3 (with the Hertz prefactor);
(f) below F_tr roughness lowers k against the smooth sphere (Conclusions);
(g) the scaling of F_tr with R and h_rms implied by eq. 17; (h) eq. 18's λ
for H → 0. Beyond the paraboloid (Conclusions): (a), (b), (d)–(f) per body of
revolution and for 1 < H < 2; (i) a short-wavelength cutoff leaves k unchanged
where the contact is larger than the cutoff; (j) a roll-off's effect on the
low-force slope; (k) elasticity on all scales is not crucial (a hardness cap
leaves the unloading and the loading stiffness unchanged); (l), (m) the local
exponents of flat surfaces against Pastewka et al. (2013) and Pohrt & Popov (2012).
Tangential contact (axes ``poisson``, ``friction``): (r) the full-stick k_t/k_n against Mindlin's
2(1−ν)/(2−ν) on each branch; (s) k_t(Q) against Cattaneo–Mindlin above the crossover and
Ciavarella–Jäger below it; (t) the largest micro-slip against Grzemba et al.'s μ d E*/G*.
Real contact area (Hyun et al. 2004; Pastewka & Robbins 2016): (u) between the one-asperity
regime's end F_1 and the crossover A = κ F/(E* h′_rms) with κ ≈ 2; (v) above the crossover A → π a²
(Hertz); (w) below F_1 one summit, A ∝ F^(2/3); each at the loads whose area is resolved
(:mod:`roughcontact.study.analysis.area`).

Each claim is one :class:`Claim` (its letter, statement, the inputs it needs and its estimator:
``rows(inputs)`` over the whole study, or ``estimate(combination)`` over one sweep combination
with ``applies``, the rule of the combinations it is tested on; the registry loops over the
combinations), registered by a module of
this package: :mod:`roughcontact.study.claims.paper` (a)-(h), :mod:`roughcontact.study.claims.zeta_law` (c'), :mod:`roughcontact.study.claims.effects` (i)-(k),
:mod:`roughcontact.study.claims.exponents` (l), (m), :mod:`roughcontact.study.claims.adhesion` (n)-(q),
:mod:`roughcontact.study.claims.tangential` (r)-(t), :mod:`roughcontact.study.claims.area` (u)-(w).
:func:`claims_table` loops over the registry; a new claim is one
object in one module (worked example in the package guide, ``docs/guide/package.md``); a claim
that reads a table of its own registers it (:class:`InputTable`, made by a rule of the user's). A claim
that raises gives rows with the verdict ``error`` and the exception as the reason; the others'
rows are kept. The ``claims`` rule's files, ``claims.csv`` and its page, are written by
:mod:`roughcontact.study.report.claims`: this package estimates and imports nothing of the report.
"""
from __future__ import annotations

from ..._registry import import_modules
from ..config.settings import StudySettings
from .registry import (CLAIMS, TABLES, Claim, ClaimInputs, Combination, InputTable, register, register_table, row,
                       table_rows)

__all__ = ["Claim", "ClaimInputs", "Combination", "CLAIMS", "InputTable", "TABLES", "register", "register_table", "row",
           "claims", "claims_table", "failed", "input_tables", "EQ16_TOLERANCE", "prl2012_exponent", "CLAIMS_COLUMNS",
           "NO_CLAIM"]

#: the modules of the claims of Pohrt & Popov (2013) and the studies that extend them, in the order
#: they are imported (each registers its claims); further modules of this package follow by name
_ORDER = ("paper", "zeta_law", "effects", "exponents", "adhesion", "tangential", "area")
_loaded: list = []


def claims() -> dict[str, Claim]:
    """``{letter: Claim}`` of every registered claim in letter order (every module of this package
    imported once)."""
    if not _loaded:
        import_modules(__name__, __path__, _ORDER)
        _loaded.append(True)
    return dict(sorted(CLAIMS.items()))


def input_tables() -> dict[str, InputTable]:
    """``{name: InputTable}`` of every table a registered claim may read beyond the built-in inputs
    (every module of this package imported once), in registration order: the ``claims`` rule's
    ``tables`` input."""
    claims()
    return dict(TABLES)


def __getattr__(name: str):
    """Constants of the claim modules, where they are defined: ``EQ16_TOLERANCE`` and
    ``prl2012_exponent`` (claims (a), (m)); ``EFFECT_CLAIM`` and ``AXIS_COLUMNS`` (from the axis
    registry)."""
    if name in ("EQ16_TOLERANCE", "LAMBDA_EQ17", "LAMBDA_GT"):
        from . import paper
        return getattr(paper, name)
    if name == "prl2012_exponent":
        from .exponents import prl2012_exponent
        return prl2012_exponent
    if name in ("EFFECT_CLAIM", "AXIS_COLUMNS"):
        from . import registry
        return getattr(registry, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def claims_table(cross, reps, zeta_df, study, groups: dict | None = None, exponents=None,
                 zeta_replicates=None, adhesion=None, stickiness=None, tangential=None, tables=None):
    """``claims.csv``: one row per quantitative claim (every registered :class:`Claim` whose
    inputs are given) and per combination it is tested on, with the measured value, its 95 %
    interval, the paper's value, the verdict and the sweep and loads it rests on; ordered by
    the claim's letter, then as each claim gives its rows. Each claim runs in isolation
    (:func:`~roughcontact.study.claims.registry.table_rows`): one that raises has ``error`` rows
    with the exception as the reason, and every other row is kept. *tables*: ``{name: DataFrame}``
    of the registered input tables (:func:`input_tables`; ``None`` for one without a row)."""
    import pandas as pd

    inputs = ClaimInputs(cross=cross, replicates=reps, zeta=zeta_df, study=StudySettings.of(study), groups=groups,
                         exponents=exponents, zeta_replicates=zeta_replicates, adhesion=adhesion,
                         stickiness=stickiness, tangential=tangential, tables=dict(tables or {}))
    rows = []
    for claim in claims().values():
        if all(inputs.get(need) is not None for need in claim.needed):
            rows += table_rows(claim, inputs)
    if not rows:
        return pd.DataFrame(columns=CLAIMS_COLUMNS)
    return pd.DataFrame(rows).sort_values("claim", kind="stable", ignore_index=True)


def failed(table) -> list:
    """The letters of the claims with an ``error`` row in *table* (:func:`claims_table`), in order."""
    if not len(table):
        return []
    return sorted(set(table.loc[table["verdict"] == "error", "claim"]))


#: the columns of claims.csv around the sweep axes (the header of a table without a row)
CLAIMS_COLUMNS = ("claim", "statement", "hurst", "radius", "h_rms", "measured", "ci_low", "ci_high", "paper_value",
                  "verdict", "untested_because", "reason", "sweep", "loads", "note")

#: why claims.csv has no row
NO_CLAIM = "no claim of the paper has what it needs in this sweep"
