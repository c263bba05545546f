"""Truth as a property (issue 48): what the landing page and the tables say of a finished study agrees
with the one table that holds each fact. :func:`check_report_truth` is run by the workflow fuzzer
(``tests/test_sweep_space.py``) on every sweep it draws and on its named zoo, and on fixed study
directories by ``tests/test_report_truth.py``.

The invariants, each stated against its table:

* no verdict without an interval: a ``consistent`` or ``differs`` row of ``claims.csv``, of the
  crossover table's two predictions and of the scorecard's systematic verdicts has a finite interval
  of positive width;
* the landing page's tallies (one row per comparison) are ``claims.csv``'s counts, row by row;
* the answer's counts add up: the comparisons it names (tested, then the other ones by reason)
  are those of ``claims.csv``, and the untested ones' counts per reason sum to the untested ones;
* the grid error the answer states is the statement of ``grid_error.csv``
  (:func:`roughcontact.study.analysis.grid_error.statement`);
* each recommended model's ``holds`` cell on the landing page is ``models.csv``'s ``holds``.
"""
from __future__ import annotations

import html
import math
import re
from html.parser import HTMLParser
from pathlib import Path

import numpy as np

from roughcontact.study.analysis.grid_error import statement
from roughcontact.study.files.io import read_csv
from roughcontact.study.report import answer

VERDICT_WORDS = ("consistent", "differs")


class _Tables(HTMLParser):
    """Every ``<table>`` of a page as a list of rows of cell texts (``th`` and ``td``)."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.tables, self._row, self._cell = [], None, None

    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self._row = []
        elif tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append(" ".join("".join(self._cell).split()))
            self._cell = None
        elif tag == "tr" and self._row is not None:
            self.tables[-1].append(self._row)
            self._row = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def tables(page: str) -> list[list[list[str]]]:
    parser = _Tables()
    parser.feed(page)
    return parser.tables


def text(page: str) -> str:
    """The page's text, tags removed, whitespace collapsed."""
    return " ".join(html.unescape(re.sub(r"<[^>]+>", " ", page)).split())


def _with_interval(frame, verdict, low, high) -> list[str]:
    """The rows of *frame* whose *verdict* column is consistent/differs without a positive interval."""
    if verdict not in frame or low not in frame or high not in frame:
        return []
    bad = []
    for _, row in frame.iterrows():
        if str(row[verdict]).split(":")[0] in VERDICT_WORDS:
            lo, hi = float(row[low]), float(row[high])
            if not (math.isfinite(lo) and math.isfinite(hi) and hi > lo):
                bad.append(f"{verdict} = {row[verdict]} on [{lo}, {hi}]")
    return bad


def verdict_problems(results: Path) -> list[str]:
    """Verdicts without an interval in claims.csv, crossover.csv and models.csv."""
    problems = []
    claims = read_csv(results / "claims.csv")
    problems += [f"claims.csv: {p}" for p in _with_interval(claims, "verdict", "ci_low", "ci_high")]
    cross = read_csv(results / "crossover.csv")
    for column in ("verdict_fit", "verdict_estimate"):
        problems += [f"crossover.csv: {p}" for p in _with_interval(cross, column, "Ftr_ci_low", "Ftr_ci_high")]
    models = read_csv(results / "models.csv")
    for branch in ("low", "high"):
        problems += [f"models.csv: {p}" for p in _with_interval(
            models, f"systematic_{branch}_verdict", f"systematic_{branch}_ci_low", f"systematic_{branch}_ci_high")]
    return problems


def landing_problems(results: Path, coarse) -> list[str]:
    """What the landing page (summary.html) says that its tables do not."""
    page = (results / "summary.html").read_text()
    words = text(page)
    claims = read_csv(results / "claims.csv")
    found = answer.comparisons(claims)
    problems = []
    # the tallies: one row per comparison, its counts those of claims.csv
    tallies = next((t for t in tables(page) if t and t[0][:2] == ["claim", "comparison"]), None)
    if found:
        if tallies is None:
            return ["summary.html: no tally table for a claims table with rows"]
        header, rows = tallies[0], tallies[1:]
        if len(rows) != len(found):
            problems.append(f"summary.html: {len(rows)} tally rows for {len(found)} comparisons")
        for row, comparison in zip(rows, found):
            for word, cell in zip(header[2:], row[2:]):
                shown = int(cell.split()[0]) if cell else 0
                if shown != comparison.counts.get(word, 0):
                    problems.append(f"summary.html: claim {comparison.claim} shows {shown} {word}, "
                                    f"claims.csv has {comparison.counts.get(word, 0)}")
    # the answer's counts add up
    tested = sum(1 for c in found if c.tested)
    untested = len(found) - tested
    match = re.search(r"none of the (\d+) comparisons", words)
    if match and (int(match.group(1)) != len(found) or tested):
        problems.append(f"answer: 'none of the {match.group(1)}' for {len(found)} comparisons, {tested} tested")
    match = re.search(r"of the (\d+) comparisons with the paper that (?:this study|it) tests", words)
    if match and int(match.group(1)) != tested:
        problems.append(f"answer: {match.group(1)} tested comparisons, claims.csv has {tested}")
    match = re.search(r"The other (\d+) (?:are|is) untested here", words)
    if tested and untested and (not match or int(match.group(1)) != untested):
        problems.append(f"answer: the other untested comparisons are not {untested}")
    listing = re.search(r"(?:is tested here|untested here): (.*?)\. This study", words)
    if untested and listing:
        counts = [int(n) for n in re.findall(r"(?:^|; )(\d+) ", listing.group(1))]
        if sum(counts) != untested:
            problems.append(f"answer: untested counts {counts} do not add up to {untested}")
    # the grid error, stated once
    grid_csv = results / "grid_error.csv"
    said = statement(read_csv(grid_csv) if coarse is not None and grid_csv.exists() else None, coarse)
    spheres = int(np.isfinite(claims.get("radius", [])).any()) if len(claims) else 0
    if spheres and "This study:" in words and said.sentence() not in words:
        problems.append(f"answer: the grid error is not stated as grid_error.csv says: {said.sentence()!r}")
    # each recommended model's holds
    models = read_csv(results / "models.csv")
    recommended = next((t for t in tables(page) if t and t[0][:3] == ["combination", "model", "holds"]), None)
    if recommended is not None and len(models) and "holds" in models:
        for row in recommended[1:]:
            model, cell = row[1], row[2]
            if cell in ("—", ""):
                continue
            rows = models[(models["model"] == model) & models["recommended"].astype(bool)] \
                if "recommended" in models else models[models["model"] == model]
            if not len(rows):
                continue
            holds = {str(v).strip().lower() == "true" for v in rows["holds"]}
            if (cell == "yes") not in holds:
                problems.append(f"summary.html: {model} holds = {cell!r}, models.csv: {sorted(holds)}")
    return problems


def check_report_truth(work: Path, coarse=None) -> None:
    """Assert every invariant of the module docstring on the finished study in *work*."""
    results = Path(work) / "results"
    problems = verdict_problems(results)
    if (results / "summary.html").exists() and (results / "claims.csv").exists():
        problems += landing_problems(results, coarse)
    assert not problems, "\n".join(problems)
