"""Rule ``histograms_figure``: ``stiffness.nc`` -> the figure of one load's pressure and gap
histograms, the ensemble's mean in normalized units over each seed's
(:func:`roughcontact.study.report.histograms.make_histogram_figure`,
:func:`roughcontact.study.analysis.histograms.mean_histograms`)."""
from __future__ import annotations

__all__ = ["run"]


def run(study, stiffness_nc, out_png) -> None:
    """Draw the histograms of the merged file *stiffness_nc* for the resolved configuration *study*
    into *out_png*."""
    from ..report.histograms import make_histogram_figure

    make_histogram_figure(study, stiffness_nc, out_png)
