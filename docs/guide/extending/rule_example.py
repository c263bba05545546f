# module: roughcontact.study.rules.resolved_loads
"""The resolved loads of every sphere combination (``resolved_loads.csv``, the rule
``resolved_loads`` of ``workflow/rules/extra/resolved_loads.smk``): how many loads of its path are
resolved, the smallest of them and the load before it (the resolution threshold lies between the
two: the interval the claim of the guide's table-claim example judges), and where they lie against
eq. 17's crossover force.

A load is resolved where its ensemble-mean contact has at least ``fit.resolved_cells`` cells
(:func:`roughcontact.study.analysis.ensemble.resolved`, the rule every fit of the study applies);
the crossover force is eq. 17 of Pohrt & Popov (2013) with ζ = 1.7/(H+1) (eq. 13,
:func:`roughcontact.models.paper.crossover_force`). Forces are normalised, F/(E* L²). The rule's
entry point is :func:`run`, its script ``workflow/scripts/resolved_loads.py``; the rule's
``params`` carry the fingerprint of this module's code, so that an edit of it reruns the rule.
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ...models import paper
from ..analysis.ensemble import combinations, resolved
from ..config.settings import StudySettings

__all__ = ["RESOLVED_COLUMNS", "NO_SPHERE_ROW", "resolved_loads_table", "run"]

log = logging.getLogger(__name__)

#: the columns of resolved_loads.csv after the sphere's sweep axes
RESOLVED_COLUMNS = ("loads", "resolved_loads", "first_resolved_force", "crossover_force_eq17",
                    "first_resolved_ratio", "previous_ratio")
#: why resolved_loads.csv has no row
NO_SPHERE_ROW = "the sweep has no sphere combination"


def _crossover(where: dict, length: float) -> float:
    """Eq. 17's F_tr/(E* L²) of the combination *where* with ζ of eq. 13 (NaN for m = H: no crossover)."""
    hurst, exponent = where["hurst"], where.get("exponent", 2.0)
    if hurst == exponent:
        return math.nan
    return float(paper.crossover_force(where["radius"], hurst=hurst, h_rms=where["h_rms"], length=length,
                                       e_star=1.0, zeta=paper.zeta_estimate(hurst), exponent=exponent)) / length**2


def resolved_loads_table(sphere, study: StudySettings):
    """One row per combination of the merged sphere runs *sphere* (``stiffness.nc``'s group):
    its sweep axes, the loads of its path, how many are resolved, the smallest resolved
    F/(E* L²) (NaN where none is), eq. 17's crossover force, their ratio and the ratio of the load
    before the smallest resolved one (0 where the path's first load is resolved)."""
    import pandas as pd

    rows = []
    for where, sub in combinations(sphere):            # sub: (seed, force)
        ok = np.asarray(resolved(sub["contact_cells"].values.mean(0), study.fit.resolved_cells))
        force = sub["force_normalized"].values
        first = float(force[ok][0]) if ok.any() else math.nan
        index = int(np.argmax(ok)) if ok.any() else 0
        previous = float(force[index - 1]) if ok.any() and index > 0 else (0.0 if ok.any() else math.nan)
        crossover = _crossover(where, study.grid.length)
        rows.append({**where, "loads": int(force.size), "resolved_loads": int(ok.sum()),
                     "first_resolved_force": first, "crossover_force_eq17": crossover,
                     "first_resolved_ratio": first / crossover, "previous_ratio": previous / crossover})
    return pd.DataFrame(rows)


def run(cfg, *, stiffness, csv) -> None:
    """``resolved_loads`` rule: the merged runs *stiffness* (``stiffness.nc``) of the resolved
    configuration *cfg* -> *csv* (``resolved_loads.csv``, a header and its reason without a sphere)."""
    from ..files.io import read_groups, write_csv

    study = StudySettings.of(cfg)
    sphere = read_groups(stiffness).get("sphere")
    table = resolved_loads_table(sphere, study) if sphere is not None else None
    if table is None:
        import pandas as pd

        table = pd.DataFrame()
    write_csv(table, csv, columns=RESOLVED_COLUMNS, reason=NO_SPHERE_ROW)
    log.info("resolved loads of %d sphere combinations written to %s", len(table), csv)
