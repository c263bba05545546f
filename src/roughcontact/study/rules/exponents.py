"""Rule ``exponents``: ``stiffness.nc`` -> ``exponents.csv`` (the local exponents ``d ln k/d ln F``
with their intervals, :func:`roughcontact.study.analysis.exponents.exponent_table`), its page and
its figure (:func:`roughcontact.study.report.exponents.exponents_figure`)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(cfg, *, stiffness, csv, png, html) -> None:
    """Write the local exponents of the merged runs *stiffness* of the resolved configuration
    *cfg* to *csv* (an empty table with its reason without a resolved window), its page to *html*
    and its figure to *png*."""
    from ..analysis.exponents import empty_reason, exponent_table
    from ..files.io import read_groups, write_csv
    from ..report.exponents import exponents_figure
    from ..report.tables import csv_to_html

    table = exponent_table(read_groups(stiffness), cfg)
    write_csv(table, csv, reason=empty_reason(cfg))
    exponents_figure(table, png)
    csv_to_html(csv, html, "exponents")
    log.info("local exponents: %d rows", len(table))
