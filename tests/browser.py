"""Reading a report as a person does: headless Chromium (Debian's package; .ci/run installs it)
driven by playwright. :data:`needs_chromium` skips a test on a machine without Chromium;
:func:`report_page` opens a report and collects the console's errors and the page's exceptions."""
from __future__ import annotations

import contextlib
import shutil
from pathlib import Path

import pytest

#: the Chromium executable of this machine, or None
CHROMIUM = next((p for p in map(shutil.which, ("chromium", "chromium-browser", "google-chrome")) if p), None)
#: skip marker of the tests that need it
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="no Chromium on this machine (.ci/run installs it)")


@contextlib.contextmanager
def report_page(report: Path, *, viewport: dict | None = None):
    """``(page, errors)``: *report* open in headless Chromium (a ``viewport`` of ``width``/``height``
    if given) and the list its console errors and page exceptions are appended to."""
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright (the test extra) is not installed")
    errors: list[str] = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox"])
        try:
            page = browser.new_page(**({"viewport": viewport} if viewport else {}))
            page.on("console", lambda message: errors.append(message.text) if message.type == "error" else None)
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.goto(Path(report).resolve().as_uri())
            yield page, errors
        finally:
            browser.close()
