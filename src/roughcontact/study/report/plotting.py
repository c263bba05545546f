"""The study's figures' two shared steps: pyplot on the non-interactive Agg backend, and a
figure written as PNG atomically (:func:`roughcontact.study.files.provenance.atomic_path`) and closed.

matplotlib is imported only when a figure is drawn (the ``pipeline`` extra)."""
from __future__ import annotations

import math

from ..files import provenance

__all__ = ["MAX_CURVES", "chunks", "data_limits", "edge_mark", "fixed_layout", "layout_with_legends", "legend_below",
           "panel_grid", "pyplot", "save_png"]

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


def legend_below(ax, *, gap: float, fontsize: float = 6.5, ncol: int = 1, **kwargs):
    """*ax*'s legend under it, its top *gap* inches below the axes' bottom edge (below the tick labels
    and the x label the margin there holds), anchored to the axes so that it follows them when the
    layout moves them: a legend that covers no data. ``None`` where *ax* has nothing labelled."""
    from matplotlib.transforms import ScaledTranslation

    handles, labels = kwargs.pop("handles", None), kwargs.pop("labels", None)
    if handles is None:
        handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return None
    anchor = ax.transAxes + ScaledTranslation(0, -gap, ax.figure.dpi_scale_trans)
    return ax.legend(handles, labels, loc="upper center", bbox_to_anchor=(0.5, 0.0), bbox_transform=anchor,
                     fontsize=fontsize, ncol=ncol, borderaxespad=0.0, **kwargs)


def layout_with_legends(fig, legends, *, left: float, right: float, bottom: float, top: float,
                        wspace: float = 0.0, hspace: float = 0.0) -> None:
    """:func:`fixed_layout` for a figure whose panels have their legends under them
    (:func:`legend_below`, anchored *bottom* inches under the axes, where the margins without the
    legends would end): the figure grows by the tallest legend under every row of panels, and
    wider where a legend is wider than its panel, so that the panels keep their size and no
    legend overlaps a panel or leaves the figure."""
    legends = [lg for lg in legends if lg is not None]
    width, height = fig.get_size_inches()
    spec = next((ax.get_subplotspec() for ax in fig.axes if ax.get_subplotspec() is not None), None)
    rows, cols = spec.get_gridspec().get_geometry() if spec is not None else (1, 1)
    extra_height = extra_width = 0.0
    if legends:
        renderer = fig.canvas.get_renderer()
        boxes = [lg.get_window_extent(renderer) for lg in legends]
        extra_height = max(b.height for b in boxes) / fig.dpi + 0.1
        panel = (width - left - right - (cols - 1) * wspace) / cols
        # a legend centred under its panel may reach into the margins and the gap beside it
        room = min(2 * left, 2 * right, wspace if cols > 1 else math.inf)
        extra_width = max(0.0, max(b.width for b in boxes) / fig.dpi + 0.1 - panel - room)
    fig.set_size_inches(width + cols * extra_width, height + rows * extra_height)
    fixed_layout(fig, left=left, right=right, bottom=bottom + extra_height, top=top, wspace=wspace,
                 hspace=hspace + extra_height)


def data_limits(x, y, *, low=None, high=None, pad: float = 1.6):
    """Log-axis limits ``((x0, x1), (y0, y1))`` that hold the measured values drawn (*x*, *y* and
    the error bars' ends *low*, *high*), widened by the factor *pad* on each side; a model's curve
    or a predicted force beyond them does not stretch the axes (:func:`edge_mark`). ``None`` for
    an axis without a positive finite value."""
    import numpy as np

    def span(*arrays):
        values = np.concatenate([np.ravel(np.asarray(a, dtype=float)) for a in arrays if a is not None])
        values = values[np.isfinite(values) & (values > 0)]
        return (float(values.min()) / pad, float(values.max()) * pad) if values.size else None

    return span(x), span(y, low, high)


def edge_mark(ax, value: float, text: str, *, color="0.3", ls="-.", lw=1.0, label=None):
    """A vertical line at *value* (a force on *ax*'s x axis) where it lies within the axes' limits;
    else an arrow at the edge it lies beyond, pointing out of the axes, with *text* and the value
    beside it (top left, bottom right: the corners a rising k(F) leaves free), the line's style
    kept in the legend under *label* (the arrows at one edge stacked). The axes' limits must be set
    first. Returns the line or the arrow's annotation."""
    from matplotlib.lines import Line2D

    lo, hi = ax.get_xlim()
    if lo <= value <= hi:
        return ax.axvline(value, color=color, ls=ls, lw=lw, label=label)
    left = value < lo
    side = "left" if left else "right"
    before = sum(getattr(t, "edge_side", None) == side for t in ax.texts)   # the arrows at this edge stack
    x, y = (0.0, 0.93 - 0.07 * before) if left else (1.0, 0.07 + 0.07 * before)
    note = ax.annotate(f"{text} = {value:.2g}", xy=(x, y), xycoords="axes fraction",
                xytext=(0.1 if left else 0.9, y), textcoords="axes fraction", fontsize=6.5, color=color,
                ha="left" if left else "right", va="center",
                arrowprops={"arrowstyle": "->", "color": color, "lw": lw})
    note.edge_side = side
    if label:
        ax.add_line(Line2D([], [], color=color, ls=ls, lw=lw, label=f"{label} (beyond the {side} edge: arrow)"))
    return note


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
