"""The claim registry: what a claim is (:class:`Claim`), what it may read (:class:`ClaimInputs`; a
table made by a rule of its own: :class:`InputTable`),
the combinations a claim is estimated on (:func:`combinations`, :class:`Combination`) with the
rules of which apply (:func:`sphere`, :func:`at_theory`, ...), the row every claim writes
(:func:`row`) and the loop that runs a claim in isolation (:func:`table_rows`). The paper's setting
is :func:`roughcontact.study.config.axes.paper_setting`, the one test every claim uses."""
from __future__ import annotations

import dataclasses
import logging
import math
from typing import Callable

import numpy as np

from ..._registry import add
from ..config import axes
from ..config.axes import AXES, optional_axes
from ..analysis.statistics import OFF_PAPER, split_verdict, untested, untested_if_degenerate

__all__ = ["Claim", "ClaimInputs", "Combination", "CLAIMS", "InputTable", "TABLES", "register", "register_table",
           "row", "AXIS_COLUMNS", "EFFECT_CLAIM",
           "combinations", "table_rows", "sphere", "flat", "with_crossover", "paper_setting", "at_theory", "all_of",
           "describe", "off_theory", "flat_zeta_rows"]

log = logging.getLogger(__name__)


@dataclasses.dataclass(frozen=True)
class ClaimInputs:
    """What the claims are estimated from (the ``claims`` rule's inputs).

    Attributes
    ----------
    cross : pandas.DataFrame
        ``crossover.csv``: per sphere combination, eq. 16 fitted with free prefactors, the slopes
        and their intervals (:mod:`roughcontact.study.analysis.crossover`); empty without spheres.
    replicates : xarray.Dataset
        Bootstrap replicates of the crossover force (``crossover.nc``).
    zeta : pandas.DataFrame
        ``zeta.csv``: ζ(H) of eq. 11 with its interval.
    study : roughcontact.study.config.settings.StudySettings
        The study's settings (grid, seeds, sweep, fit windows).
    groups : dict or None
        The merged runs, one Dataset per surface kind (``stiffness.nc``).
    exponents : pandas.DataFrame or None
        The local exponents (``exponents.csv``).
    zeta_replicates : xarray.DataArray or None
        Bootstrap replicates of ζ(H) (``zeta.nc``).
    adhesion : pandas.DataFrame or None
        The pull-off table of the adhesive runs (``adhesion/pull_off.csv``,
        :mod:`roughcontact.study.analysis.adhesion`); ``None`` without adhesive runs.
    stickiness : pandas.DataFrame or None
        The stickiness table (``stickiness/stickiness.csv``, :mod:`roughcontact.study.analysis.stickiness`);
        ``None`` without the config's ``stickiness`` section.
    tangential : dict or None
        The tangential runs merged (``tangential/tangential.nc``: groups ``full_stick`` and
        ``partial_slip``, :mod:`roughcontact.study.analysis.tangential`); ``None`` without the axis
        ``poisson``.
    """

    cross: object
    replicates: object
    zeta: object
    study: object
    groups: dict | None = None
    exponents: object = None
    zeta_replicates: object = None
    adhesion: object = None
    stickiness: object = None
    tangential: object = None
    tables: dict = dataclasses.field(default_factory=dict)

    def get(self, need: str):
        """The input *need* (a field of this class, or the name of a registered :class:`InputTable`:
        its rows from :attr:`tables`); ``None`` where the study has none."""
        if need in TABLES:
            return self.tables.get(need)
        return getattr(self, need)


@dataclasses.dataclass(frozen=True)
class InputTable:
    """A table some claim reads beyond the built-in inputs of :class:`ClaimInputs`: made by a rule
    of the workflow (a user's rule, ``workflow/rules/extra/``), given to the ``claims`` rule as an
    input and to the claims as ``inputs.tables[name]`` (a DataFrame; ``None`` without a row).

    Attributes
    ----------
    name : str
        What a :attr:`Claim.needs` names it by.
    path : str
        The file the rule writes, relative to the study's directory (``results/<name>.csv``): the
        ``claims`` rule asks for it, so Snakemake runs the rule that makes it first.
    """

    name: str
    path: str


#: every registered input table, by name, in registration order (the ``claims`` rule's ``tables``)
TABLES: dict[str, InputTable] = {}


def register_table(table: InputTable) -> InputTable:
    """Add *table* to :data:`TABLES` (``ValueError`` for a name registered already)."""
    return add(TABLES, table.name, table, "input table")


@dataclasses.dataclass(frozen=True)
class Combination:
    """One sweep combination of the merged runs, what a per-combination claim estimates from.

    Attributes
    ----------
    kind : str
        ``"sphere"`` or ``"flat"`` (the group of ``inputs.groups`` it belongs to).
    axes : dict
        ``{axis: merged-file coordinate}`` of every sweep dimension of its group (the columns of
        its rows, :func:`row`).
    data : xarray.Dataset
        Its slice of the merged Dataset, dimensions ``(seed, force)`` in that order.
    crossover : pandas.Series or None
        Its row of ``crossover.csv`` (spheres), ``None`` where there is none.
    study : roughcontact.study.config.settings.StudySettings
        The study's settings.
    """

    kind: str
    axes: dict
    data: object
    crossover: object
    study: object
    _lookup: Callable | None = dataclasses.field(default=None, repr=False, compare=False)

    def with_axes(self, **changes):
        """The combination of the same kind with the axes *changes* set (e.g. the paired run
        without a hardness, for a claim on the hardness's effect); ``None`` where the sweep has
        no such combination."""
        where = {**self.axes, **{k: float(v) for k, v in changes.items()}}
        return self._lookup(where) if self._lookup is not None else None


def sphere(combination: Combination):
    """Rule of :attr:`Claim.applies`: sphere combinations only (``None`` elsewhere: no row)."""
    return "" if combination.kind == "sphere" else None


def flat(combination: Combination):
    """Rule of :attr:`Claim.applies`: flat combinations only."""
    return "" if combination.kind == "flat" else None


def with_crossover(combination: Combination):
    """Rule of :attr:`Claim.applies`: sphere combinations with a row of ``crossover.csv``."""
    return "" if combination.kind == "sphere" and combination.crossover is not None else None


def paper_setting(combination: Combination):
    """Rule of :attr:`Claim.applies`: combinations at the paper's setting of every optional axis
    (:func:`roughcontact.study.config.axes.paper_setting`); no row elsewhere."""
    return "" if axes.paper_setting(combination.axes, combination.study.grid.length) else None


def at_theory(combination: Combination):
    """Rule of :attr:`Claim.applies`: every combination; off the paper's setting (:func:`off_theory`)
    its rows keep their measured values and say ``untested`` with the reason."""
    return off_theory(combination.axes, combination.study.grid.length)


def all_of(*rules: Callable) -> Callable:
    """A rule of :attr:`Claim.applies` that is the first of *rules* not to apply: ``None`` (no row)
    if one says so, else the first untested reason, else ``""``."""
    def rule(combination):
        reasons = [r(combination) for r in rules]
        if any(reason is None for reason in reasons):
            return None
        return next((reason for reason in reasons if reason), "")
    rule.__doc__ = "all of: " + ", ".join(r.__name__ for r in rules)
    return rule


@dataclasses.dataclass(frozen=True)
class Claim:
    """One quantitative claim: a whole-study estimator, a per-combination one, or both.

    Attributes
    ----------
    letter : str
        Its label in the claims table (``a`` ... ``m``, ``c'``); rows are ordered by it.
    statement : str
        The claim in words (each row states it for its combination; the statement of its
        ``error`` rows).
    rows : callable or None
        ``rows(inputs) -> list of dict``: the rows estimated from the whole study (each a
        :func:`row`), first among the claim's rows.
    needs : tuple of str
        The fields of :class:`ClaimInputs` it reads besides ``study``, or the names of registered
        :class:`InputTable` (:meth:`ClaimInputs.get`); without one of them (``None``) the claim
        has no rows.
    estimate : callable or None
        ``estimate(combination) -> dict or list of dict``: the rows of one :class:`Combination`
        (a :func:`row` each; ``[]`` for none), for every combination of ``inputs.groups``
        (:func:`combinations`) that *applies* admits. Implies ``needs`` ``groups``.
    applies : callable
        ``applies(combination) -> str or None``, the rule of the combinations *estimate* is
        tested on: ``None``, no row; ``""``, the rows' verdicts stand; otherwise the untested
        verdict text (:func:`roughcontact.study.analysis.statistics.untested`) that replaces the verdict of
        every row of the combination, whose measured values are kept. Rules: :func:`sphere`, :func:`flat`, :func:`with_crossover`,
        :func:`paper_setting`, :func:`at_theory`, combined by :func:`all_of`. Default: spheres.

    Notes
    -----
    :func:`table_rows` runs each claim in isolation: an exception of *rows* gives one row, of
    *estimate* one row per failing combination, with verdict ``error`` and the reason
    ``"<ExceptionType>: <message>"``; every other row of the table is kept.
    """

    letter: str
    statement: str
    rows: Callable | None = None
    needs: tuple = ()
    estimate: Callable | None = None
    applies: Callable = sphere

    @property
    def needed(self) -> tuple:
        """The fields of :class:`ClaimInputs` the claim reads (``groups`` for an *estimate*)."""
        return tuple(self.needs) + (("groups",) if self.estimate is not None and "groups" not in self.needs else ())


#: every registered claim, in registration order (the table orders rows by letter)
CLAIMS: dict[str, Claim] = {}


def register(claim: Claim) -> Claim:
    """Add *claim* to :data:`CLAIMS` (one object per letter)."""
    return add(CLAIMS, claim.letter, claim, "claim")


def __getattr__(name: str):
    """``AXIS_COLUMNS``: the sweep axes of the normal problem (:data:`roughcontact.study.config.axes.AXES`
    whose ``normal`` is true), the columns naming the combination every row rests on (a row of the
    tangential claims also has ``poisson`` and ``friction``); ``EFFECT_CLAIM``: the claim that tests each optional axis off the
    paper's elastic, purely self-affine setting. Both read the axis registry when asked."""
    if name == "AXIS_COLUMNS":
        return axes.names(normal=True)
    if name == "EFFECT_CLAIM":
        return {a.name: a.claim for a in optional_axes() if a.claim}
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def row(claim, statement, measured, low, high, paper, verdict_text, *, sweep="", loads="", note="", **where) -> dict:
    """One row of the claims table; *verdict_text* is ``"verdict: reason"``, an untested one made by
    :func:`roughcontact.study.analysis.statistics.untested` (its named reason is the ``untested_because``
    column; any other untested text raises ``ValueError``: an ``error`` row); *where* the
    combination's axes (missing ones NaN; an axis of the tangential problem only where given, so a
    study without them has the columns it had). The *note* says what the measured value is; it states
    no verdict (a second comparison is a row of its own). A verdict whose interval is a point or
    missing is made ``untested`` here (:func:`~roughcontact.study.analysis.statistics.untested_if_degenerate`),
    whatever the claim said: no verdict without an interval."""
    word, because, reason = split_verdict(untested_if_degenerate(verdict_text, low, high))
    return {"claim": claim, "statement": statement,
            **{k: where.get(k, math.nan) for k, spec in AXES.items() if spec.normal or k in where},
            "measured": measured, "ci_low": low, "ci_high": high, "paper_value": paper,
            "verdict": word, "untested_because": because, "reason": reason,
            "sweep": sweep, "loads": loads, "note": note}


def describe(r, length: float, n: int, seeds: int) -> str:
    """The sweep a row rests on: the combination *r* (axis -> coordinate: ``sphere H, R`` or, for
    ``R = inf``, ``flat H``; h_rms; the optional axes off the paper's setting, :func:`roughcontact.study.config.axes.off_paper`, then the axes of the tangential
    problem it has, by their tag: ``nu``, ``mu``), seeds, grid."""
    radius = float(r["radius"]) if r.get("radius") is not None else math.inf
    body = f"sphere H = {r['hurst']:g}, R = {radius:g}" if math.isfinite(radius) else f"flat H = {r['hurst']:g}"
    text = f"{body}, h_rms = {r['h_rms']:g}"
    for axis, value in axes.off_paper(r, length).items():
        text += f", {axis} = {value:g}"
    for spec in axes.optional_axes(normal=False):
        if spec.name in r:
            text += f", {spec.tag} = {r[spec.name]:g}"
    return f"{text}, {seeds} seeds, n = {n}"


def off_theory(r, length: float) -> str:
    """Why eqs. 11-17 do not apply to the combination *r* ('' where they do): an optional axis off
    the paper's setting (:func:`roughcontact.study.config.axes.off_paper`), named with the claim that
    tests it where there is one. The body's axes (role ``body``, the exponent m) are not among
    them: the claims that use this rule are stated per body of revolution."""
    off = [f"{name} = {value:g}" + (f" (claim {AXES[name].claim} tests it)" if AXES[name].claim else "")
           for name, value in axes.off_paper(r, length).items() if AXES[name].role != "body"]
    if not off:
        return ""
    return untested(OFF_PAPER, "eqs. 11-17 are for an elastic, purely self-affine surface; here " + ", ".join(off))


def combinations(inputs: ClaimInputs, kinds=("sphere", "flat")):
    """Every :class:`Combination` of ``inputs.groups`` of the surface *kinds*, in the order of the
    merged files' dimensions (that of ``crossover.csv``), each with its ``(seed, force)`` slice
    and its row of ``inputs.cross`` (matched on the axes' coordinates)."""
    from ..analysis.ensemble import combinations as dataset_combinations

    cross = inputs.cross if inputs.cross is not None else ()
    for kind in kinds:
        ds = (inputs.groups or {}).get(kind)
        if ds is None:
            continue
        dims = [d for d in ds["stiffness"].dims if d not in ("seed", "force")]
        matched = {}
        if kind == "sphere" and len(cross):
            for _, r in cross.iterrows():
                matched.setdefault(tuple(float(r[d]) if d in r else math.nan for d in dims), r)

        def lookup(where, ds=ds, kind=kind, matched=matched):
            try:
                data = ds.sel(where).transpose("seed", "force")
            except KeyError:
                return None
            return Combination(kind, where, data, _match(matched, tuple(where.values())), inputs.study, lookup)

        for where, data in dataset_combinations(ds):
            yield Combination(kind, where, data, _match(matched, tuple(where.values())), inputs.study, lookup)


def _match(matched: dict, key: tuple):
    """The crossover row of the coordinates *key* (exactly, else within a CSV round trip's digits)."""
    if key in matched:
        return matched[key]
    for other, r in matched.items():
        if np.allclose(other, key, rtol=1e-12, atol=0.0, equal_nan=True):
            return r
    return None


def _error_row(claim: Claim, error: Exception, where: dict) -> dict:
    """The ``error`` row of *claim* for an exception: ``<ExceptionType>: <message>`` on one line."""
    message = " ".join(str(error).split())
    log.warning("claim %s failed%s: %s: %s", claim.letter,
                "".join(f", {k} = {v:g}" for k, v in where.items()), type(error).__name__, message)
    return row(claim.letter, claim.statement, math.nan, math.nan, math.nan, math.nan,
               f"error: {type(error).__name__}: {message}" if message else f"error: {type(error).__name__}", **where)


def _untested(rows: list, reason: str) -> list:
    """*rows* with the verdict replaced by the untested verdict text *reason*
    (:func:`roughcontact.study.analysis.statistics.untested`)."""
    word, because, text = split_verdict(reason)
    return [{**r, "verdict": word, "untested_because": because, "reason": text} for r in rows]


def table_rows(claim: Claim, inputs: ClaimInputs) -> list:
    """The rows of *claim*: its whole-study :attr:`~Claim.rows`, then its :attr:`~Claim.estimate`
    of every combination its rule admits (untested where the rule gives a reason), each in
    isolation (a failing call gives an ``error`` row, :class:`Claim`)."""
    out = []
    if claim.rows is not None:
        try:
            out += claim.rows(inputs)
        except Exception as error:   # noqa: BLE001 -- one claim must not lose the table
            out.append(_error_row(claim, error, {}))
    if claim.estimate is None:
        return out
    for combination in combinations(inputs):
        try:
            reason = claim.applies(combination)
            if reason is None:
                continue
            rows = claim.estimate(combination)
            rows = [rows] if isinstance(rows, dict) else list(rows)
            rows = _untested(rows, reason) if reason else rows
        except Exception as error:   # noqa: BLE001
            out.append(_error_row(claim, error, combination.axes))
            continue
        out += rows
    return out


def flat_zeta_rows(zeta_df):
    """Rows of zeta.csv fitted on flat runs at the paper's setting (not on the sweep's first value of
    an optional axis whose paper value it lacks: :func:`roughcontact.study.analysis.zeta.fit.paper_setting`
    says so in the source)."""
    if not len(zeta_df):
        return zeta_df
    return zeta_df[zeta_df["source"].astype(str) == "flat"]
