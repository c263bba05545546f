"""The study's figures' two shared steps: pyplot on the non-interactive Agg backend, and a
figure written as PNG atomically (:func:`roughcontact.study.provenance.atomic_path`) and closed.

matplotlib is imported only when a figure is drawn (the ``pipeline`` extra)."""
from __future__ import annotations

from . import provenance

__all__ = ["pyplot", "save_png"]


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
