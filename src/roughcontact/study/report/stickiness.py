"""The report's stickiness figure: load against contact area of the stickiness runs.

One panel per Hurst exponent and group of at most six numbers ``N``: ``F/(h′E*L²)`` against
``A/L²`` along the loading of every seed, from the surfaces apart (0, 0), one colour per
Pastewka–Robbins number ``N`` (labelled with the mean
loading slope ``F/A`` at ``A* = stickiness.area``, dotted), and the line of no adhesion with
:data:`KAPPA`. A curve that reaches ``A*`` under tension is sticky.
"""
from __future__ import annotations

import numpy as np

from .plotting import MAX_CURVES, chunks, panel_grid, pyplot, save_png
from ..config.stickiness import StickinessSettings

__all__ = ["KAPPA", "loading_figure"]

#: the reference line without adhesion, ``A = κF/(h′E*)``: Pastewka & Robbins' (and Hyun et al.'s) κ ≈ 2
KAPPA = 2.0


def loading_figure(s: StickinessSettings, runs: dict, path) -> None:
    """The load–area figure (module docstring) of the stickiness runs *runs* (``{run: Dataset}``, a
    :class:`~roughcontact.study.config.stickiness.StickinessRun` of the sweep *s* each) to *path* (PNG)."""
    plt = pyplot()
    cells = float(s.n * s.n)
    scale = s.rms_slope * s.e_star * s.length**2
    # one panel per Hurst exponent and group of at most MAX_CURVES - 1 numbers N (one colour
    # each; the line of no adhesion is on every panel)
    facets = [(hurst, group) for hurst in s.hurst for group in chunks(enumerate(s.number), MAX_CURVES - 1)]
    fig, panels = panel_grid(plt, len(facets), width=5.2, height=4.0, max_columns=3)
    for ax, (hurst, group) in zip(panels, facets):
        for j, number in group:
            mine = [run for job, run in runs.items() if job.hurst == hurst and job.number == number]
            slope = float(np.mean([float(run["loading_slope"]) for run in mine]))
            for k, run in enumerate(mine):
                area = np.r_[0.0, run["contact_cells"].values / cells]
                force = np.r_[0.0, run["force"].values / scale]
                ax.plot(area, force, ".-", color=f"C{j % 10}", lw=0.8, ms=2,
                        label=f"N = {number:g}: F/A = {slope:.3g} h'E* at A*" if k == 0 else None)
        ax.plot([0.0, 1.2 * s.area], [0.0, 1.2 * s.area / KAPPA], "--", color="0.5", lw=0.8,
                label=f"no adhesion: F/A = 1/κ, κ = {KAPPA:g}")
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.axvline(s.area, color="k", lw=0.5, ls=":")
        ax.set(xlabel="contact area A / L²", ylabel="F / (h' E* L²)",
               title=f"H {hurst:g}, n = {s.n}, h' = {s.rms_slope:g}, Δr/g₀ = {s.range_ratio:g}, every seed")
        ax.title.set_fontsize(8)
        ax.legend(fontsize=7)
    fig.suptitle("loading into a Dugdale half-space; sticky (F < 0 at A*) predicted for N < 1", fontsize=9)
    fig.tight_layout()
    save_png(fig, path)
