"""Rule ``summary``: the report's landing page, ``results/summary.html``. A sweep of generated
surfaces gets :func:`roughcontact.study.report.summary.write_summary`'s page (claims, crossover, ζ,
models, Fig. 3), followed by the measured scans' section where it has scans too; a sweep of
measured scans only (``hurst`` empty) gets a page of that section
(:mod:`roughcontact.study.report.landing_measured`); the measured spectra's section follows the
scans' (a sweep of spectra only gets a page of it)."""
from __future__ import annotations

__all__ = ["run"]


def _scans(cfg, fits, scorecards) -> dict:
    """``{scan name: (fit, scorecard)}`` in the configuration's order (that of the rule's inputs)."""
    from ..report.summary import _read

    names = [entry["name"] for entry in cfg.get("topography", [])]
    if not (len(names) == len(fits) == len(scorecards)):
        raise ValueError(f"summary: {len(fits)} spectrum fits and {len(scorecards)} scorecards for the "
                         f"{len(names)} scans {names}")
    return {name: (_read(fit), _read(card)) for name, fit, card in zip(names, fits, scorecards)}


def _spectra(cfg, merged, figures) -> dict:
    """``{spectrum name: (groups of its merged file, its k(F) figure)}`` in the configuration's order."""
    from ..files.io import read_groups

    names = [entry["name"] for entry in cfg.get("spectrum", [])]
    if not (len(names) == len(merged) == len(figures)):
        raise ValueError(f"summary: {len(merged)} merged files and {len(figures)} figures for the "
                         f"{len(names)} spectra {names}")
    return {name: (read_groups(path), figure) for name, path, figure in zip(names, merged, figures)}


def run(cfg, out_html, *, claims_csv=None, crossover_csv=None, zeta_csv=None, models_csv=None, figure_paths=(),
        measured_fits=(), measured_scorecards=(), spectrum_merged=(), spectrum_figures=()) -> None:
    """Write the landing page to *out_html* for the resolved configuration *cfg*: the generated
    study's tables (``None`` where the sweep has no generated surface), the measured scans'
    spectrum fits and scorecards (paths, in the order of ``topography``) and the measured spectra's
    merged files and k(F) figures (paths, in the order of ``spectrum``)."""
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..report import landing_measured
    from ..report.summary import write_summary

    scans = _scans(cfg, list(measured_fits), list(measured_scorecards))
    spectra = _spectra(cfg, list(spectrum_merged), list(spectrum_figures))
    spectra_html = (landing_measured.spectrum_section(spectra, StudySettings.of(cfg).fit.resolved_cells)
                    if spectra else "")
    if claims_csv is not None:
        extra = "\n".join(part for part in (landing_measured.measured_section(scans) if scans else "", spectra_html)
                          if part)
        write_summary(cfg, claims_csv, crossover_csv, zeta_csv, models_csv, figure_paths, out_html, extra=extra)
    elif scans or spectra:
        provenance.write_text(landing_measured.measured_only_html(scans, spectra_html), out_html)
    else:
        raise ValueError("summary: the sweep has neither generated surfaces nor measured inputs")
