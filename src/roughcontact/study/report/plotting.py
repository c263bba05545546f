"""The study's figures' two shared steps: pyplot on the non-interactive Agg backend, and a
figure written as PNG atomically (:func:`roughcontact.study.files.provenance.atomic_path`) and closed.

matplotlib is imported only when a figure is drawn (the ``pipeline`` extra)."""
from __future__ import annotations

from ..files import provenance

__all__ = ["MAX_CURVES", "chunks", "panel_grid", "pyplot", "save_png"]

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
