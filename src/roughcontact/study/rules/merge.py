"""Rules ``merge``, ``merge_coarse`` and ``merge_fine``: the run files of a study (or of its grid
companion) -> ``stiffness.nc`` and ``ensemble.nc``, a group per surface kind
(:func:`roughcontact.study.analysis.merge.run_merge`)."""
from __future__ import annotations

__all__ = ["run"]


def run(study, run_files, out_stiffness, out_ensemble) -> None:
    """Merge *run_files* of the resolved configuration *study* into *out_stiffness* (every seed)
    and *out_ensemble* (the means over seeds)."""
    from ..analysis.merge import run_merge

    run_merge(study, run_files, out_stiffness, out_ensemble)
