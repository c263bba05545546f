"""The claims page of the report: what :func:`roughcontact.study.claims.claims_table` estimates, as
an HTML page (:mod:`roughcontact.study.report.tables`) with its lead. The ``claims`` rule
(:mod:`roughcontact.study.rules.claims`) reads the inputs and writes ``claims.csv`` and this page.
"""
from __future__ import annotations

from .tables import write_html_table

__all__ = ["CLAIMS_LEAD", "write_claims_page"]


#: the lead paragraph of the claims page of the report
CLAIMS_LEAD = ("One row per quantitative claim of Pohrt & Popov (2013) and per sweep combination it is tested "
               "on: the measured value with its 95 % bootstrap-over-seeds interval (ci_low, ci_high), the "
               "paper's value and the verdict: consistent (the paper's value lies inside the interval, or for a "
               "bound the interval lies on the claimed side), differs (it is excluded), untested (the claim is "
               "not decided; untested_because names why: not swept, off the paper's setting, interval holds the "
               "threshold, unresolved, outside the model's range or no prediction, and the reason gives the "
               "detail) or error (the claim's estimate failed; the reason is the exception, the workflow's log "
               "names the claim). The note says what the measured or paper value is; a second comparison (claim "
               "(b) with the fitted zeta, the slopes of eq. 16 itself) is a row of its own. claims.csv holds "
               "every digit.")


def write_claims_page(table, path) -> None:
    """The report's page of the claims *table* (:func:`roughcontact.study.claims.claims_table`):
    :data:`CLAIMS_LEAD` and the columns that say the verdict first."""
    write_html_table(table, path, title="Claims of the paper", lead=CLAIMS_LEAD,
                     first=("claim", "statement", "verdict", "untested_because", "measured", "ci_low", "ci_high",
                            "paper_value", "reason"))
