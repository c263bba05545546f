"""Rule ``figures``: the paper's Figs. 1-4, ζ(H) and the collapse plot, as PNG files in the report
(:func:`roughcontact.study.report.figures.make_figures`; which files: ``figure_specs``)."""
from __future__ import annotations

__all__ = ["run"]


def run(study, ensemble_nc, zeta_csv, crossover_csv, outputs, model_curves_nc=None) -> None:
    """Draw every figure of the resolved configuration *study* to *outputs* (paths in the order of
    ``figure_specs``) from the ensemble means, the ζ and crossover tables and the precomputed
    models' curves *model_curves_nc* (rule ``model_curves``)."""
    from ..report.figures import make_figures

    make_figures(study, ensemble_nc, zeta_csv, crossover_csv, outputs, model_curves_nc=model_curves_nc)
