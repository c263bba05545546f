"""One sphere combination of a merged study as the models read it: its axes as merged-file coordinates
with the study's grid, and the :class:`~roughcontact.models.scorecard.registry.Surface` and run name they
make. Shared by the stiffness scorecard (:mod:`~roughcontact.study.analysis.scorecard`) and the area
scorecard (:mod:`~roughcontact.study.analysis.area`); it imports the models' ``Surface`` only, not their
registry, so the area and claims rules do not rerun when a stiffness model is added."""
from __future__ import annotations

import math

from ...models.scorecard import registry
from ..config import axes
from ..config.settings import StudySettings
from ..runs import naming as runs

__all__ = ["Combination", "combination", "combo_label"]


class Combination(dict):
    """One sphere combination of the sweep: the axes as merged-file coordinates, plus ``n``,
    ``length``, ``e_star`` and ``zeta_fit`` (the study's fitted ζ(H), NaN if none)."""

    @property
    def paper_setting(self) -> bool:
        """Every optional axis at the paper's value (:func:`roughcontact.study.config.axes.paper_setting`)."""
        return axes.paper_setting(self, self["length"])

    def surface(self) -> registry.Surface:
        """What the models read (:class:`roughcontact.models.scorecard.Surface`), with every
        optional axis of the combination in its ``axes`` (merged-file coordinates)."""
        length = self["length"]
        return registry.Surface(
            hurst=self["hurst"], h_rms=self["h_rms"], radius=self["radius"], length=length, n=int(self["n"]),
            e_star=self["e_star"], exponent=self["exponent"], zeta_fit=self["zeta_fit"],
            rolloff=runs.axis_value("rolloff", self["rolloff"], length),
            cutoff=runs.axis_value("cutoff", self["cutoff"], length),
            axes={a.name: self[a.name] for a in axes.optional_axes() if a.name in self})


def combination(where: dict, study: StudySettings, *, zeta_fit: float = math.nan) -> Combination:
    """The :class:`Combination` of the sphere combination *where* (axis -> merged-file coordinate) of
    *study*: an axis a file made before it existed lacks is at its paper setting; ``zeta_fit`` NaN
    unless given."""
    combo = Combination(where)
    for axis, setting in runs.DEFAULTS.items():   # an axis a file made before it existed lacks
        if axis in runs.AXES["sphere"]:
            combo.setdefault(axis, runs.coordinate(axis, setting, study.grid.length))
    combo.update(n=study.grid.n, length=study.grid.length, e_star=study.e_star, zeta_fit=float(zeta_fit))
    return combo


def combo_label(c: Combination) -> str:
    """The run name of a combination (``H0.7_R0.5_h0.009`` and the tags of the optional axes)."""
    run = {axis: runs.axis_value(axis, c[axis], c["length"]) if axis in runs.DEFAULTS else c[axis]
           for axis in runs.AXES["sphere"]}
    return runs.combo_name(run)
