"""Rules ``tangential_figures`` and ``partial_slip_figures``: ``tangential.nc`` and ``tangential.csv``
-> the figures asked for (:func:`roughcontact.study.report.tangential.ratio_figure`;
with friction :func:`~roughcontact.study.report.tangential.slip_figure` and
:func:`~roughcontact.study.report.tangential.micro_slip_figure`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, *, nc, csv, ratio=None, slip=None, micro_slip=None) -> None:
    """Draw the figures whose paths are given (PNG; ``None``: not drawn): *ratio* (rule
    ``tangential_figures``) from the table *csv*, *slip* and *micro_slip* (rule
    ``partial_slip_figures``) from the merged file *nc*. *cfg*: the resolved configuration (the
    rule's ``params``; the figures need nothing of it but what the files record)."""
    import pandas as pd

    from ..files.io import read_groups
    from ..report.plotting import pyplot
    from ..report.tangential import micro_slip_figure, ratio_figure, slip_figure

    plt = pyplot()
    if ratio:
        ratio_figure(plt, pd.read_csv(csv), ratio)
    if slip or micro_slip:
        groups = read_groups(nc)
        if slip:
            slip_figure(plt, groups, slip)
        if micro_slip:
            micro_slip_figure(plt, groups, micro_slip)
