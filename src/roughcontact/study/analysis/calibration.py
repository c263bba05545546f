"""Calibration of the scorecard's own model on the BEM ensembles of named presets.

The model (:mod:`roughcontact.models.superposition`) has two constants: a factor ``c`` on
the ζ(H) law of flat surfaces (:func:`roughcontact.models.zeta_law.zeta_law`; a sphere's
fractal branch need not carry the prefactor of a flat, periodic surface) and the order ``p``
of the p-norm that joins the body's and the roughness's forces. In the form ``constant``
(``contact_scale``) they are two numbers; in the form ``hurst`` (``contact_scale_h``) each is
linear in H, ``c = c₀ + c₁ H`` and ``p = p₀ + p₁ H`` (four numbers). They minimise

    χ² = Σ_combinations Σ_resolved F ((ln k̄_BEM − ln k_model(F; c, p)) / s)²,

``k̄_BEM`` the ensemble mean over seeds, ``s`` its relative standard error (at least 1 %),
over the sphere combinations at the paper's setting (paraboloid, no roll-off or cutoff,
elastic) of every study given, loads resolved as in the scorecard (mean contact cells ≥
``fit.zeta.min_cells``). Run it as

    python -m roughcontact.study.analysis.calibration [--form hurst] STUDY_DIR [STUDY_DIR ...]

(each a directory a preset ran in); it prints the constants and every combination's largest
deviation. The constants in :data:`roughcontact.models.superposition.CALIBRATED` (form
``constant``) and :data:`~roughcontact.models.superposition.CALIBRATED_HURST` (form ``hurst``)
were made so.
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

__all__ = ["FORMS", "Calibration", "ensemble_points", "calibrate", "main"]

#: floor of the relative standard error of an ensemble mean in the weights
MIN_RELATIVE_ERROR = 0.01
#: the forms of the constants: their start values and bounds, and (c, p) at H from them
FORMS = {
    "constant": {"start": [1.0, 1.5], "bounds": ([0.2, 1.0], [5.0, 50.0]),
                 "constants": lambda theta, hurst: (theta[0], theta[1])},
    "hurst": {"start": [1.0, 0.0, 1.5, 0.0], "bounds": ([0.2, -5.0, 0.05, -20.0], [5.0, 5.0, 50.0, 20.0]),
              "constants": lambda theta, hurst: superposition.hurst_constants(
                  hurst, {"zeta_factor": theta[:2], "power": theta[2:]})},
}


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
        e_star=point["e_star"], zeta_factor=zeta_factor, power=max(power, 1e-3))


@dataclass(frozen=True)
class Calibration:
    """The calibrated constants and what they rest on.

    Attributes
    ----------
    zeta_factor, power : float or tuple of float
        ``c`` and ``p`` (form ``constant``), or their coefficients ``(c₀, c₁)`` and ``(p₀, p₁)``
        (form ``hurst``; module docstring).
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
    form: str = "constant"


def calibrate(studies, form: str = "constant") -> Calibration:
    """Fit the constants of *form* (:data:`FORMS`) on the sphere ensembles of *studies* (module
    docstring)."""
    if form not in FORMS:
        raise ValueError(f"form must be one of {sorted(FORMS)}, got {form!r}")
    spec = FORMS[form]
    points = [p for study in studies for p in ensemble_points(study) if p["force"].size]
    if not points:
        raise ValueError("no resolved sphere loads in the studies given")

    def predicted(point, theta):
        return _model(point, *spec["constants"](theta, point["hurst"]))

    def residuals(theta):
        return np.concatenate([(np.log(p["stiffness"]) - np.log(predicted(p, theta))) / p["relative_error"]
                               for p in points])

    fit = least_squares(residuals, spec["start"], bounds=spec["bounds"])
    total = sum(p["force"].size for p in points)
    deviations = {f"{p['study']}:H{p['hurst']:g}_R{p['radius']:g}_h{p['h_rms']:g}":
                  float(np.max(np.abs(predicted(p, fit.x) / p["stiffness"] - 1))) for p in points}
    theta = [float(x) for x in fit.x]
    half = len(theta) // 2
    zeta_factor, power = (theta[0], theta[1]) if form == "constant" else (tuple(theta[:half]), tuple(theta[half:]))
    return Calibration(zeta_factor=zeta_factor, power=power,
                       chi2_per_point=float(np.sum(fit.fun**2) / max(total - len(theta), 1)), points=total,
                       max_rel_dev=deviations, form=form)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("studies", nargs="+", type=Path, help="directories the calibration presets ran in")
    parser.add_argument("--form", choices=sorted(FORMS), default="constant",
                        help="constant: c and p (contact_scale); hurst: each linear in H (contact_scale_h)")
    args = parser.parse_args(argv)
    result = calibrate(args.studies, args.form)

    def show(value):
        return f"{value:.4f}" if isinstance(value, float) else "(" + ", ".join(f"{v:.4f}" for v in value) + ")"

    print(f"form {result.form}: zeta_factor = {show(result.zeta_factor)}, power = {show(result.power)}, "
          f"chi2/point = {result.chi2_per_point:.3f}, {result.points} resolved loads")
    for name, value in result.max_rel_dev.items():
        print(f"  {name}: max |k_model/k_BEM - 1| = {value:.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
