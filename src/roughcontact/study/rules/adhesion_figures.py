"""Rule ``adhesion_figures``: ``adhesion.nc``, ``stiffness.nc`` and ``pull_off.csv`` -> the load–retract
paths and the pull-off against roughness (:func:`roughcontact.study.report.adhesion.paths_figure`,
:func:`~roughcontact.study.report.adhesion.pull_off_figure`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, *, adhesion, stiffness, pull_off, out_paths, out_pull_off) -> None:
    """Draw the paths figure of the merged adhesive runs *adhesion* and loaded runs *stiffness* to
    *out_paths* and the pull-off figure of the table *pull_off* to *out_pull_off* (PNG) for the
    resolved configuration *cfg*."""
    import pandas as pd

    from ..config.settings import StudySettings
    from ..files.io import read_groups
    from ..report.adhesion import paths_figure, pull_off_figure
    from ..report.plotting import pyplot

    study = StudySettings.of(cfg)
    plt = pyplot()
    table = pd.read_csv(pull_off)
    paths_figure(plt, read_groups(adhesion), read_groups(stiffness), study, out_paths, table)
    pull_off_figure(plt, table, out_pull_off)
