"""Rule ``measured_scorecard``: every model against the tiles of one scan
(:func:`roughcontact.study.analysis.measured_scorecard.measured_scorecard`) -> its CSV and its page
(:func:`roughcontact.study.report.measured.scorecard_page`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, name: str, *, merged, spectrum, csv, html) -> None:
    """Write the scorecard of the scan *name* of the resolved configuration *cfg* to *csv* (an empty
    table with its reason where no load is resolved and predicted) and its page to *html*; *merged*:
    the scan's merged runs, *spectrum*: the models' predictions (rule ``measured_spectrum``)."""
    from ..analysis.measured_scorecard import measured_scorecard
    from ..config.settings import StudySettings
    from ..files.io import read_groups, write_csv
    from ..report.measured import scorecard_page

    study = StudySettings.of(cfg)
    predicted = read_groups(spectrum)
    table = measured_scorecard(read_groups(merged), predicted, name=name, min_cells=study.fit.resolved_cells,
                               fit=study.fit)
    write_csv(table, csv, reason=f"no load of the scan {name} has at least {study.fit.resolved_cells} contact "
                                 "cells and a model's prediction")
    fit = predicted.get("spectrum")
    scorecard_page(table, fit.attrs if fit is not None else {}, name, html)
