"""The claims table's files (the ``claims`` rule): what :func:`roughcontact.study.claims.claims_table`
estimates, written for the report as ``claims.csv`` and the same table as an HTML page
(:mod:`roughcontact.study.report.tables`).

The claims estimate and judge; this module reads the rule's inputs, writes its outputs and logs the
claims that failed, as :mod:`roughcontact.study.report.scorecard` does for the ``models`` rule.
"""
from __future__ import annotations

import logging

from ..claims import NO_CLAIM, claims_table, failed, input_tables
from .tables import write_html_table

__all__ = ["CLAIMS_LEAD", "run_claims"]

log = logging.getLogger(__name__)


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


def _rows_or_none(path):
    """The table *path* (:func:`roughcontact.study.files.io.read_csv`), or ``None`` without a path or
    a row: the claims that need it are then not in the table."""
    from ..files.io import read_csv

    table = read_csv(path) if path else None
    return table if table is not None and len(table) else None


def run_claims(study, crossover_csv, crossover_nc, zeta_csv, zeta_nc, stiffness_nc, exponents_csv, out_csv, out_html,
               pull_off_csv=None, stickiness_csv=None, tangential_nc=None, tables=()):
    """``claims`` rule: crossover.csv, its replicates, zeta.csv and zeta.nc (its replicates), the
    runs, the local exponents, the adhesive runs' pull-off table (*pull_off_csv*, or ``None``
    without adhesive runs) and the stickiness table (*stickiness_csv*, or ``None`` without the
    config's ``stickiness`` section), the tangential runs (*tangential_nc*, or ``None`` without the
    axis ``poisson``) and the registered input tables (*tables*: their paths, in the order of
    :func:`roughcontact.study.claims.input_tables`) -> claims.csv and the same table as an HTML
    page for the report (:mod:`roughcontact.study.report.tables`)."""
    import pandas as pd
    import xarray as xr

    from ..files.io import read_csv, read_groups, write_csv

    cross = read_csv(crossover_csv)
    with xr.open_dataset(crossover_nc, engine="netcdf4") as reps, xr.open_dataset(zeta_nc, engine="netcdf4") as zds:
        exponents = read_csv(exponents_csv)
        table = claims_table(cross, reps.load(), pd.read_csv(zeta_csv), study, read_groups(stiffness_nc), exponents,
                             zds["zeta_replicates"].load(),
                             adhesion=_rows_or_none(pull_off_csv), stickiness=_rows_or_none(stickiness_csv),
                             tangential=read_groups(tangential_nc) if tangential_nc else None,
                             tables={name: _rows_or_none(path) for name, path in zip(input_tables(), tables)})
    write_csv(table, out_csv, reason=NO_CLAIM)
    write_html_table(table, out_html, title="Claims of the paper", lead=CLAIMS_LEAD,
                     first=("claim", "statement", "verdict", "untested_because", "measured", "ci_low", "ci_high",
                            "paper_value", "reason"))
    log.info("claims:\n%s", table.to_string())
    if failed(table):
        log.warning("claims that failed (verdict error, the reason is the exception): %s", ", ".join(failed(table)))
