"""Rules ``measured_merge`` and ``spectrum_merge``: the runs of one measured surface (a scan's tiles,
or a spectrum's seeds) -> one NetCDF file, one group per kind
(:func:`roughcontact.study.analysis.measured_merge.merge_surface`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, source: str, name: str, *, runs, nc, surface=None) -> None:
    """Merge the run files *runs* of the surface *name* of *source* (``"topography"``: a scan,
    *surface* its surface file, whose scan attributes the merged file records; ``"spectrum"``: a
    measured spectrum, no *surface*) of the resolved configuration *cfg* into *nc*."""
    from ..analysis.measured_merge import merge_surface

    if source not in ("topography", "spectrum"):
        raise ValueError(f"measured_merge: source {source!r}; allowed: topography, spectrum")
    merge_surface(cfg, source, name, runs, nc, surface_file=surface if source == "topography" else None)
