"""Rule ``fine_reference``: the study's ``stiffness.nc``, its companion's on ``grid.fine`` (and on
``grid.coarse``) -> ``fine_reference.csv`` and its page
(:func:`roughcontact.study.analysis.fine_reference.fine_reference`)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(cfg, *, stiffness, fine, csv, html, coarse=None) -> None:
    """Write the fine reference of the study's small loads to *csv* and its page to *html*:
    *stiffness* is the study's ``stiffness.nc``, *fine* the fine companion's, *coarse* the coarse
    companion's (``None`` without ``grid.coarse``; with it, Richardson's extrapolation over the
    three grids)."""
    import pandas as pd

    from ..analysis.fine_reference import FINE_REFERENCE_COLUMNS, fine_reference
    from ..analysis.grid_error import empty_reason
    from ..config.settings import StudySettings
    from ..files.io import read_groups, write_csv
    from ..report.tables import csv_to_html
    from ..runs import naming

    study = StudySettings.of(cfg)
    fit = study.fit
    groups, fine_groups = read_groups(stiffness), read_groups(fine)
    reason = empty_reason(groups, fine_groups)
    if reason:
        table = pd.DataFrame(columns=[*naming.AXES["sphere"], *FINE_REFERENCE_COLUMNS])
    else:
        coarse_sphere = read_groups(coarse)["sphere"] if coarse else None
        table = fine_reference(groups["sphere"], fine_groups["sphere"], coarse_sphere, n=study.grid.n,
                               n_fine=study.grid.fine, n_coarse=study.grid.coarse, min_cells=fit.resolved_cells,
                               bootstrap=fit.bootstrap, confidence=fit.confidence)
    write_csv(table, csv, reason=reason)
    csv_to_html(csv, html, "fine_reference")
    log.info("fine reference on %d²: %d loads of %d sphere combinations; single-asperity loads: %d", study.grid.fine,
             len(table), len(table.groupby([c for c in ("hurst", "radius", "h_rms") if c in table])) if len(table) else 0,
             int(table["single_asperity"].sum()) if len(table) else 0)
