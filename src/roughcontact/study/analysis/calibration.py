"""Calibration of the scorecard's own model on the BEM ensembles of named presets.

The model (:mod:`roughcontact.models.superposition`) has two constants: a factor ``c`` on
the ζ(H) law of flat surfaces (:func:`roughcontact.models.zeta_law.zeta_law`; a sphere's
fractal branch need not carry the prefactor of a flat, periodic surface) and the order ``p``
of the p-norm that joins the body's and the roughness's forces. In the form ``constant``
(``contact_scale``) they are two numbers; in the form ``hurst`` (``contact_scale_h``) each is
linear in H, ``c = c₀ + c₁ H`` and ``p = p₀ + p₁ H`` (four numbers); the form ``tail``
(``contact_scale_tail``) adds the β of the join's tail towards the body's law (five). They minimise

    χ² = Σ_combinations Σ_resolved F ((ln k̄_BEM − ln k_model(F; c, p)) / s)²,

``k̄_BEM`` the ensemble mean over seeds, ``s`` its relative standard error (at least 1 %),
over the sphere combinations at the paper's setting (paraboloid, no roll-off or cutoff,
elastic) of every study given, loads resolved as in the scorecard (mean contact cells ≥
``fit.resolved_cells``). Run it as

    python -m roughcontact.study.analysis.calibration [--form hurst|tail] [--bootstrap N] STUDY_DIR [STUDY_DIR ...]

(each a directory a preset ran in); it prints the constants and every combination's largest
deviation. With ``--bootstrap N`` each constant carries a 95 % percentile interval over seeds
(Efron & Tibshirani, *An Introduction to the Bootstrap*, 1993, ch. 13): each study's seeds are
resampled with replacement, the *same* indices for all its combinations (equal seeds give the
same roughness pattern, so a study's combinations share one sampling offset), the means and
their errors formed again and the constants refitted. The constants in
:data:`roughcontact.models.superposition.CALIBRATED` (form ``constant``),
:data:`~roughcontact.models.superposition.CALIBRATED_HURST` (form ``hurst``) and
:data:`~roughcontact.models.superposition.CALIBRATED_TAIL` (form ``tail``) were made so.
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
from .statistics import BOOTSTRAP_SEED, interval
from ..config.settings import StudySettings
from ..files.directory import StudyDirectory

__all__ = ["FORMS", "Calibration", "ensemble_points", "calibrate", "main"]

#: floor of the relative standard error of an ensemble mean in the weights
MIN_RELATIVE_ERROR = 0.01
#: the forms of the constants: their start values and bounds, and which of the fitted numbers each
#: constant takes (``slots``): a polynomial in H, rising order (:func:`_constants`; one number: a constant)
FORMS = {
    "constant": {"start": [1.0, 1.5], "bounds": ([0.2, 1.0], [5.0, 50.0]),
                 "slots": {"zeta_factor": slice(0, 1), "power": slice(1, 2)}},
    "hurst": {"start": [1.0, 0.0, 1.5, 0.0], "bounds": ([0.2, -5.0, 0.05, -20.0], [5.0, 5.0, 50.0, 20.0]),
              "slots": {"zeta_factor": slice(0, 2), "power": slice(2, 4)}},
    # started at a sharp crossover (p ≈ 2), where the tail, not the order, sets the approach to Hertz
    "tail": {"start": [1.0, 0.0, 2.0, 0.5, 1.0],
             "bounds": ([0.2, -5.0, 0.05, -20.0, 0.0], [5.0, 5.0, 50.0, 20.0, 100.0]),
             "slots": {"zeta_factor": slice(0, 2), "power": slice(2, 4), "tail": slice(4, 5)}},
}


def _constants(spec: dict, theta, hurst) -> dict:
    """The model's keywords (``zeta_factor``, ``power``, ``tail``) at H from the fitted numbers
    *theta*: each slot's numbers are a polynomial in H (as
    :func:`roughcontact.models.superposition.hurst_constants` reads them)."""
    return {name: float(np.polynomial.polynomial.polyval(hurst, theta[where])) for name, where in spec["slots"].items()}


def ensemble_points(study) -> list[dict]:
    """Per sphere combination at the paper's setting of *study* (a directory a preset ran
    in; :func:`roughcontact.study.config.axes.paper_setting`, none where the sweep lacks it): the
    directory's name and resolved path (``study``, ``source``), ``hurst``, ``radius``, ``h_rms``,
    ``length``, ``e_star``, ``n``, the resolved forces, the ensemble-mean stiffness and its relative
    standard error, and ``samples`` (each seed's stiffness at the resolved loads, ``(seed, load)``)
    for the bootstrap."""
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
        use = resolved(sub["contact_cells"].values.mean(0), study_of_file.fit.resolved_cells)
        mean, error = _mean_and_error(k[:, use])
        out.append({"study": Path(study).name, "source": str(Path(study).resolve()), "hurst": combo["hurst"],
                    "radius": combo["radius"], "h_rms": combo["h_rms"], "length": length, "e_star": e_star,
                    "n": study_of_file.grid.n,
                    "force": sub["force"].values[use], "stiffness": mean, "relative_error": error,
                    "samples": k[:, use]})
    return out


def _mean_and_error(samples):
    """Ensemble mean over seeds and its relative standard error (at least :data:`MIN_RELATIVE_ERROR`)."""
    mean = samples.mean(0)
    error = samples.std(0, ddof=1) / math.sqrt(samples.shape[0]) / mean
    return mean, np.maximum(error, MIN_RELATIVE_ERROR)


def _model(point, zeta_factor, power, tail=0.0):
    return superposition.calibrated_stiffness(
        point["force"], radius=point["radius"], hurst=point["hurst"], h_rms=point["h_rms"], length=point["length"],
        e_star=point["e_star"], zeta_factor=zeta_factor, power=max(power, 1e-3), tail=max(tail, 0.0))


@dataclass(frozen=True)
class Calibration:
    """The calibrated constants and what they rest on.

    Attributes
    ----------
    zeta_factor, power : float or tuple of float
        ``c`` and ``p`` (form ``constant``), or their coefficients ``(c₀, c₁)`` and ``(p₀, p₁)``
        (forms ``hurst`` and ``tail``; module docstring).
    chi2_per_point : float
        χ²/(points − constants fitted) at the optimum (1 if the model is as good as the ensembles'
        scatter).
    points : int
        Resolved loads used.
    max_rel_dev : dict[str, float]
        ``max_F |k_model/k̄_BEM − 1|`` per combination (``study:H..._R..._h...``).
    form : str
        The form of the constants (:data:`FORMS`).
    tail : float
        The join's β (form ``tail``; 0 otherwise).
    zeta_factor_ci, power_ci, tail_ci : tuple
        The ``(low, high)`` percentile interval over the seeds' bootstrap at ``level`` (module
        docstring) of ``c``, ``p`` and β, or one such pair per coefficient (forms ``hurst`` and
        ``tail``); empty without a bootstrap.
    resamples : int
        Bootstrap resamples (0: none).
    level : float
        Confidence level of the intervals.
    """

    zeta_factor: float
    power: float
    chi2_per_point: float
    points: int
    max_rel_dev: dict
    form: str = "constant"
    tail: float = 0.0
    zeta_factor_ci: tuple = ()
    power_ci: tuple = ()
    tail_ci: tuple = ()
    resamples: int = 0
    level: float = 0.95


def calibrate(studies, form: str = "constant", *, resamples: int = 0, level: float = 0.95) -> Calibration:
    """Fit the constants of *form* (:data:`FORMS`) on the sphere ensembles of *studies* (module
    docstring).

    Parameters
    ----------
    studies : iterable of path-like
        Directories the calibration presets ran in.
    form : str
        ``constant``, ``hurst`` or ``tail`` (:data:`FORMS`).
    resamples : int, keyword-only
        Bootstrap resamples of the seeds for the constants' intervals (0: no intervals).
    level : float, keyword-only
        Confidence level of the percentile intervals.

    Returns
    -------
    Calibration
    """
    if form not in FORMS:
        raise ValueError(f"form must be one of {sorted(FORMS)}, got {form!r}")
    if resamples < 0:
        raise ValueError(f"resamples must be >= 0, got {resamples}")
    spec = FORMS[form]
    points = [p for study in studies for p in ensemble_points(study) if p["force"].size]
    if not points:
        raise ValueError("no resolved sphere loads in the studies given")

    def predicted(point, theta):
        return _model(point, **_constants(spec, theta, point["hurst"]))

    def residuals(theta, means=None):
        means = means or [(p["stiffness"], p["relative_error"]) for p in points]
        return np.concatenate([(np.log(mean) - np.log(predicted(p, theta))) / error
                               for p, (mean, error) in zip(points, means)])

    fit = least_squares(residuals, spec["start"], bounds=spec["bounds"])
    replicates = np.array([least_squares(residuals, fit.x, bounds=spec["bounds"], args=(means,)).x
                           for means in _resampled_means(points, resamples)]).reshape(resamples, len(fit.x))
    cis = [interval(replicates[:, i], level) for i in range(len(fit.x))]
    total = sum(p["force"].size for p in points)
    deviations = {f"{p['study']}:H{p['hurst']:g}_R{p['radius']:g}_h{p['h_rms']:g}":
                  float(np.max(np.abs(predicted(p, fit.x) / p["stiffness"] - 1))) for p in points}
    theta = [float(x) for x in fit.x]
    values = {name: _shaped(theta[where]) for name, where in spec["slots"].items()}
    intervals = {f"{name}_ci": _shaped(cis[where]) if resamples else () for name, where in spec["slots"].items()}
    return Calibration(**values, **intervals, chi2_per_point=float(np.sum(fit.fun**2) / max(total - len(theta), 1)),
                       points=total, max_rel_dev=deviations, form=form, resamples=resamples, level=level)


def _shaped(values):
    """One constant's numbers: the number itself for one coefficient, a tuple for several."""
    return values[0] if len(values) == 1 else tuple(values)


def _resampled_means(points, resamples):
    """Per bootstrap resample, the ``(mean, relative error)`` of every point: each study's seeds
    drawn with replacement, the same indices for all its combinations (module docstring)."""
    rng = np.random.default_rng(BOOTSTRAP_SEED)
    seeds = {p["source"]: p["samples"].shape[0] for p in points}
    for _ in range(resamples):
        draw = {study: rng.integers(0, n, size=n) for study, n in seeds.items()}
        yield [_mean_and_error(p["samples"][draw[p["source"]]]) for p in points]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("studies", nargs="+", type=Path, help="directories the calibration presets ran in")
    parser.add_argument("--form", choices=sorted(FORMS), default="constant",
                        help="constant: c and p (contact_scale); hurst: each linear in H (contact_scale_h); "
                             "tail: as hurst, with the join's tail beta (contact_scale_tail)")
    parser.add_argument("--bootstrap", type=int, default=0, metavar="N",
                        help="resamples of the seeds for 95 %% intervals of the constants (default 0: none)")
    args = parser.parse_args(argv)
    if args.bootstrap < 0:
        parser.error(f"--bootstrap must be >= 0, got {args.bootstrap}")
    result = calibrate(args.studies, args.form, resamples=args.bootstrap)

    def show(value, cis):
        scalar = isinstance(value, float)
        values, cis = ([value], [cis]) if scalar else (list(value), list(cis))
        text = [f"{v:.4f}" + (f" [{c[0]:.4f}, {c[1]:.4f}]" if c else "")
                for v, c in zip(values, cis or [()] * len(values))]
        return text[0] if scalar else "(" + ", ".join(text) + ")"

    tail = f"tail = {show(result.tail, result.tail_ci)}, " if "tail" in FORMS[result.form]["slots"] else ""
    print(f"form {result.form}: zeta_factor = {show(result.zeta_factor, result.zeta_factor_ci)}, "
          f"power = {show(result.power, result.power_ci)}, {tail}"
          f"chi2/point = {result.chi2_per_point:.3f}, {result.points} resolved loads"
          + (f"; intervals: {result.level:.0%} over {result.resamples} resamples of the seeds"
             if result.resamples else ""))
    for name, value in result.max_rel_dev.items():
        print(f"  {name}: max |k_model/k_BEM - 1| = {value:.3f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
