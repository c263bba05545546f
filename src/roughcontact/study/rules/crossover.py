"""Rule ``crossover``: ζ(H) of eq. 11 and the crossover table of eqs. 16 and 17 in one job, from
``stiffness.nc`` read once: ``zeta.csv`` and ``zeta.nc``
(:func:`roughcontact.study.analysis.zeta.fit.fit_zeta`), then ``crossover.csv`` and
``crossover.nc`` (:func:`roughcontact.study.analysis.crossover.crossover_table`), each table with
its report page. The crossover reads ζ back from ``zeta.csv``, as it did when it was a rule of its
own, so both tables are the same to the bit; one job instead of two saves a process start on the
analysis' critical path (merge → crossover → figures → summary)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(study, stiffness_nc, *, zeta_csv, zeta_html, zeta_nc, crossover_csv, crossover_html, crossover_nc) -> None:
    """Write ζ(H) (*zeta_csv*, its page *zeta_html*, the bootstrap replicates *zeta_nc*) and the
    crossover table (*crossover_csv*, *crossover_html*, the replicates of F_tr *crossover_nc*) of the
    resolved configuration *study* from the merged sphere and flat runs *stiffness_nc*."""
    import pandas as pd

    from ..analysis.crossover import NO_SPHERE, crossover_table
    from ..analysis.zeta.fit import NO_HURST, fit_zeta
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import read_groups, write_csv, write_netcdf
    from ..report.tables import csv_to_html

    study = StudySettings.of(study)
    groups = read_groups(stiffness_nc)
    zeta, replicates = fit_zeta(groups, study)
    write_csv(zeta, zeta_csv, reason=NO_HURST)
    write_netcdf(replicates, zeta_nc)
    log.info("zeta(H):\n%s", zeta.to_string())
    csv_to_html(zeta_csv, zeta_html, "zeta")

    table, reps = crossover_table(groups, pd.read_csv(zeta_csv), study)   # ζ as the file holds it
    reps.attrs.update(provenance.provenance_attrs(config=study.config, title="roughcontact: crossover force replicates"))
    write_csv(table, crossover_csv, reason=NO_SPHERE)
    write_netcdf(reps, crossover_nc)
    log.info("crossover:\n%s", table.to_string())
    csv_to_html(crossover_csv, crossover_html, "crossover")
