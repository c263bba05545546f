"""Rule ``stickiness``: the stickiness run files -> ``stickiness.nc``
(:func:`roughcontact.study.analysis.stickiness.merge_stickiness`), ``stickiness.csv``
(:func:`~roughcontact.study.analysis.stickiness.stickiness_table`) and its page."""
from __future__ import annotations

__all__ = ["run"]


def run(sweep, *, runs, nc, csv, html) -> None:
    """Merge the run files *runs* (one per :meth:`~roughcontact.study.config.stickiness.StickinessSettings.jobs`,
    in its order) of the *sweep* (:class:`~roughcontact.study.config.stickiness.StickinessSettings`,
    the rule's ``params``, or a resolved configuration) into *nc*, whose provenance records
    :meth:`~roughcontact.study.config.stickiness.StickinessSettings.record`; write the table of
    loading slopes to *csv* and its page to *html*."""
    from ..analysis.stickiness import merge_stickiness, stickiness_table
    from ..config.stickiness import StickinessSettings
    from ..files import provenance
    from ..files.io import write_csv
    from ..report.tables import csv_to_html

    s = StickinessSettings.of(sweep)
    ds = merge_stickiness(s, list(runs))
    ds.attrs.update(provenance.provenance_attrs(
        config=s.record(), title="roughcontact stickiness runs: loading slopes F/A at the area A*",
        forces="e_star * length**2 (stickiness.csv: dF/dA in units of h'E*)"))
    provenance.write_netcdf(ds, nc)
    write_csv(stickiness_table(ds, s), csv)
    csv_to_html(csv, html, "stickiness")
