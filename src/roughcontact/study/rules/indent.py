"""Rules ``indent``, ``indent_coarse``, ``indent_fine`` and their batches (``indent_seeds0_5``, …):
the runs of one combination and block of seeds (``jobs.batch``; one run with batch 1), one after
another in this process, each written to its own file (and log) as soon as it is done
(:func:`roughcontact.study.runs.indent.run_indent`, also what ``roughcontact indent`` runs), so that
a job pays the start-up of Python and the package once."""
from __future__ import annotations

__all__ = ["run", "failure_line"]


def run(settings, *, outputs, logs=None) -> None:
    """Compute the runs *settings* (a :class:`~roughcontact.study.runs.jobs.JobSettings` or a sequence
    of them) one after another, each written to its path of *outputs* (atomic) with its log of *logs*
    (``None``: no logs), in the same order.

    Stops at the first run that fails and raises its error, which carries that run's log path as
    ``err.run_log``: the runs written before it stay, complete and valid, the failing run and
    those after it leave no file. ``ValueError`` where the three counts differ."""
    from ..runs.indent import run_indent
    from ..runs.jobs import JobSettings

    runs = [settings] if isinstance(settings, JobSettings) else list(settings)
    outputs = list(outputs)
    logs = [None] * len(runs) if logs is None else list(logs)
    if not len(runs) == len(outputs) == len(logs):
        raise ValueError(f"indent: {len(runs)} runs, {len(outputs)} outputs and {len(logs)} logs")
    for job, output, log in zip(runs, outputs, logs):
        try:
            run_indent(job, output, log=log)
        except Exception as exc:
            exc.run_log = log
            raise


def failure_line(rule: str, err: BaseException) -> str:
    """The one console line of a failed indent job of *rule*: the error and, where the run has one,
    its log (which holds the traceback)."""
    log = getattr(err, "run_log", None)
    return f"Error in rule {rule}: {type(err).__name__}: {err}" + (f" (log: {log})" if log else "")
