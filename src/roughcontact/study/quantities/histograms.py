"""Histograms of the pressure and of the gap at chosen loads (``fields.histograms``): the
distributions contact.engineering shows beside the contact area, kept by each run at the loads of
its path nearest ``fields.histograms.at`` (:attr:`roughcontact.study.runs.jobs.JobSettings.histogram_loads`)
and written to its run file (:data:`roughcontact.study.files.runfile.HISTOGRAM_VARIABLES`).

At one load, the pressure is counted over the contact cells and the gap over the cells out of
contact (where each is not 0), in ``bins`` equal bins from 0 to the largest value of that load: the
counts sum to the contact cells and to the free cells, and a histogram over cells is one over area
(every cell has the area ``(L/n)²``). The bins differ between runs and loads (their edges are
kept with the counts); the ensemble's mean is taken on common edges in normalized units by
:func:`roughcontact.study.analysis.histograms.mean_histograms`.

Closed forms that test it (``tests/test_histograms.py``): under Hertz's pressure
``p(r) = p₀ √(1 − r²/a²)`` (Hertz; K. L. Johnson, Contact Mechanics, 1985, §3.9) the share of the
contact area with ``p < x`` is ``(x/p₀)²``; out of contact the gap is Hertz's
``g(r) = r²/2R − d + u(r)`` (ibid., §3.9), which grows with ``r``, so the area with ``0 < g < x`` is
the annulus ``π (r(x)² − a²)``.
"""
from __future__ import annotations

import dataclasses

import numpy as np

from .gap import gap_field

__all__ = ["Histogram", "histogram", "load_histograms"]


@dataclasses.dataclass(frozen=True)
class Histogram:
    """One histogram of cell values.

    Attributes
    ----------
    counts : numpy.ndarray
        ``(bins,)`` int: the cells whose value lies in each bin (the last bin holds its right edge).
    edges : numpy.ndarray
        ``(bins + 1,)`` float: the bins' edges, equal from 0 to the largest value (all 0 where
        the largest value is 0 or there is no cell: then every cell is in the first bin).
    """

    counts: np.ndarray
    edges: np.ndarray


def histogram(values, bins: int) -> Histogram:
    """The :class:`Histogram` of *values* in *bins* equal bins from 0 to their largest; values below
    0 (a gap negative to the solver's tolerance) count as 0, so the counts sum to ``values.size``."""
    values = np.clip(np.asarray(values, dtype=float).ravel(), 0.0, None)
    top = float(values.max()) if values.size else 0.0
    if not top > 0:
        counts = np.zeros(bins, dtype=np.int64)
        counts[0] = values.size
        return Histogram(counts=counts, edges=np.zeros(bins + 1))
    counts, edges = np.histogram(values, bins=bins, range=(0.0, top))
    return Histogram(counts=counts.astype(np.int64), edges=edges)


def load_histograms(state, load, bins: int) -> dict:
    """The histograms of one solved *state* (its :class:`~roughcontact.study.quantities.Load`
    *load*, whose gap it shares with the gap quantities): ``{"force": F, "pressure": Histogram of
    the pressure over the contact cells, "gap": Histogram of the gap over the cells out of contact}``."""
    contact = np.asarray(state.contact, dtype=bool)
    return {"force": float(state.force), "pressure": histogram(state.pressure[contact], bins),
            "gap": histogram(gap_field(state, load)[~contact], bins)}
