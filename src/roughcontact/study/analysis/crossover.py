"""The crossover table (``crossover.csv``, rule ``crossover``): per sphere combination, the
crossover force of eq. 17 (eq. 16 fitted with free prefactors), the asymptotic slopes and the
deviation from eq. 16, each with its 95 % interval and verdicts; the claims table built from them
is :mod:`roughcontact.study.claims`.

Every measured quantity carries a percentile bootstrap interval over seeds
(Efron & Tibshirani, *An Introduction to the Bootstrap*, 1993, ch. 13): the
seeds are resampled with replacement, the ensemble mean is formed again and
the estimate recomputed, with one fixed random state, so the numbers are
identical on every run. All sphere combinations resample the *same* seed
indices, because equal seeds give the same roughness pattern (only scaled by
h_rms), which keeps the replicates of different combinations paired.

Verdicts
--------
``consistent``
    the paper's value lies inside the 95 % interval (it is not excluded);
``differs``
    the interval excludes it;
``unresolved``
    (crossover force) the resolved loads do not bracket the crossover;
``untested``
    the sweep cannot test the claim; the reason is given.

Forces are normalised, F/(E* L²), and stiffnesses k/(E* L) throughout.
"""
from __future__ import annotations

import dataclasses
import logging
import math

import numpy as np

from ...models import paper
from . import ensemble
from .eq16_fit import Eq16Fit, _slopes, fit_eq16
from .statistics import BOOTSTRAP_SEED, bootstrap_indices, interval, verdict
from ..config.settings import StudySettings
from ..runs import naming as runs

__all__ = ["Eq16Fit", "fit_eq16", "SphereCase", "VerdictWindows", "SphereVerdicts", "sphere_verdicts", "crossover_table",
           "CROSSOVER_COLUMNS", "NO_SPHERE"]

log = logging.getLogger(__name__)

# --------------------------------------------------------------------------
# one sphere combination (H, R, h_rms)
# --------------------------------------------------------------------------
@dataclasses.dataclass(frozen=True)
class SphereVerdicts:
    """Estimates, 95 % intervals and verdicts of one sphere combination.

    ``row`` is the combination's row of ``crossover.csv`` (a dict of the
    documented columns); ``crossover_replicates`` holds the bootstrap
    replicates of the measured F_tr (NaN where a replicate's fit failed), for
    the scaling claim across combinations.
    """

    row: dict
    crossover_replicates: np.ndarray


@dataclasses.dataclass(frozen=True)
class SphereCase:
    """One sphere combination (lengths in one unit, that of ``length``).

    Attributes
    ----------
    hurst, radius, h_rms, length : float
        Hurst exponent, body radius, rms roughness height, side ``L`` of the surface.
    exponent : float
        Body of revolution ``z = (R/m)(r/R)^m`` (2: the paper's paraboloid): eqs. 16 and 17
        with the smooth body's eq. 7 in place of Hertz.
    """

    hurst: float
    radius: float
    h_rms: float
    length: float
    exponent: float = 2.0


@dataclasses.dataclass(frozen=True)
class VerdictWindows:
    """Which loads the verdicts use (``fit.resolved_cells``, ``fit.confidence`` and ``fit.slopes`` of the configuration).

    Attributes
    ----------
    min_cells : int
        A load is resolved when its mean contact cells are at least this many.
    low_max_ratio, high_min_ratio : float
        Slope windows ``F ≤ low_max_ratio·F_tr`` (resolved loads) and ``F ≥ high_min_ratio·F_tr``,
        F_tr of eq. 17 with the fitted ζ.
    level : float
        Confidence level of the intervals.
    """

    min_cells: int
    low_max_ratio: float
    high_min_ratio: float
    level: float = 0.95

    @classmethod
    def of(cls, fit) -> "VerdictWindows":
        """The windows of a study's :class:`~roughcontact.study.config.settings.FitSettings`."""
        return cls(min_cells=fit.resolved_cells, low_max_ratio=fit.slopes.low_max_ratio,
                   high_min_ratio=fit.slopes.high_min_ratio, level=fit.confidence)


def sphere_verdicts(force, stiffness, contact_cells, *, case: SphereCase, zeta_fit: float,
                    indices: np.ndarray, windows: VerdictWindows) -> SphereVerdicts:
    """Crossover force, slopes and eq. 16 checks of one sphere combination.

    Parameters
    ----------
    force : array_like, shape (m,)
        Loads F/(E* L²).
    stiffness, contact_cells : array_like, shape (seeds, m)
        Per-seed stiffness k/(E* L) and contact cells.
    case : SphereCase
        The combination.
    zeta_fit : float
        ζ(H) fitted elsewhere (flat surfaces), NaN if none: eq. 17's first prediction.
    indices : ndarray, shape (resamples, seeds)
        Bootstrap seed indices (:func:`bootstrap_indices`).
    windows : VerdictWindows
        The loads the estimates use, and the confidence level.
    """
    hurst, radius, h_rms, length, exponent = case.hurst, case.radius, case.h_rms, case.length, case.exponent
    min_cells, low_max_ratio, high_min_ratio = windows.min_cells, windows.low_max_ratio, windows.high_min_ratio
    level = windows.level
    F = np.asarray(force, dtype=float)
    k_seeds = np.asarray(stiffness, dtype=float)
    cells = np.asarray(contact_cells, dtype=float).mean(0)
    L = length
    notes = []
    z_est = float(paper.zeta_estimate(hurst))
    z_used = zeta_fit if math.isfinite(zeta_fit) else z_est
    if not math.isfinite(zeta_fit):
        notes.append("no fitted zeta: 1.7/(H+1) used for eq. 16 and the slope windows")
    m = exponent
    f_pred_fit = paper.crossover_force(radius, hurst=hurst, h_rms=h_rms, length=L, e_star=1.0, zeta=zeta_fit, exponent=m) / L**2
    f_pred_est = paper.crossover_force(radius, hurst=hurst, h_rms=h_rms, length=L, e_star=1.0, zeta=z_est, exponent=m) / L**2
    f_window = f_pred_fit if math.isfinite(f_pred_fit) else f_pred_est
    resolved = ensemble.resolved(cells, min_cells)   # the loads this combination's verdicts may use
    k_mean = k_seeds.mean(0)
    k_boot = k_seeds[indices].mean(1)          # (resamples, m): ensemble means of resampled seeds
    row = {"hurst": hurst, "radius": radius, "exponent": m, "h_rms": h_rms, "zeta_fit": zeta_fit, "zeta_estimate": z_est,
           "Ftr_pred_fit": f_pred_fit, "Ftr_pred_estimate": f_pred_est}

    # crossover: eq. 16 with free prefactors over every resolved load
    Fr = F[resolved]
    replicates = np.full(indices.shape[0], np.nan)
    if resolved.sum() >= 4:
        fit = fit_eq16(Fr, k_mean[resolved], hurst, exponent=m)
        boot = fit_eq16(Fr, k_boot[:, resolved], hurst, exponent=m)
        f_tr = float(fit.crossover_force)
        replicates = np.where(np.isfinite(boot.crossover_force), boot.crossover_force, np.nan)
        below, above = int((Fr < f_tr).sum()), int((Fr > f_tr).sum())
        if below >= 2 and above >= 2:
            lo, hi = interval(replicates, level)
            reason = ""
        else:
            lo = hi = math.nan
            reason = (f"unresolved: {below} resolved loads below and {above} above the fitted F_tr = {f_tr:.3g}; "
                      "eq. 16 needs at least 2 on each side")
            replicates = np.full(indices.shape[0], np.nan)
        # the prefactors mean something only where both terms are seen: left NaN for an unresolved crossover
        if reason:
            a = b = a_lo = a_hi = b_lo = b_hi = zs_lo = zs_hi = math.nan
        else:
            a, b = float(fit.hertz_coefficient), float(fit.rough_coefficient)
            a_lo, a_hi = interval(boot.hertz_coefficient, level)
            b_lo, b_hi = interval(boot.rough_coefficient, level)
            zs_lo, zs_hi = interval((h_rms / L / boot.rough_coefficient) ** (1 / (hurst + 1)), level)
        row.update({"Ftr_measured": f_tr if not reason else math.nan, "Ftr_ci_low": lo, "Ftr_ci_high": hi,
                    "hertz_coefficient": a, "hertz_coefficient_ci_low": a_lo,
                    "hertz_coefficient_ci_high": a_hi,
                    # k/(E* L) = 1 is the contact radius a = L/2 (k = 2 E* a)
                    "hertz_coefficient_theory": float(paper.body_indentation(L / 2, radius=radius, e_star=1.0, exponent=m).force)
                    / L**2,
                    "rough_coefficient": b, "rough_coefficient_ci_low": b_lo,
                    "rough_coefficient_ci_high": b_hi,
                    "rough_coefficient_eq12": h_rms / L * z_used ** -(hurst + 1),
                    "zeta_sphere": (h_rms / L / b) ** (1 / (hurst + 1)),
                    "zeta_sphere_ci_low": zs_lo, "zeta_sphere_ci_high": zs_hi})
    else:
        reason = f"unresolved: only {int(resolved.sum())} resolved loads (eq. 16 has 2 free prefactors; need >= 4)"
        lo = hi = math.nan
        row.update({"Ftr_measured": math.nan, "Ftr_ci_low": math.nan, "Ftr_ci_high": math.nan})
    for column, predicted in (("verdict_fit", f_pred_fit), ("verdict_estimate", f_pred_est)):
        row[column] = reason.split(":")[0] if reason else verdict(predicted, lo, hi)
    if reason:
        notes.append(reason)

    # asymptotic slopes
    for name, mask, theory_value in (
        # the term with the smaller exponent dominates at small forces: roughness if H < m, else the body
        ("slope_low", resolved & (F <= low_max_ratio * f_window), 1 / (min(hurst, m) + 1)),
        ("slope_high", resolved & (F >= high_min_ratio * f_window), 1 / (max(hurst, m) + 1)),
    ):
        row[f"{name}_theory"] = theory_value
        row[f"n_loads_{name.split('_')[1]}"] = int(mask.sum())
        if mask.sum() >= 2:
            log_f = np.log(F[mask])
            value = float(_slopes(log_f, np.log(k_mean[mask])))
            s_lo, s_hi = interval(_slopes(log_f, np.log(k_boot[:, mask])), level)
            k16 = paper.stiffness_from_force(F[mask] * L**2, radius=radius, hurst=hurst, h_rms=h_rms, length=L, e_star=1.0, zeta=z_used, exponent=m) / L
            row.update({name: value, f"{name}_ci_low": s_lo, f"{name}_ci_high": s_hi,
                        f"{name}_eq16": float(_slopes(log_f, np.log(k16))),
                        f"{name}_verdict": verdict(theory_value, s_lo, s_hi)})
        else:
            row.update({name: math.nan, f"{name}_ci_low": math.nan, f"{name}_ci_high": math.nan,
                        f"{name}_eq16": math.nan,
                        f"{name}_verdict": f"untested: {int(mask.sum())} loads in the window"})

    # eq. 16 (fitted zeta, no free parameter) against the ensemble, and k against Hertz below F_tr
    if resolved.any():
        k16 = paper.stiffness_from_force(Fr * L**2, radius=radius, hurst=hurst, h_rms=h_rms, length=L, e_star=1.0, zeta=z_used, exponent=m) / L
        dev = np.abs(k_boot[:, resolved] / k16 - 1).max(-1)
        d_lo, d_hi = interval(dev, level)
        log_dev = np.abs(np.log10(k_mean[resolved] / k16))
        row.update({"eq16_max_rel_dev": float(np.abs(k_mean[resolved] / k16 - 1).max()),
                    "eq16_max_rel_dev_ci_low": d_lo, "eq16_max_rel_dev_ci_high": d_hi,
                    "max_abs_log10_k_over_eq16": float(log_dev.max()),
                    "rms_log10_k_over_eq16": float(np.sqrt(np.mean(log_dev**2)))})
    f_split = row["Ftr_measured"] if math.isfinite(row["Ftr_measured"]) else f_window
    soft = resolved & (F < f_split)
    row["n_loads_below_Ftr"] = int(soft.sum())
    if soft.any():   # eq. 16 on the fractal branch alone: the resolved loads below F_tr (k16 at Fr above)
        k16_soft = k16[soft[resolved]]
        signed = k_boot[:, soft] / k16_soft - 1
        m_lo, m_hi = interval(np.abs(signed).max(-1), level)
        s_lo, s_hi = interval(signed.mean(-1), level)
        row.update({"eq16_fractal_max_rel_dev": float(np.abs(k_mean[soft] / k16_soft - 1).max()),
                    "eq16_fractal_max_rel_dev_ci_low": m_lo, "eq16_fractal_max_rel_dev_ci_high": m_hi,
                    "eq16_fractal_mean_rel_dev": float((k_mean[soft] / k16_soft - 1).mean()),
                    "eq16_fractal_mean_rel_dev_ci_low": s_lo, "eq16_fractal_mean_rel_dev_ci_high": s_hi})
    if soft.any():
        k_h = paper.body_stiffness(F[soft] * L**2, radius=radius, e_star=1.0, exponent=m) / L
        ratio = (k_boot[:, soft] / k_h).max(-1)
        r_lo, r_hi = interval(ratio, level)
        row.update({"k_over_hertz_below_Ftr": float((k_mean[soft] / k_h).max()),
                    "k_over_hertz_below_Ftr_ci_low": r_lo, "k_over_hertz_below_Ftr_ci_high": r_hi})
    row.update({"n_loads": int(F.size), "n_loads_resolved": int(resolved.sum()),
                "force_min_resolved": float(Fr.min()) if Fr.size else math.nan, "force_max": float(F.max()),
                "n_seeds": int(k_seeds.shape[0]), "confidence": level, "note": "; ".join(notes)})
    return SphereVerdicts(row=row, crossover_replicates=replicates)


# --------------------------------------------------------------------------
# tables
# --------------------------------------------------------------------------
#: the columns of crossover.csv after the sphere axes (the header of a table without a row; a row may
#: have more: the prefactors and deviations of eq. 16 where they were measured)
CROSSOVER_COLUMNS = ("zeta_fit", "zeta_estimate", "Ftr_pred_fit", "Ftr_pred_estimate", "Ftr_measured", "Ftr_ci_low",
                     "Ftr_ci_high", "verdict_fit", "verdict_estimate", "slope_low", "slope_low_ci_low",
                     "slope_low_ci_high", "slope_low_verdict", "slope_high", "slope_high_ci_low", "slope_high_ci_high",
                     "slope_high_verdict", "n_loads", "n_loads_resolved", "n_seeds", "confidence", "note")

#: why crossover.csv and models.csv have no row: the sweep has no sphere
NO_SPHERE = "the sweep has no sphere (every radius is .inf), so no crossover force and no model scorecard"


def crossover_table(groups: dict, zeta_df, study):
    """``crossover.csv`` (one row per sphere combination of every sweep axis,
    :func:`sphere_verdicts`) and a Dataset of the bootstrap replicates of the
    measured F_tr over those axes and ``replicate``."""
    import pandas as pd
    import xarray as xr

    if "sphere" not in groups:
        return pd.DataFrame(columns=[*runs.AXES["sphere"], *CROSSOVER_COLUMNS]), xr.Dataset()
    study = StudySettings.of(study)
    ds = groups["sphere"]
    L, E = study.grid.length, study.e_star
    windows = VerdictWindows.of(study.fit)
    resamples = study.fit.bootstrap
    indices = bootstrap_indices(ds.sizes["seed"], resamples)
    zeta_of = dict(zip(zeta_df["hurst"], zeta_df["zeta"])) if len(zeta_df) else {}
    axes = [d for d in ds["stiffness"].dims if d not in ("seed", "force")]
    replicates = np.full([ds.sizes[a] for a in axes] + [resamples], np.nan)
    force = ds["force"].values / (E * L**2)
    rows = []
    for number, (combo, sub) in enumerate(ensemble.combinations(ds)):
        result = sphere_verdicts(
            force, sub["stiffness"].values / (E * L), sub["contact_cells"].values,
            case=SphereCase(hurst=combo["hurst"], radius=combo["radius"], h_rms=combo["h_rms"], length=L,
                            exponent=combo.get("exponent", 2.0)),
            zeta_fit=float(zeta_of.get(combo["hurst"], math.nan)), indices=indices, windows=windows)
        rows.append({**combo, **result.row})
        replicates[np.unravel_index(number, replicates.shape[:-1])] = result.crossover_replicates
    reps = xr.Dataset(
        {"Ftr_replicates": ((*axes, "replicate"), replicates,
                            {"long_name": "bootstrap replicates of the measured crossover force F_tr/(E* L^2)",
                             "units": "1"})},
        coords={**{a: ds[a] for a in axes}, "replicate": np.arange(resamples)},
        attrs={"bootstrap_over": "seeds (the same resampled indices for every combination)",
               "bootstrap_seed": BOOTSTRAP_SEED})
    return pd.DataFrame(rows), reps
