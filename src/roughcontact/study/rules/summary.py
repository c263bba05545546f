"""Rule ``summary``: the report's landing page, ``results/summary.html``. A sweep of generated
surfaces gets :func:`roughcontact.study.report.summary.write_summary`'s page (claims, crossover, ζ,
models, Fig. 3), followed by the measured scans' section where it has scans too; a sweep of
measured scans only (``hurst`` empty) gets a page of that section
(:mod:`roughcontact.study.report.landing_measured`); the measured spectra's section follows the
scans' (a sweep of spectra only gets a page of it)."""
from __future__ import annotations

__all__ = ["run"]


def _by_name(cfg, key: str, **paths) -> list[tuple]:
    """``(name, path, …)`` of every entry of the configuration's *key* (``topography``, ``spectrum``)
    in its order, that of the rule's inputs *paths* (one list per kind of input)."""
    names = [entry["name"] for entry in cfg.get(key, [])]
    lists = [list(p) for p in paths.values()]
    if any(len(p) != len(names) for p in lists):
        counts = ", ".join(f"{len(p)} {what}" for what, p in zip(paths, lists))
        raise ValueError(f"summary: {counts} for the {len(names)} entries of {key} {names}")
    return list(zip(names, *lists))


def run(cfg, out_html, *, claims_csv=None, crossover_csv=None, zeta_csv=None, models_csv=None, figure_paths=(),
        grid_error_csv=None, measured_fits=(), measured_scorecards=(), spectrum_merged=(),
        spectrum_figures=()) -> None:
    """Write the landing page to *out_html* for the resolved configuration *cfg*: the generated
    study's tables (``None`` where the sweep has no generated surface), the measured scans'
    spectrum fits and scorecards (paths, in the order of ``topography``) and the measured spectra's
    merged files and k(F) figures (paths, in the order of ``spectrum``)."""
    from ..config.settings import StudySettings
    from ..files import provenance
    from ..files.io import read_groups
    from ..report import landing_measured
    from ..report.summary import _read, write_summary

    scans = {name: (_read(fit), _read(card)) for name, fit, card in
             _by_name(cfg, "topography", spectrum_fits=measured_fits, scorecards=measured_scorecards)}
    spectra = {name: (read_groups(merged), figure) for name, merged, figure in
               _by_name(cfg, "spectrum", merged_files=spectrum_merged, figures=spectrum_figures)}
    spectra_html = (landing_measured.spectrum_section(spectra, StudySettings.of(cfg).fit.resolved_cells)
                    if spectra else "")
    if claims_csv is not None:
        extra = "\n".join(part for part in (landing_measured.measured_section(scans) if scans else "", spectra_html)
                          if part)
        write_summary(cfg, claims_csv, crossover_csv, zeta_csv, models_csv, figure_paths, out_html,
                      grid_error_csv=grid_error_csv, extra=extra)
    elif scans or spectra:
        provenance.write_text(landing_measured.measured_only_html(scans, spectra_html), out_html)
    else:
        raise ValueError("summary: the sweep has neither generated surfaces nor measured inputs")
