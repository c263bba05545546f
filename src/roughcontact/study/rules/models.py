"""Rule ``models``: the merged runs and ζ -> the model scorecard (``models.csv``, its page), the
per-load deviations (``models.nc``) and one figure per elastic sphere combination
(:func:`roughcontact.study.analysis.scorecard.scorecard` measures;
:mod:`roughcontact.study.report.scorecard` draws)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(cfg, *, stiffness, zeta, csv, nc, html, figures, grid_error=None, fine_reference=None,
        model_curves=None) -> None:
    """Write the scorecard of the resolved configuration *cfg* to *csv* and its page to *html*, the
    per-load deviations to *nc* (one group per combination) and one figure per elastic sphere
    combination to *figures* (in the order of :func:`roughcontact.study.runs.naming.sphere_names`
    with ``adhesive=False``).

    *stiffness*: ``stiffness.nc``; *zeta*: ``zeta.csv``; *grid_error*: ``grid_error.csv`` of the
    companion on ``grid.coarse`` (or ``None``); *fine_reference*: ``fine_reference.csv`` of the
    companion on ``grid.fine`` (or ``None``), whose grid error replaces the coarse one at its loads
    (:func:`roughcontact.study.analysis.fine_reference.combined_grid_error`); *model_curves*: the
    precomputed models' curves (rule ``model_curves``; ``None``: computed here)."""
    import pandas as pd

    from ..analysis.fine_reference import combined_grid_error
    from ..analysis.grid_error import statement
    from ..analysis.scorecard import NOT_MEASURED_HERE, empty_reason, scorecard
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import read_csv, read_groups, write_csv, write_groups
    from ..report.scorecard import scorecard_figure, write_scorecard_page
    from ..runs import naming

    study = StudySettings.of(cfg)
    errors = combined_grid_error(pd.read_csv(grid_error) if grid_error else None,
                                 pd.read_csv(fine_reference) if fine_reference else None)
    precomputed = read_groups(model_curves) if model_curves else None
    grid = statement(read_csv(grid_error) if grid_error else None, study.grid.coarse)
    # a combination without grid-error rows: the study's reason, or (measured elsewhere) none here
    table, curves = scorecard(read_groups(stiffness), pd.read_csv(zeta), study, errors, precomputed,
                              not_measured=NOT_MEASURED_HERE if grid.measured else grid.sentence())
    attrs = provenance.provenance_attrs(config=study.config, title="model scorecard: k_model/k_BEM - 1 per load",
                                        bootstrap_over="seeds", forces="F/(E* L^2)")
    write_csv(table, csv, reason=empty_reason(study))
    write_groups(nc, curves, attrs)
    write_scorecard_page(table, study, html, grid)
    names = naming.sphere_names(study, adhesive=False)
    figures = list(figures)
    if len(names) != len(figures):
        raise ValueError(f"models: {len(figures)} figure paths for {len(names)} sphere combinations")
    for label, path in zip(names, figures):
        if label not in curves:
            raise ValueError(f"no sphere combination {label} in {stiffness} for the figure {path}")
        scorecard_figure(path, label, curves[label], table)
    log.info("scorecard:\n%s", table.to_string() if len(table) else "(no sphere runs)")
