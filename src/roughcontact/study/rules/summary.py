"""Rule ``summary``: the report's landing page, ``results/summary.html``. A sweep of generated
surfaces gets :func:`roughcontact.study.report.summary.write_summary`'s page (claims, crossover, ζ,
models, Fig. 3), followed by the measured scans' section where it has scans too; a sweep of
measured scans only (``hurst`` empty) gets a page of that section
(:mod:`roughcontact.study.report.landing_measured`)."""
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


def run(cfg, out_html, *, claims_csv=None, crossover_csv=None, zeta_csv=None, models_csv=None, figure_paths=(),
        measured_fits=(), measured_scorecards=()) -> None:
    """Write the landing page to *out_html* for the resolved configuration *cfg*: the generated
    study's tables (``None`` where the sweep has no generated surface) and the measured scans'
    spectrum fits and scorecards (paths, in the order of ``topography``)."""
    from ..files import provenance
    from ..report import landing_measured
    from ..report.summary import write_summary

    scans = _scans(cfg, list(measured_fits), list(measured_scorecards))
    if claims_csv is not None:
        write_summary(cfg, claims_csv, crossover_csv, zeta_csv, models_csv, figure_paths, out_html,
                      extra=landing_measured.measured_section(scans) if scans else "")
    elif scans:
        provenance.write_text(landing_measured.measured_only_html(scans), out_html)
    else:
        raise ValueError("summary: the sweep has neither generated surfaces nor measured scans")
