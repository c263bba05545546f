"""Rules ``merge``, ``merge_coarse`` and ``merge_fine``: the run files of a study (of its companion
on ``grid.coarse``, on ``grid.fine``) -> ``stiffness.nc`` and ``ensemble.nc``, one group per surface
kind (:func:`roughcontact.study.analysis.merge.merge_runs`,
:func:`~roughcontact.study.analysis.ensemble.ensemble`)."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(cfg, *, runs, stiffness, ensemble) -> None:
    """Merge the run files *runs* (in the order of
    :func:`roughcontact.study.runs.naming.run_paths`) of the resolved configuration *cfg* into
    *stiffness* (every run, with units) and *ensemble* (the statistics over seeds)."""
    from ..analysis import merge
    from ..analysis.ensemble import ensemble as ensemble_of
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import write_groups

    study = StudySettings.of(cfg)
    groups = merge.merge_runs(study, list(runs))
    attrs = provenance.provenance_attrs(
        config=study.config, title="roughcontact parameter study: all runs",
        layout="one group per surface kind (sphere, flat)", grid_n=study.grid.n, grid_length=study.grid.length,
        e_star=study.e_star, solver_tol=study.solver.tol, stiffness_method=study.solver.stiffness,
        seeds=list(study.seeds))
    write_groups(stiffness, {kind: merge.with_units(ds, study) for kind, ds in groups.items()}, attrs)
    attrs["title"] = "roughcontact parameter study: ensemble statistics over seeds"
    write_groups(ensemble, {kind: merge.with_units(ensemble_of(ds), study) for kind, ds in groups.items()}, attrs)
    log.info("merged %d runs (%s) into %s and %s", len(runs), ", ".join(groups), stiffness, ensemble)
