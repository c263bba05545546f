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

from ..analysis.grid_error import GridErrorStatement
from ..analysis.statistics import (HOLDS_THRESHOLD, NO_PREDICTION, NOT_SWEPT, OFF_PAPER, OUT_OF_RANGE, UNRESOLVED,
                                   VERDICTS)
from .tables import verdict_word

__all__ = ["README_PRESETS", "Comparison", "StudySize", "answer_html", "comparisons"]

#: where the README's headline numbers come from (larger studies than the default one)
README_PRESETS = ("presets/crossover.yaml (the crossover force of the paper's sphere: 400 seeds on 513²), "
                  "presets/paper.yaml (Fig. 3: 50 seeds on 513²), presets/zeta-law.yaml (ζ(H) of flat "
                  "surfaces) and, for the model that holds within 3 % on both branches (contact_scale_tail), "
                  "presets/heldout-branches-a.yaml, heldout-branches-b.yaml and validation-branches*.yaml "
                  "(docs/results/fractal_branch_model.md); a study's own scorecard judges only its own sweep")


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
    grid_error : GridErrorStatement or None
        The study's grid error as stated once
        (:func:`roughcontact.study.analysis.grid_error.statement`); ``None``: not measured, no reason
        known.
    """

    n: int
    seeds: int
    spheres: int
    flats: int
    grid_error: GridErrorStatement | None = None

    @classmethod
    def of(cls, cfg, grid_error: GridErrorStatement | None = None) -> "StudySize":
        """The size of the resolved configuration *cfg*, with its grid error's statement."""
        from ..runs.naming import combinations

        combos = combinations(cfg) if cfg.get("hurst") else []
        spheres = sum(1 for c in combos if math.isfinite(c["radius"]))
        return cls(n=int(cfg["grid"]["n"]), seeds=len(cfg.get("seeds", ())), spheres=spheres,
                   flats=len(combos) - spheres, grid_error=grid_error)

    def sentence(self) -> str:
        """``12 sphere and 6 flat combinations, 6 seeds each, on 385² (grid error measured against
        193²: up to 16 % …)``; the grid error's words are its statement's."""
        kinds = [f"{count} {kind} combination{'s' if count != 1 else ''}"
                 for count, kind in ((self.spheres, "sphere"), (self.flats, "flat")) if count]
        grid = (self.grid_error.sentence() if self.grid_error is not None and self.spheres
                else "grid error not measured" if self.spheres else "no sphere, so no grid error")
        return (f"{' and '.join(kinds) or 'no generated surface'}, {self.seeds} seed{'s' if self.seeds != 1 else ''} "
                f"each, on {self.n}² ({grid})")


def _letters(items: list[Comparison]) -> str:
    """The claim letters of *items*, each once, in table order: ``claims a, b, e``."""
    letters = list(dict.fromkeys(c.claim for c in items))
    return f"claim{'s' if len(letters) != 1 else ''} <b>{html.escape(', '.join(letters))}</b>"


#: why a comparison is untested, in the answer's words (singular, plural), by ``untested_because``
_UNTESTED_WORDS = {
    UNRESOLVED: ("is unresolved (too few resolved loads, seeds or contact cells: a larger study decides it)",
                 "are unresolved (too few resolved loads, seeds or contact cells: a larger study decides them)"),
    NOT_SWEPT: ("needs an axis, surface kind or pairing this sweep does not have",
                "need an axis, surface kind or pairing this sweep does not have"),
    OFF_PAPER: ("is off the paper's setting (eqs. 11-17 are for an elastic, purely self-affine surface)",
                "are off the paper's setting (eqs. 11-17 are for an elastic, purely self-affine surface)"),
    HOLDS_THRESHOLD: ("has an interval that holds the threshold (more seeds may decide it)",
                      "have an interval that holds the threshold (more seeds may decide them)"),
    OUT_OF_RANGE: ("lies outside its model's stated range", "lie outside their model's stated range"),
    NO_PREDICTION: ("has no paper value to compare with here", "have no paper value to compare with here"),
}


def _why_untested(untested: list[Comparison]) -> str:
    """``15 are unresolved (…), 10 need an axis …``: the untested comparisons counted by their
    (most frequent) reason, largest count first; the counts add up to ``len(untested)``."""
    counts = collections.Counter(c.untested_because or UNRESOLVED for c in untested)
    words = []
    for because, count in counts.most_common():
        singular, plural = _UNTESTED_WORDS.get(because, (f"is untested ({because})", f"are untested ({because})"))
        words.append(f"{count} {singular if count == 1 else plural}")
    return html.escape("; ".join(words))


def answer_html(found: list[Comparison], size: StudySize | None = None) -> str:
    """The answer's paragraph: do the paper's claims hold here; which comparisons differ wherever
    tested and which only in some combinations (their claim letters; the table below has each
    comparison's counts); the untested ones counted by their reason (:func:`_why_untested`: the
    counts add up, each reason the one its rows name); how large the study is, its grid error as
    stated once, and which presets give the README's numbers."""
    tested = [c for c in found if c.tested]
    differs = [c for c in tested if c.counts.get("differs", 0) == c.tested]
    mixed = [c for c in tested if 0 < c.counts.get("differs", 0) < c.tested]
    consistent = len(tested) - len(differs) - len(mixed)
    untested = [c for c in found if not c.tested]
    if not found:
        verdict = "<b>Not answered:</b> this study tests none of the paper's claims (its claims table is empty)."
    elif not tested:
        verdict = (f"<b>Not answered:</b> none of the {len(found)} comparisons with the paper is tested here: "
                   f"{_why_untested(untested)}.")
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
    if tested and untested:
        parts.append(f"The other {len(untested)} {'are' if len(untested) != 1 else 'is'} untested here: "
                     f"{_why_untested(untested)}.")
    if size is not None:
        parts.append(f"This study: {html.escape(size.sentence())}.")
    parts.append(f"The README's numbers come from larger studies: {html.escape(README_PRESETS)}.")
    return '<p class="rc-answer" style="font-size: 15px;">' + " ".join(parts) + "</p>"
