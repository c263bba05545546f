"""Rule ``stickiness_figures``: the stickiness run files -> the load–area figure
(:func:`roughcontact.study.report.stickiness.loading_figure`)."""
from __future__ import annotations

__all__ = ["run"]


def run(sweep, *, runs, loading) -> None:
    """Draw the load–area figure of the run files *runs* (one per
    :meth:`~roughcontact.study.config.stickiness.StickinessSettings.jobs`, in its order) of the
    *sweep* (a :class:`~roughcontact.study.config.stickiness.StickinessSettings`, the rule's
    ``params``, or a resolved configuration) to *loading* (PNG)."""
    import xarray as xr

    from ..config.stickiness import StickinessSettings
    from ..report.stickiness import loading_figure

    s = StickinessSettings.of(sweep)
    loaded = {}
    for job, path in zip(s.jobs(), runs):
        with xr.open_dataset(path, engine="netcdf4") as ds:
            loaded[job] = ds.load()
    loading_figure(s, loaded, loading)
