"""The report's landing page in a real browser on the sweeps a user writes (issue 40 item 3): a
sphere-only, a flat-only and an adhesive sweep, each on a 33² grid, run to its report; headless
Chromium opens the report and shows the answer's sentence on screen at once, a "Not measured,
because …" where a table has no row, and no console error."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from browser import needs_chromium, report_page

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
_COMMON = "grid: {n: 33, length: 1.0, coarse: null}\nsolver: {tol: 1.0e-8}\nfit: {resolved_cells: 4, bootstrap: 50}\n"
SWEEPS = {
    "sphere-only": _COMMON + "hurst: [0.7]\nradius: [0.5]\nh_rms: [9.0e-3]\nseeds: 2\n"
                             "forces: {sphere: {from: 1.0e-4, to: 1.0e-2, count: 5}}\n",
    "flat-only": _COMMON + "hurst: [0.5, 0.8]\nradius: [.inf]\nh_rms: [9.0e-3]\nseeds: 2\n"
                           "forces: {flat: {from: 1.0e-5, to: 1.0e-3, count: 5}}\n",
    # nearly smooth: the scorecard has no resolved rough branch (issue 40's one-byte models.csv)
    "adhesive": _COMMON + "hurst: [0.7]\nradius: [0.8]\nh_rms: [1.0e-7]\nseeds: 1\nwork_of_adhesion: [1.2e-3]\n"
                          "forces: {sphere: {from: 1.0e-4, to: 1.0e-2, count: 5}}\n",
}
#: what each landing page must say, beyond the answer's sentence
EXPECTED = {
    "sphere-only": [],
    "flat-only": ["Not measured, because the sweep has no sphere"],
    "adhesive": [],
}


def _snakemake(args, cwd):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), *args], cwd=cwd,
                          capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]


@pytest.fixture(scope="module", params=sorted(SWEEPS))
def report(request, tmp_path_factory):
    work = tmp_path_factory.mktemp(request.param)
    (work / "sweep.yaml").write_text(SWEEPS[request.param])
    _snakemake(["--configfile", "sweep.yaml", "--cores", "2", "-q"], work)
    _snakemake(["--configfile", "sweep.yaml", "--report", "results/report.html"], work)
    return request.param, work


def test_the_summary_holds_the_answer(report):
    """Without a browser: the landing page's fragment opens with the answer's sentence."""
    name, work = report
    text = (work / "results/summary.html").read_text()
    assert 'class="rc-answer"' in text, name
    if "<table" in text:
        assert text.index('class="rc-answer"') < text.index("<table"), name
    for phrase in EXPECTED[name]:
        assert phrase in text, (name, phrase)


@needs_chromium
def test_the_answer_is_on_screen_as_the_report_opens(report):
    name, work = report
    with report_page(work / "results/report.html", viewport={"width": 1400, "height": 1000}) as (page, errors):
        answer = page.locator(".rc-summary .rc-answer")
        answer.wait_for(timeout=20_000)
        top = answer.evaluate("p => p.getBoundingClientRect().top")
        text = page.locator(".rc-summary").inner_text()
    assert 0 <= top < 1000, f"{name}: the answer is not on screen as the page opens (top at {top} px)"
    assert "This study:" in text, name
    for phrase in EXPECTED[name]:
        assert phrase in text, (name, phrase)
    assert not errors, (name, errors)
