"""Contact patches: the connected clusters of contact cells of a solved state.

Two contact cells belong to one patch when they share an edge (4-connectivity: cells that touch at
a corner only are two patches, since no traction is transmitted through a corner on the grid). On
a periodic half-space the grid wraps: a patch that leaves one edge and enters at the opposite one
is one patch. Labelling by :func:`scipy.ndimage.label` (a two-pass connected-component labelling;
K. Wu, E. Otoo and K. Suzuki, Pattern Anal. Appl. 12, 117 (2009), doi:10.1007/s10044-008-0109-y),
with the periodic wrap merged by a union–find over the edge pairs.
"""
from __future__ import annotations

import dataclasses

import numpy as np

__all__ = ["Patches", "contact_patches", "contact_window"]

#: 4-connectivity: neighbours across an edge
_EDGE_NEIGHBOURS = np.array([[0, 1, 0], [1, 1, 1], [0, 1, 0]])


@dataclasses.dataclass(frozen=True)
class Patches:
    """The contact patches of one contact set.

    Attributes
    ----------
    count : int
        Number of patches (0 without contact).
    largest : int
        Cells of the largest patch (0 without contact).
    labels : numpy.ndarray
        ``(n, n)`` int, the patch of each cell (1 … ``count``; 0 out of contact).
    sizes : numpy.ndarray
        ``(count,)`` cells of each patch, by label.
    """

    count: int
    largest: int
    labels: np.ndarray
    sizes: np.ndarray


def contact_patches(contact, *, periodic: bool = False) -> Patches:
    """The patches of the boolean contact set *contact* (module docstring).

    Parameters
    ----------
    contact : array_like of bool, shape (n, m)
        Cells in contact (:attr:`roughcontact.bem.ContactState.contact`).
    periodic : bool, keyword-only
        Whether the grid wraps (the periodic half-space of a nominally flat surface).
    """
    from scipy import ndimage

    mask = np.asarray(contact, dtype=bool)
    if mask.ndim != 2:
        raise ValueError(f"contact must be a 2-D array, got shape {mask.shape}")
    labels, count = ndimage.label(mask, structure=_EDGE_NEIGHBOURS)
    if periodic and count > 1:
        parent = np.arange(count + 1)

        def find(a):
            while parent[a] != a:
                parent[a] = parent[parent[a]]
                a = parent[a]
            return a

        for first, last in ((labels[0, :], labels[-1, :]), (labels[:, 0], labels[:, -1])):
            for a, b in zip(first[(first > 0) & (last > 0)], last[(first > 0) & (last > 0)]):
                ra, rb = find(a), find(b)
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
        roots = np.array([find(a) for a in range(count + 1)])
        _, relabel = np.unique(roots, return_inverse=True)   # roots 0, r1 < r2 < ... -> 0, 1, 2, ...
        labels = relabel[labels]
        count = int(relabel.max())
    sizes = np.bincount(labels.ravel(), minlength=count + 1)[1:]
    return Patches(count=int(count), largest=int(sizes.max()) if count else 0, labels=labels, sizes=sizes)


def contact_window(contact, *, margin: int = 2) -> tuple[slice, slice]:
    """The smallest rectangle of rows and columns holding every contact cell of *contact*, widened
    by *margin* cells on each side within the grid (the whole grid without contact)."""
    mask = np.asarray(contact, dtype=bool)
    rows, cols = np.flatnonzero(mask.any(1)), np.flatnonzero(mask.any(0))
    if rows.size == 0:
        return slice(0, mask.shape[0]), slice(0, mask.shape[1])
    return (slice(max(rows[0] - margin, 0), min(rows[-1] + margin + 1, mask.shape[0])),
            slice(max(cols[0] - margin, 0), min(cols[-1] + margin + 1, mask.shape[1])))
