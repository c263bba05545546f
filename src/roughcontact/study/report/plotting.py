"""The study's figures' two shared steps: pyplot on the non-interactive Agg backend, and a
figure written as PNG atomically (:func:`roughcontact.study.files.provenance.atomic_path`) and closed.

matplotlib is imported only when a figure is drawn (the ``pipeline`` extra)."""
from __future__ import annotations

from ..files import provenance

__all__ = ["MAX_CURVES", "chunks", "fixed_layout", "panel_grid", "pyplot", "save_png"]

#: most curves on one panel: a figure with more is faceted into panels of at most this many
MAX_CURVES = 7


def chunks(items, size: int) -> list[list]:
    """*items* in consecutive groups of at most *size* (at least one group, maybe empty)."""
    items = list(items)
    size = max(1, int(size))
    return [items[i:i + size] for i in range(0, len(items), size)] or [[]]


def panel_grid(plt, count: int, *, width: float, height: float, max_columns: int = 3, **kwargs):
    """A figure with *count* panels (rows of at most *max_columns*): ``(fig, panels)``, the unused
    panels switched off, *panels* a flat list of the first *count*."""
    import math

    cols = max(1, min(max_columns, count))
    rows = max(1, math.ceil(count / cols))
    fig, grid = plt.subplots(rows, cols, figsize=(width * cols, height * rows), squeeze=False, **kwargs)
    flat = list(grid.flat)
    for ax in flat[count:]:
        ax.axis("off")
    return fig, flat[:max(count, 1)]


def fixed_layout(fig, *, left: float, right: float, bottom: float, top: float, wspace: float = 0.0,
                 hspace: float = 0.0) -> None:
    """Place *fig*'s grid of panels with fixed margins and gaps, in inches (the figure's edges to
    the panels; between two columns, *wspace*, and two rows, *hspace*): one layout pass, that of
    ``savefig``, instead of ``tight_layout``'s measuring of every tick label first (which doubled
    the cost of drawing a figure of log axes). The margins hold the tick labels, axis labels and
    titles of the figure they are chosen for; the panels' size follows the figure's."""
    width, height = fig.get_size_inches()
    spec = next((ax.get_subplotspec() for ax in fig.axes if ax.get_subplotspec() is not None), None)
    rows, cols = spec.get_gridspec().get_geometry() if spec is not None else (1, 1)
    panel_width = (width - left - right - (cols - 1) * wspace) / cols
    panel_height = (height - bottom - top - (rows - 1) * hspace) / rows
    fig.subplots_adjust(left=left / width, right=1 - right / width, bottom=bottom / height, top=1 - top / height,
                        wspace=wspace / panel_width, hspace=hspace / panel_height)


def pyplot():
    """``matplotlib.pyplot`` on the Agg backend (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_png(fig, path, *, dpi: int = 110) -> None:
    """Write *fig* to *path* as PNG, atomically, and close it."""
    with provenance.atomic_path(path) as tmp:
        fig.savefig(tmp, dpi=dpi, format="png")
    pyplot().close(fig)
