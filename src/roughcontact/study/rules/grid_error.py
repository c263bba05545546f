"""Rule ``grid_error``: the study's ``stiffness.nc`` against its companion's on ``grid.coarse`` (the
same surfaces) -> ``grid_error.csv`` and its page
(:func:`roughcontact.study.analysis.grid_error.grid_error`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, *, fine, coarse, csv, html) -> None:
    """Write the grid error of every resolved load of the study (*fine*: its ``stiffness.nc``)
    against the coarse companion (*coarse*) to *csv* (an empty table with its reason without sphere
    runs or with fewer than 2 seeds) and its report page to *html*, with the study's fit windows
    (``fit``) and grid ratio ``n/grid.coarse``."""
    import pandas as pd

    from ..analysis.grid_error import GRID_ERROR_COLUMNS, empty_reason, grid_error
    from ..config.settings import StudySettings
    from ..files.io import read_groups, write_csv
    from ..report.tables import csv_to_html
    from ..runs import naming

    study = StudySettings.of(cfg)
    fit = study.fit
    fine_groups, coarse_groups = read_groups(fine), read_groups(coarse)
    reason = empty_reason(fine_groups, coarse_groups)
    table = (pd.DataFrame(columns=[*naming.AXES["sphere"], *GRID_ERROR_COLUMNS]) if reason else
             grid_error(coarse_groups["sphere"], fine_groups["sphere"], min_cells=fit.resolved_cells,
                        bootstrap=fit.bootstrap, confidence=fit.confidence, ratio=study.grid.n / study.grid.coarse))
    write_csv(table, csv, reason=reason)
    csv_to_html(csv, html, "grid_error")
