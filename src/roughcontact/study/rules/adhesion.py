"""Rule ``adhesion``: the adhesive run files -> ``adhesion.nc`` (their retract paths, one group per
kind, :func:`roughcontact.study.analysis.adhesion.merge_adhesion`), ``pull_off.csv``
(:func:`~roughcontact.study.analysis.adhesion.pull_off_table`) and its page
(:func:`roughcontact.study.report.adhesion.write_pull_off_page`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, *, runs, nc, csv, html) -> None:
    """Merge the adhesive run files *runs* (in the order of
    :func:`roughcontact.study.analysis.adhesion.adhesive_runs`) of the resolved configuration *cfg*
    into *nc*, write their pull-off table to *csv* and its page to *html*."""
    from ..analysis.adhesion import merge_adhesion, pull_off_table
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import write_csv, write_groups
    from ..report.adhesion import write_pull_off_page

    study = StudySettings.of(cfg)
    groups = merge_adhesion(study, list(runs))
    write_groups(nc, groups, provenance.provenance_attrs(
        config=study.config, title="roughcontact adhesive runs: retract paths and pull-off",
        forces="e_star * length**2 (pull_off.csv: F/(E* L^2))"))
    write_csv(pull_off_table(groups, study), csv)
    write_pull_off_page(csv, html)
