"""Rule ``spectrum_figures``: the report figure of one measured spectrum, k(F) of the surfaces drawn
from it (:func:`roughcontact.study.report.measured.draw_stiffness`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, name: str, *, merged, kf) -> None:
    """Draw k(F) of the merged runs *merged* of the spectrum *name* of the resolved configuration
    *cfg* to *kf* (PNG, atomic)."""
    from ..config.settings import StudySettings
    from ..report.measured import FIGURE_DPI, draw_stiffness
    from ..report.plotting import pyplot, save_png

    study = StudySettings.of(cfg)
    fig = draw_stiffness(pyplot(), merged, study)
    level = 100 * study.fit.confidence
    fig.suptitle(f"{name}: mean over {len(study.seeds)} seeds, {level:g} % bootstrap band", fontsize=9)
    save_png(fig, kf, dpi=FIGURE_DPI)
