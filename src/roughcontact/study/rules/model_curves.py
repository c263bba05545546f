"""Rule ``model_curves``: the precomputable models' curves of every elastic sphere combination,
from the configuration alone (:func:`roughcontact.study.analysis.scorecard.precomputed_curves`), so that the rules
``models`` and ``figures`` read them instead of each computing them after the runs."""
from __future__ import annotations

import logging

__all__ = ["run"]

log = logging.getLogger(__name__)


def run(study, out_nc) -> None:
    """Write ``model_curves.nc`` (one group per elastic sphere combination, provenance at the root)
    for the resolved configuration *study*."""
    from ..analysis.scorecard import precomputed_curves
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import write_groups

    study = StudySettings.of(study)
    curves = precomputed_curves(study)
    attrs = provenance.provenance_attrs(config=study.config, title="precomputed model curves (k per load; Fig. 3's "
                                        "Greenwood-Tripp curve)", forces="e_star * length^2")
    write_groups(out_nc, curves, attrs)
    log.info("model curves of %d sphere combinations: %s", len(curves), ", ".join(curves))
