"""Calibration of the scorecard's own model on the BEM ensembles of named presets.

The model (:mod:`roughcontact.models.superposition`) has two constants: a factor ``c`` on
the ζ(H) law of flat surfaces (:func:`roughcontact.models.zeta_law.zeta_law`; a sphere's
fractal branch need not carry the prefactor of a flat, periodic surface) and the order ``p``
of the p-norm that joins the body's and the roughness's forces. They minimise

    χ² = Σ_combinations Σ_resolved F ((ln k̄_BEM − ln k_model(F; c, p)) / s)²,

``k̄_BEM`` the ensemble mean over seeds, ``s`` its relative standard error (at least 1 %),
over the sphere combinations at the paper's setting (paraboloid, no roll-off or cutoff,
elastic) of every study given, loads resolved as in the scorecard (mean contact cells ≥
``fit.zeta.min_cells``). Run it as

    python -m roughcontact.study.analysis.calibration STUDY_DIR [STUDY_DIR ...]

(each a directory a preset ran in); it prints the constants and every combination's largest
deviation. The constants in :data:`roughcontact.models.superposition.CALIBRATED` were made
so.
"""
from __future__ import annotations

import argparse
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import least_squares

from ...models import superposition
from ..config import axes
from .ensemble import combinations, resolved
from ..config.settings import StudySettings
from ..files.directory import StudyDirectory

__all__ = ["Calibration", "ensemble_points", "calibrate", "main"]

#: floor of the relative standard error of an ensemble mean in the weights
MIN_RELATIVE_ERROR = 0.01


def ensemble_points(study) -> list[dict]:
    """Per sphere combination at the paper's setting of *study* (a directory a preset ran
    in; :func:`roughcontact.study.config.axes.paper_setting`, none where the sweep lacks it): ``hurst``, ``radius``, ``h_rms``, ``length``, ``e_star``, the resolved forces, the
    ensemble-mean stiffness and its relative standard error."""
    results = StudyDirectory(study)
    study_of_file = StudySettings.of(results.configuration())
    groups = results.groups("stiffness")
    if "sphere" not in groups:
        return []
    length, e_star = study_of_file.grid.length, study_of_file.e_star
    ds = groups["sphere"]
    out = []
    for combo, sub in combinations(ds):
        if not axes.paper_setting(combo, length):
            continue
        k = sub["stiffness"].values
        use = resolved(sub["contact_cells"].values.mean(0), study_of_file.fit.zeta.min_cells)
        mean = k.mean(0)
        error = k.std(0, ddof=1) / math.sqrt(k.shape[0]) / mean
        out.append({"study": Path(study).name, "hurst": combo["hurst"], "radius": combo["radius"],
                    "h_rms": combo["h_rms"], "length": length, "e_star": e_star, "n": study_of_file.grid.n,
                    "force": sub["force"].values[use], "stiffness": mean[use],
                    "relative_error": np.maximum(error[use], MIN_RELATIVE_ERROR)})
    return out


def _model(point, zeta_factor, power):
    return superposition.calibrated_stiffness(
        point["force"], radius=point["radius"], hurst=point["hurst"], h_rms=point["h_rms"], length=point["length"],
        e_star=point["e_star"], zeta_factor=zeta_factor, power=power)


@dataclass(frozen=True)
class Calibration:
    """The calibrated constants and what they rest on.

    Attributes
    ----------
    zeta_factor, power : float
        ``c`` and ``p`` (module docstring).
    chi2_per_point : float
        χ²/(points − 2) at the optimum (1 if the model is as good as the ensembles' scatter).
    points : int
        Resolved loads used.
    max_rel_dev : dict[str, float]
        ``max_F |k_model/k̄_BEM − 1|`` per combination (``study:H..._R..._h...``).
    """

    zeta_factor: float
    power: float
    chi2_per_point: float
    points: int
    max_rel_dev: dict


def calibrate(studies) -> Calibration:
    """Fit ``c`` and ``p`` on the sphere ensembles of *studies* (module docstring)."""
    points = [p for study in studies for p in ensemble_points(study) if p["force"].size]
    if not points:
        raise ValueError("no resolved sphere loads in the studies given")

    def residuals(theta):
        return np.concatenate([(np.log(p["stiffness"]) - np.log(_model(p, *theta))) / p["relative_error"]
                               for p in points])

    fit = least_squares(residuals, [1.0, 1.5], bounds=([0.2, 1.0], [5.0, 50.0]))
    total = sum(p["force"].size for p in points)
    deviations = {f"{p['study']}:H{p['hurst']:g}_R{p['radius']:g}_h{p['h_rms']:g}":
                  float(np.max(np.abs(_model(p, *fit.x) / p["stiffness"] - 1))) for p in points}
    return Calibration(zeta_factor=float(fit.x[0]), power=float(fit.x[1]),
                       chi2_per_point=float(np.sum(fit.fun**2) / max(total - 2, 1)), points=total,
                       max_rel_dev=deviations)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("studies", nargs="+", type=Path, help="directories the calibration presets ran in")
    result = calibrate(parser.parse_args(argv).studies)
    print(f"zeta_factor = {result.zeta_factor:.4f}, power = {result.power:.4f}, "
          f"chi2/point = {result.chi2_per_point:.3f}, {result.points} resolved loads")
    for name, value in result.max_rel_dev.items():
        print(f"  {name}: max |k_model/k_BEM - 1| = {value:.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
