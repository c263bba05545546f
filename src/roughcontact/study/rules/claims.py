"""Rule ``claims``: the analysis' tables -> ``claims.csv`` and its page, the paper's claims with their
verdicts (:func:`roughcontact.study.claims.claims_table` estimates and judges;
:func:`roughcontact.study.report.claims.write_claims_page` writes the page). The claims that failed
are logged."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def _rows_or_none(path):
    """The table *path* (:func:`roughcontact.study.files.io.read_csv`), or ``None`` without a path or
    a row: the claims that need it are then not in the table."""
    from ..files.io import read_csv

    table = read_csv(path) if path else None
    return table if table is not None and len(table) else None


def run(cfg, *, crossover, replicates, zeta, zeta_replicates, stiffness, exponents, csv, html, pull_off=None,
        stickiness=None, tangential=None, tables=()) -> None:
    """Write the claims table of the resolved configuration *cfg* to *csv* and its page to *html*.

    Inputs (paths): *crossover* (``crossover.csv``) and *replicates* (``crossover.nc``, its
    bootstrap replicates), *zeta* (``zeta.csv``) and *zeta_replicates* (``zeta.nc``), the merged
    runs *stiffness*, the local *exponents*; ``None`` where the study has none: *pull_off*
    (``pull_off.csv`` of the adhesive runs), *stickiness* (``stickiness.csv`` of the config's
    ``stickiness`` section), *tangential* (``tangential.nc``, the axis ``poisson``); *tables*: the
    registered input tables' paths, in the order of :func:`roughcontact.study.claims.input_tables`.
    """
    import pandas as pd
    import xarray as xr

    from ..claims import NO_CLAIM, claims_table, failed, input_tables
    from ..files.io import read_csv, read_groups, write_csv
    from ..report.claims import write_claims_page

    cross = read_csv(crossover)
    with xr.open_dataset(replicates, engine="netcdf4") as reps, xr.open_dataset(zeta_replicates, engine="netcdf4") as zds:
        table = claims_table(cross, reps.load(), pd.read_csv(zeta), cfg, read_groups(stiffness), read_csv(exponents),
                             zds["zeta_replicates"].load(),
                             adhesion=_rows_or_none(pull_off), stickiness=_rows_or_none(stickiness),
                             tangential=read_groups(tangential) if tangential else None,
                             tables={name: _rows_or_none(path) for name, path in zip(input_tables(), tables)})
    write_csv(table, csv, reason=NO_CLAIM)
    write_claims_page(table, html)
    log.info("claims:\n%s", table.to_string())
    if failed(table):
        log.warning("claims that failed (verdict error, the reason is the exception): %s", ", ".join(failed(table)))
