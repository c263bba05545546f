"""Rule ``measured_figures``: the report figures of one scan, its height map, its spectrum with the fit
and k(F) with the models (:func:`roughcontact.study.report.measured.draw_heights`,
:func:`~roughcontact.study.report.measured.draw_spectrum`,
:func:`~roughcontact.study.report.measured.draw_stiffness`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, name: str, *, surface, merged, heights, kf, spectrum=None, psd=None) -> None:
    """Draw the figures of the scan *name* of the resolved configuration *cfg* (PNG, atomic):
    *heights* from its surface file *surface*, *psd* (with *spectrum*, rule ``measured_spectrum``'s
    file) and *kf* from its merged runs *merged* (with the models of *spectrum*)."""
    from ..config.settings import StudySettings
    from ..report.measured import FIGURE_DPI, draw_heights, draw_spectrum, draw_stiffness
    from ..report.plotting import pyplot, save_png

    study = StudySettings.of(cfg)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5.2, 4.4), constrained_layout=True)
    image = draw_heights(ax, surface, name)
    fig.colorbar(image, ax=ax, label="measured height h (nm)")
    save_png(fig, heights, dpi=FIGURE_DPI)
    if spectrum is not None:
        fig, ax = plt.subplots(figsize=(5.2, 4.4), constrained_layout=True)
        draw_spectrum(ax, spectrum, study.units.length)
        ax.set_title(f"{name}: power spectrum over the tiles and its self-affine fit", fontsize=9)
        save_png(fig, psd, dpi=FIGURE_DPI)
    fig = draw_stiffness(plt, merged, study, spectrum)
    level = 100 * study.fit.confidence
    fig.suptitle(f"{name}: mean over tiles, {level:g} % bootstrap band", fontsize=9)
    save_png(fig, kf, dpi=FIGURE_DPI)
