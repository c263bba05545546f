"""Rules ``measured_indent`` and ``spectrum_indent``: one tile of a scan (or one seed of a spectrum) and
one radius -> one run file (:func:`roughcontact.study.runs.measured.run_job`, also what
``roughcontact measured`` runs)."""
from __future__ import annotations

__all__ = ["run"]


def run(job, source, *, run) -> None:
    """Compute the run *job* (a :class:`~roughcontact.study.runs.measured.MeasuredJob`, the rule's
    ``params``) on *source* (the scan's surface file, or the spectrum's table) and write it to the
    run file *run*."""
    from ..runs.measured import run_job

    run_job(job, source, run)
