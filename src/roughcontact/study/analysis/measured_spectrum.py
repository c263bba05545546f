"""The spectrum of a measured scan, its self-affine fit and the models' predictions of k(F).

What the ``measured_spectrum`` rule (:mod:`roughcontact.study.rules.measured_spectrum`) computes per
scan (:func:`spectrum_groups`): :func:`roughcontact.surfaces.spectrum_fit.fit_spectrum` over the scan's tiles (Hann window, each tile levelled; intervals a bootstrap over the tiles;
band ``fit.spectrum.band``, wavelengths in ``units.length``, default L/2 to 8 cells of a tile),
and :func:`roughcontact.study.analysis.measured_models.predict` at the forces of the measured runs, with
the measured rms height of the tiles (``fit.h_rms``: a measured scan rolls off, so the power
law extrapolated to the tile's side would overestimate it) and the tile's side and cells.

Outputs: a one-row CSV of the fit (lengths in ``units.length``, wavenumbers in rad per
``units.length``) and a NetCDF file with the groups ``spectrum`` (the radially averaged
spectrum and the fit's binned points), ``sphere`` (``model, radius, force``) and ``flat``
(``model, force``): stiffness in N/m at the force coordinate in N, NaN where a model does not
apply (Greenwood–Tripp for the flat tile).
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ...models.scorecard import models
from ..config.measured import to_metres, to_pascals
from ..runs.naming import kind_of
from ..config.settings import StudySettings

__all__ = ["fit_scan", "spectrum_groups"]

logger = logging.getLogger(__name__)



def _tiles(surface_file):
    from ..runs.measured import read_surface

    heights, length, attrs = read_surface(surface_file)
    n = heights.shape[0]
    tile = int(attrs["tile"])
    count = n // tile
    blocks = [heights[a * tile:(a + 1) * tile, b * tile:(b + 1) * tile] for a in range(count) for b in range(count)]
    return blocks, length * tile / n, tile, attrs


def fit_scan(study, surface_file):
    """``(fit, tile_length, tile)``: the :class:`SpectrumFit` of the tiles of a surface file
    (*study*: :class:`~roughcontact.study.config.settings.StudySettings` or a resolved configuration)."""
    from ...surfaces.spectrum_fit import fit_spectrum

    study = StudySettings.of(study)
    blocks, length, tile, _ = _tiles(surface_file)
    band = study.fit.spectrum_band
    q_band = None if band is None else (2 * math.pi / band[0], 2 * math.pi / band[1])
    fit = fit_spectrum(blocks, length=length, band=q_band, window="hann", detrend="height",
                       resamples=study.fit.bootstrap, confidence=study.fit.confidence)
    return fit, length, tile


def _fit_row(name: str, fit, unit: str) -> dict:
    row = {"name": name, "unit": unit, "q_min": fit.q_min, "q_max": fit.q_max,
           "wavelength_max": 2 * math.pi / fit.q_min, "wavelength_min": 2 * math.pi / fit.q_max,
           "tile_length": fit.length, "tile": fit.n, "tiles": fit.windows}
    for key in ("hurst", "h_rms", "h_rms_fit", "rms_slope", "rms_slope_spectrum"):
        ci = getattr(fit, f"{key}_ci")
        row.update({key: getattr(fit, key), f"{key}_ci_low": ci.low, f"{key}_ci_high": ci.high})
    row.update(prefactor_persson=fit.prefactor, confidence=fit.confidence, interval=fit.interval)
    return row


def spectrum_groups(study, name: str, surface_file) -> tuple[dict, dict]:
    """The fit of the scan *name* (the file *surface_file* of
    :func:`roughcontact.study.runs.measured.prepare_surface`) and the models' k(F) at the forces of
    its runs: ``(groups, row)``, *groups* the NetCDF groups of the module docstring
    (``spectrum``, ``sphere``, ``flat``; stiffness in N/m, force in N), *row* the CSV's one row."""
    import xarray as xr

    from . import measured_models

    study = StudySettings.of(study)
    fit, length, tile = fit_scan(study, surface_file)
    unit = study.units.length
    logger.info("%s: H = %.3f [%.3f, %.3f] over %.4g ... %.4g %s", name, fit.hurst, fit.hurst_ci.low,
                fit.hurst_ci.high, 2 * math.pi / fit.q_min, 2 * math.pi / fit.q_max, unit)
    e = study.e_star
    newton = to_pascals(study.units.e_star) * to_metres(unit) ** 2      # N per (E* unit * L unit^2)
    per_metre = to_pascals(study.units.e_star) * to_metres(unit)        # N/m per (E* unit * L unit)
    groups = {"spectrum": xr.Dataset(
        {"C": ("q", fit.spectrum.persson_c(), {"long_name": "radially averaged PSD (Persson's C)",
                                                "units": f"{unit}4"}),
         "fit_c": ("bin", fit.fit_c, {"long_name": "binned measured C of the fit", "units": f"{unit}4"}),
         "fit_model": ("bin", fit.fit_model, {"long_name": "fitted power law's C in the bins", "units": f"{unit}4"})},
        coords={"q": ("q", fit.spectrum.q, {"long_name": "wavenumber", "units": f"rad {unit}-1"}),
                "fit_q": ("bin", fit.fit_q, {"long_name": "geometric-mean wavenumber of the bin",
                                             "units": f"rad {unit}-1"})},
        attrs={k: v for k, v in _fit_row(name, fit, unit).items() if not isinstance(v, str)})}
    for kind in ("sphere", "flat"):
        radii = [r for r in study.radius if kind_of(r) == kind]
        if not radii:
            continue
        force = study.forces[kind].normalized() * e * length**2
        names = list(models())     # every model of the registry, NaN where one does not apply
        k = np.full((len(names), len(radii), len(force)), np.nan)
        crossover = np.full(len(radii), np.nan)
        for j, radius in enumerate(radii):
            out = measured_models.predict(force, fit, radius=radius, e_star=e, length=length, n=tile,
                                          h_rms=fit.h_rms)
            for i, model in enumerate(names):
                if model in out:
                    k[i, j] = out[model] * per_metre
            crossover[j] = float(out["crossover_force"]) * newton
        dims = ("model", "radius", "force") if kind == "sphere" else ("model", "force")
        values = k if kind == "sphere" else k[:, 0]
        ds = xr.Dataset(
            {"stiffness": (dims, values, {"long_name": "model stiffness k(F)", "units": "N m-1"})},
            coords={"model": ("model", names),
                    "force": ("force", force * newton, {"long_name": "normal force F", "units": "N"}),
                    "force_normalized": ("force", force / (e * length**2), {"long_name": "F/(E* L^2)", "units": "1"})})
        if kind == "sphere":
            ds = ds.assign_coords(radius=("radius", radii, {"long_name": "sphere radius R", "units": unit}))
            ds["crossover_force"] = ("radius", crossover, {"long_name": "eq. 17 crossover force", "units": "N"})
        groups[kind] = ds
    return groups, _fit_row(name, fit, unit)
