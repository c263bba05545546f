"""Rule ``tangential``: the run files and ``crossover.csv`` -> ``tangential.nc``
(:func:`roughcontact.study.analysis.tangential.merge_tangential`), ``tangential.csv``
(:func:`~roughcontact.study.analysis.tangential.per_load_table`) and its page."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(cfg, *, runs, crossover, nc, csv, html) -> None:
    """Merge the tangential part of the run files *runs* (in the order of
    :func:`roughcontact.study.runs.naming.run_paths`) of the resolved configuration *cfg* into *nc*
    (groups ``full_stick`` and, with friction, ``partial_slip``), write its per-load table against the
    crossover forces of *crossover* (``crossover.csv``) to *csv* and its page to *html*."""
    from ..analysis import tangential as estimate
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import read_csv, write_csv, write_groups
    from ..report.tables import csv_to_html

    study = StudySettings.of(cfg)
    groups = estimate.merge_tangential(study, list(runs))
    attrs = provenance.provenance_attrs(
        config=study.config, title="roughcontact parameter study: tangential contact of the sphere runs",
        layout="groups full_stick (per load) and partial_slip (friction > 0)", grid_n=study.grid.n,
        grid_length=study.grid.length, e_star=study.e_star, seeds=list(study.seeds))
    write_groups(nc, groups, attrs)
    table = estimate.per_load_table(groups, read_csv(crossover), study)
    write_csv(table, csv, reason="no tangential run has a full-stick stiffness (no sphere with a poisson ratio)")
    csv_to_html(csv, html, "tangential")
    log.info("merged the tangential runs (%s) into %s; %d rows in %s", ", ".join(groups), nc, len(table), csv)
