"""Rule ``area``: the merged runs -> ``results/area/area_models.csv``, its HTML page and
``area.png`` (the area scorecard of :func:`roughcontact.study.analysis.area.area_scorecard`, drawn by
:mod:`roughcontact.study.report.area`)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(study, stiffness_nc, out_csv, out_html, out_png) -> None:
    """Write the area scorecard of the merged file *stiffness_nc* for the resolved configuration
    *study* to *out_csv* and *out_html*, and its figure to *out_png*."""
    from ..analysis.area import area_scorecard
    from ..files.io import read_groups, write_csv
    from ..report.area import area_figure, area_lead, no_area_figure, no_area_reason
    from ..report.tables import write_html_table

    groups = read_groups(stiffness_nc)
    table, curves = area_scorecard(groups, study)
    reason = no_area_reason(study)
    write_csv(table, out_csv, reason=reason)
    write_html_table(table, out_html, title="Real contact area: model scorecard", lead=area_lead(),
                     first=("model", "combination", "rank", "max_rel_dev", "max_rel_dev_ci_low", "max_rel_dev_ci_high",
                            "rms_rel_dev", "n_loads", "min_area_cells", "note"))
    if curves:
        area_figure(out_png, curves, study)
    else:
        no_area_figure(out_png, reason)
    log.info("area scorecard:\n%s", table.to_string())
