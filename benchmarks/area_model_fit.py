"""Fit the constants of the ``three_regime`` area model (:mod:`roughcontact.models.area.three_regime`)
on one study: κ, c_s and n minimising the mean square of ``ln(A_model/A_BEM)`` over the area-resolved
loads (:func:`roughcontact.study.analysis.area.area_context`) of the ensemble-mean area of every
elastic sphere combination of the study. Then the rms of ``ln`` with the module's constants and,
for each further study given, the same rms with the fitted constants (held out).

Usage::

    python benchmarks/area_model_fit.py CONFIG.yaml RESULTS_DIR [--heldout CONFIG.yaml RESULTS_DIR ...]

(the module's constants were fitted on the calibration sweep of ``docs/guide/area.md``, section
"This package's model", 2026-11-29.)
"""
from __future__ import annotations

import argparse
import math
import sys

import numpy as np
import xarray as xr
import yaml
from scipy.optimize import minimize

from roughcontact.models.area import three_regime as model
from roughcontact.study.analysis.area import area_context
from roughcontact.study.analysis.ensemble import combinations
from roughcontact.study.config.resolve import study_settings


def resolved_points(config: str, results: str) -> list[dict]:
    """Per sphere combination: force, ensemble-mean area, h′_rms, h″_rms and radius at its
    area-resolved loads."""
    with open(config) as handle:
        study = study_settings(yaml.safe_load(handle))
    with xr.open_dataset(f"{results}/stiffness.nc", group="sphere") as ds:
        ds = ds.load()
    out = []
    for where, sub in combinations(ds):
        context = area_context(where, sub, study)
        area = sub["contact_area"].values.mean(0)
        use = context.resolved & (area > 0)
        out.append({"where": where, "force": sub["force"].values[use], "area": area[use], "slope": context.rms_slope,
                    "curvature": model.rms_curvature(context.surface), "radius": context.surface.radius,
                    "e_star": study.e_star})
    return out


def rms_log(constants, points) -> float:
    """``√mean ln²(A_model/A_BEM)`` over every point with *constants* (κ, c_s, n)."""
    kappa, summit, order = constants
    residuals = [np.log(model.three_regime_area(p["force"], radius=p["radius"], e_star=p["e_star"],
                                                rms_slope=p["slope"], rms_curvature=p["curvature"], kappa=kappa,
                                                summit=summit, order=order) / p["area"]) for p in points]
    return float(np.sqrt(np.mean(np.concatenate(residuals) ** 2)))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("config")
    parser.add_argument("results")
    parser.add_argument("--heldout", nargs=2, action="append", default=[], metavar=("CONFIG", "RESULTS"))
    args = parser.parse_args(argv)
    points = resolved_points(args.config, args.results)
    start = (model.KAPPA, model.SUMMIT, model.ORDER)
    fit = minimize(lambda c: rms_log(c, points), start, method="Nelder-Mead",
                   options={"maxiter": 4000, "xatol": 1e-5, "fatol": 1e-10})
    print(f"{sum(len(p['force']) for p in points)} area-resolved loads in {len(points)} combinations")
    print(f"fitted kappa = {fit.x[0]:.4f}, c_s = {fit.x[1]:.4f}, n = {fit.x[2]:.4f}: rms ln {fit.fun:.4f}")
    print(f"module's constants {start}: rms ln {rms_log(start, points):.4f}")
    for config, results in args.heldout:
        for p in resolved_points(config, results):
            label = ", ".join(f"{k} {p['where'][k]:g}" for k in ("hurst", "radius", "h_rms", "cutoff"))
            if len(p["force"]):
                print(f"held out {results} ({label}): {len(p['force'])} loads, rms ln {rms_log(fit.x, [p]):.4f}")
    return 0 if math.isfinite(fit.fun) else 1


if __name__ == "__main__":
    sys.exit(main())
