"""The landing page's answer: whether the paper's claims hold in this study, in one sentence.

A claim letter of ``claims.csv`` (``a`` … ``m``) groups several *comparisons*, each with its own
statement (claim ``e`` tests the high-force slope against Hertz, against eq. 16 and the body's
prefactor against eq. 7): the tallies and the sentence count comparisons, never letters, and
never add up rows of different tests. :func:`comparisons` groups the rows; :class:`StudySize`
says how large the study is (grid, seeds, combinations, grid error); :func:`answer_html` makes the
sentence that opens the report. Plain data in, HTML out; :mod:`roughcontact.study.report.summary`
lays out the page.
"""
from __future__ import annotations

import collections
import dataclasses
import html
import math

from ..analysis.statistics import NOT_SWEPT, VERDICTS
from .tables import verdict_word

__all__ = ["README_PRESETS", "Comparison", "StudySize", "answer_html", "comparisons"]

#: where the README's headline numbers come from (larger studies than the default one)
README_PRESETS = ("presets/crossover.yaml (the crossover force of the paper's sphere: 400 seeds on 513²), "
                  "presets/paper.yaml (Fig. 3: 50 seeds on 513²) and presets/zeta-law.yaml (ζ(H) of flat "
                  "surfaces)")


@dataclasses.dataclass(frozen=True)
class Comparison:
    """One comparison of the claims table: a claim letter and one of its statements.

    Attributes
    ----------
    claim, statement : str
        The claim's letter and the comparison's statement (``claims.csv``).
    counts : dict
        Verdict word (:data:`~roughcontact.study.analysis.statistics.VERDICTS`) -> rows.
    untested_because : str
        The most frequent reason of its untested rows ("" when none is untested).
    """

    claim: str
    statement: str
    counts: dict
    untested_because: str = ""

    @property
    def tested(self) -> int:
        """Rows with a verdict (consistent or differs)."""
        return self.counts.get("consistent", 0) + self.counts.get("differs", 0)

    @property
    def label(self) -> str:
        """``a`` (its statement, cut to 80 characters)."""
        short = self.statement if len(self.statement) <= 80 else self.statement[:77] + "..."
        return f"{self.claim} ({short})"


def comparisons(claims) -> list[Comparison]:
    """The comparisons of *claims* (a ``claims.csv`` DataFrame, possibly empty), in table order."""
    if not len(claims) or not {"claim", "statement", "verdict"} <= set(claims.columns):
        return []
    out = []
    for (claim, statement), rows in claims.groupby(["claim", "statement"], sort=False):
        words = [verdict_word(v) for v in rows["verdict"]]
        column = next((c for c in ("untested_because", "reason") if c in rows.columns), None)
        reasons = [] if column is None else [str(r) for r, w in zip(rows[column], words)
                                             if w == "untested" and str(r) not in ("", "nan")]
        reason = collections.Counter(reasons).most_common(1)[0][0] if reasons else ""
        out.append(Comparison(str(claim), str(statement), {w: words.count(w) for w in VERDICTS}, reason))
    return out


@dataclasses.dataclass(frozen=True)
class StudySize:
    """How large a study is: the grid, the seeds, the sphere and flat combinations, the grid error.

    Attributes
    ----------
    n : int
        Grid points per side.
    seeds : int
        Surface realisations per combination.
    spheres, flats : int
        Combinations of the sweep's axes with a finite radius and with ``R = inf``.
    coarse : int or None
        The grid-error companion's grid (``grid.coarse``; ``None``: the grid error is not measured).
    """

    n: int
    seeds: int
    spheres: int
    flats: int
    coarse: int | None = None

    @classmethod
    def of(cls, cfg) -> "StudySize":
        """The size of the resolved configuration *cfg*."""
        from ..runs.naming import combinations

        combos = combinations(cfg) if cfg.get("hurst") else []
        spheres = sum(1 for c in combos if math.isfinite(c["radius"]))
        coarse = cfg["grid"].get("coarse")
        return cls(n=int(cfg["grid"]["n"]), seeds=len(cfg.get("seeds", ())), spheres=spheres,
                   flats=len(combos) - spheres, coarse=None if coarse is None or not spheres else int(coarse))

    def sentence(self) -> str:
        """``12 sphere and 6 flat combinations, 6 seeds each, on 385² (grid error against 193²)``."""
        kinds = [f"{count} {kind} combination{'s' if count != 1 else ''}"
                 for count, kind in ((self.spheres, "sphere"), (self.flats, "flat")) if count]
        grid = (f"grid error measured against {self.coarse}²" if self.coarse is not None
                else "grid error not measured" if self.spheres else "no sphere, so no grid error")
        return (f"{' and '.join(kinds) or 'no generated surface'}, {self.seeds} seed{'s' if self.seeds != 1 else ''} "
                f"each, on {self.n}² ({grid})")


def _letters(items: list[Comparison]) -> str:
    """The claim letters of *items*, each once, in table order: ``claims a, b, e``."""
    letters = list(dict.fromkeys(c.claim for c in items))
    return f"claim{'s' if len(letters) != 1 else ''} <b>{html.escape(', '.join(letters))}</b>"


def answer_html(found: list[Comparison], size: StudySize | None = None) -> str:
    """The answer's paragraph: do the paper's claims hold here; which comparisons differ wherever
    tested and which only in some combinations (their claim letters; the table below has each
    comparison's counts); how many are
    untested for want of resolution and how many need an axis the sweep lacks; how large the study
    is and which presets give the README's numbers."""
    tested = [c for c in found if c.tested]
    differs = [c for c in tested if c.counts.get("differs", 0) == c.tested]
    mixed = [c for c in tested if 0 < c.counts.get("differs", 0) < c.tested]
    consistent = len(tested) - len(differs) - len(mixed)
    untested = [c for c in found if not c.tested]
    not_swept = [c for c in untested if c.untested_because == NOT_SWEPT]
    unresolved = [c for c in untested if c.untested_because != NOT_SWEPT]
    if not found:
        verdict = "<b>Not answered:</b> this study tests none of the paper's claims (its claims table is empty)."
    elif not tested:
        verdict = (f"<b>Not answered:</b> none of the {len(found)} comparisons with the paper is tested here (too "
                   "few resolved loads, seeds or combinations); a larger preset decides them.")
    elif not differs and not mixed:
        verdict = (f"<b>Yes, as far as this study resolves:</b> each of the {len(tested)} comparisons with the "
                   "paper that it tests is consistent wherever tested.")
    else:
        verdict = (f"<b>In part:</b> of the {len(tested)} comparisons with the paper that this study tests, "
                   f"{consistent} {'is' if consistent == 1 else 'are'} consistent wherever tested")
        if differs:
            verdict += f"; {len(differs)} differ wherever tested ({_letters(differs)})"
        if mixed:
            verdict += f"; {len(mixed)} differ in some combinations only ({_letters(mixed)})"
        verdict += "."
    parts = [verdict]
    if unresolved:
        reasons = collections.Counter(c.untested_because for c in unresolved if c.untested_because)
        why = f" (most often: {html.escape(reasons.most_common(1)[0][0])})" if reasons else ""
        parts.append(f"{len(unresolved)} more {'are' if len(unresolved) != 1 else 'is'} untested here{why}.")
    if not_swept:
        parts.append(f"{len(not_swept)} need{'' if len(not_swept) != 1 else 's'} an axis or surface kind this "
                     "sweep does not have.")
    if size is not None:
        parts.append(f"This study: {html.escape(size.sentence())}.")
    parts.append(f"The README's numbers come from larger studies: {html.escape(README_PRESETS)}.")
    return '<p class="rc-answer" style="font-size: 15px;">' + " ".join(parts) + "</p>"
