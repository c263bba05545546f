"""Rule ``measured_spectrum``: one scan's surface file -> the fit of its spectrum (a one-row CSV and
its page) and the models' k(F) at the forces of its runs (NetCDF)
(:func:`roughcontact.study.analysis.measured_spectrum.spectrum_groups`)."""
from __future__ import annotations

__all__ = ["run"]


def run(cfg, name: str, *, surface, csv, nc, html) -> None:
    """Write the spectrum fit of the scan *name* (its file *surface*) of the resolved configuration
    *cfg* to *csv* and its page to *html*, and the spectrum and the models' k(F) to *nc* (groups
    ``spectrum``, ``sphere``, ``flat``)."""
    import pandas as pd

    from ..analysis.measured_spectrum import spectrum_groups
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import write_csv, write_groups
    from ..report.tables import csv_to_html

    study = StudySettings.of(cfg)
    groups, row = spectrum_groups(study, name, surface)
    attrs = provenance.provenance_attrs(config=study.config, title=f"roughcontact measured spectrum and models: {name}",
                                        h_rms_models="measured h_rms of the tiles")
    write_groups(nc, groups, attrs)
    write_csv(pd.DataFrame([row]), csv)
    csv_to_html(csv, html, "spectrum_fit")
