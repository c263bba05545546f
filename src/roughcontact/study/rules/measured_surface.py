"""Rule ``measured_surface`` (a checkpoint): one scan of ``topography`` -> its surface file, the
square cut into tiles (:func:`roughcontact.study.runs.measured.prepare_surface`, also what
``roughcontact measured`` runs)."""
from __future__ import annotations

__all__ = ["run"]


def run(entry, surface, *, nc) -> None:
    """Write the surface file *nc* of the scan *entry* (its ``topography`` entry of the resolved
    configuration); *surface*: the settings that shape the tiles, ``{"units": ..., "tile": ...}``
    (the rule's ``params``: no other setting reruns the scan's runs)."""
    from ..runs.measured import prepare_surface

    prepare_surface(entry, nc, length_unit=surface["units"]["length"], tile=surface["tile"])
