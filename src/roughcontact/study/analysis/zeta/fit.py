"""ζ(H) of eq. 11 fitted on the merged runs, with bootstrap-over-seeds intervals.

Imports pandas (the ``pipeline`` extra) where it is used. Forces in the table are
normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import logging
import math

import numpy as np

from ....models import paper
from ...config import axes
from ...files import provenance
from ..ensemble import resolved
from ...files.io import read_groups, write_csv, write_netcdf
from ..statistics import bootstrap_indices, log_log_slope
from ...config.settings import StudySettings

__all__ = ["paper_setting", "off_paper", "fit_zeta"]

log = logging.getLogger(__name__)


# --------------------------------------------------------------------------
# ζ(H)
# --------------------------------------------------------------------------
def _selection(ds, length: float) -> tuple[dict, dict]:
    """``(pick, substituted)``: the coordinate of every optional axis of *ds* at the paper's setting
    (:func:`roughcontact.study.config.axes.paper_coordinates`), and those the sweep lacks, replaced by
    its first value."""
    pick, substituted = {}, {}
    for axis, value in axes.paper_coordinates(length).items():
        if axis not in ds.dims:
            continue
        if value not in ds[axis].values:
            value = substituted[axis] = float(ds[axis].values[0])
        pick[axis] = value
    return pick, substituted


def paper_setting(ds, length: float):
    """*ds* at the paper's setting of the optional axes (paraboloid, no roll-off, no cutoff,
    elastic, no adhesion: :func:`roughcontact.study.config.axes.paper_coordinates`), those dimensions
    dropped; where the sweep lacks the paper's value, its first value is taken. Returns the
    selection and a note naming such substitutions ("" if none)."""
    pick, substituted = _selection(ds, length)
    notes = [f"{axis} = {value:g}" for axis, value in substituted.items()]
    return ds.sel(pick), ("with " + ", ".join(notes)) if notes else ""


def off_paper(groups: dict, length: float) -> dict:
    """``{axis: coordinate}`` of the optional axes at which :func:`fit_zeta` fits ζ(H) off the
    paper's setting (the runs it reads, flat ones if there are, lack the paper's value); ``{}``
    where it fits at the paper's setting."""
    kind = "flat" if "flat" in groups else "sphere"
    return _selection(groups[kind], length)[1] if kind in groups else {}


def _zeta_points(groups, study: StudySettings, hurst):
    """Per seed: arrays x = ln(F_r/(E h L)), y = ln(k/(E L)) inside the fit window,
    and the source label.  F_r is F for flat runs and F minus the Hertz force
    at the same k (eq. 16) for spheres."""
    L, E = study.grid.length, study.e_star
    zc = study.fit.zeta
    if "flat" in groups:
        ds, note = paper_setting(groups["flat"], L)
        source = "flat"
        radii = [math.inf]
    else:
        ds, note = paper_setting(groups["sphere"], L)
        radii = ds["radius"].values.tolist()
        source = ("sphere small-force branch (no flat runs): eq. 16 minus its Hertz term; "
                  "no free exponent (the window is too narrow)")
    if note:
        source += f" ({note})"
    points = []
    for seed in study.seeds:
        xs, ys, fs = [], [], []
        for radius in radii:
            for h in ds["h_rms"].values.tolist():
                sub = ds.sel(hurst=hurst, h_rms=h, seed=seed)
                if math.isfinite(radius):
                    sub = sub.sel(radius=radius)
                F = sub["force"].values
                k = sub["stiffness"].values
                ok = resolved(sub["contact_cells"].values, study.fit.resolved_cells)
                if math.isfinite(radius):
                    m = float(sub["exponent"]) if "exponent" in sub.coords else 2.0
                    f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h, length=L, e_star=E, zeta=paper.zeta_estimate(hurst), exponent=m)
                    ok &= F <= zc.sphere_max_force_ratio * f_tr
                    # eq. 16: the roughness carries F minus the smooth body's force at the same k = 2 E* a
                    Fr = F - paper.body_indentation(k / (2 * E), radius=radius, e_star=E, exponent=m).force
                    ok &= Fr > 0.1 * F
                else:
                    ok &= sub["contact_area"].values / L**2 <= zc.max_area_fraction
                    Fr = F
                xs.append(np.log(Fr[ok] / (E * h * L)))
                ys.append(np.log(k[ok] / (E * L)))
                fs.append(F[ok] / (E * L**2))
        points.append((np.concatenate(xs), np.concatenate(ys), np.concatenate(fs)))
    return points, source


def _zeta_stats(points, hurst):
    x = np.concatenate([p[0] for p in points])
    y = np.concatenate([p[1] for p in points])
    if x.size == 0:
        return math.nan, math.nan
    ln_zeta = float(np.mean(y - x / (hurst + 1)))
    slope = float(log_log_slope(x, y)) if x.size >= 2 and np.ptp(x) > 0 else math.nan
    return math.exp(ln_zeta), slope


#: the columns of zeta.csv (the header of a table without a row: a sweep without generated surfaces)
ZETA_COLUMNS = ("hurst", "zeta", "zeta_ci_low", "zeta_ci_high", "zeta_estimate", "exponent", "exponent_ci_low",
                "exponent_ci_high", "exponent_theory", "n_points", "n_seeds", "force_min", "force_max", "confidence",
                "source", "window")

#: why zeta.csv has no row
NO_HURST = "the sweep has no generated surface (hurst is empty), so no fit of zeta(H)"


def fit_zeta(groups, study):
    """ζ(H) from eq. 11 (exponent fixed to 1/(H+1)) and the free exponent, with
    bootstrap-over-seeds confidence intervals.  Returns (DataFrame, Dataset).

    Fit window: loads with at least ``fit.resolved_cells`` contact cells and,
    for flat surfaces, a contact area fraction at most
    ``fit.zeta.max_area_fraction``.  Without flat runs the sphere loads below
    ``fit.zeta.sphere_max_force_ratio`` × F_tr (eq. 17, ζ = 1.7/(H+1)) are used
    after subtracting the Hertz force at the same stiffness (eq. 16).
    """
    import pandas as pd

    study = StudySettings.of(study)
    zc = study.fit.zeta
    n_boot = study.fit.bootstrap
    level = study.fit.confidence
    rows, replicates = [], []
    for hurst in study.hurst:
        points, source = _zeta_points(groups, study, hurst)
        zeta, slope = _zeta_stats(points, hurst)
        flat = source.startswith("flat")
        boots = []
        if len(points) > 1 and math.isfinite(zeta):
            boots = [_zeta_stats([points[i] for i in pick], hurst)
                     for pick in bootstrap_indices(len(points), n_boot)]
        boots = np.array(boots) if boots else np.full((n_boot, 2), np.nan)
        replicates.append(boots[:, 0])
        q = [(1 - level) / 2 * 100, (1 + level) / 2 * 100]
        with np.errstate(all="ignore"):
            zlo, zhi = np.nanpercentile(boots[:, 0], q) if np.isfinite(boots[:, 0]).any() else (math.nan, math.nan)
            slo, shi = np.nanpercentile(boots[:, 1], q) if np.isfinite(boots[:, 1]).any() else (math.nan, math.nan)
        f_all = np.concatenate([p[2] for p in points])
        rows.append({
            "hurst": hurst,
            "zeta": zeta,
            "zeta_ci_low": zlo,
            "zeta_ci_high": zhi,
            "zeta_estimate": float(paper.zeta_estimate(hurst)),
            "exponent": slope if flat else math.nan,
            "exponent_ci_low": slo if flat else math.nan,
            "exponent_ci_high": shi if flat else math.nan,
            "exponent_theory": 1 / (hurst + 1),
            "n_points": int(f_all.size),
            "n_seeds": len(points),
            "force_min": float(f_all.min()) if f_all.size else math.nan,
            "force_max": float(f_all.max()) if f_all.size else math.nan,
            "confidence": level,
            "source": source if f_all.size else f"no loads in the fit window ({source})",
            "window": (f"contact cells >= {study.fit.resolved_cells}, "
                       + (f"A/L^2 <= {zc.max_area_fraction}" if flat
                          else f"F <= {zc.sphere_max_force_ratio} F_tr(eq. 17, zeta = 1.7/(H+1))")),
        })
    df = pd.DataFrame(rows) if rows else pd.DataFrame(columns=ZETA_COLUMNS)
    zds = df.set_index("hurst").to_xarray()
    zds["zeta_replicates"] = (("hurst", "replicate"), np.array(replicates).reshape(len(rows), n_boot), {
        "long_name": "zeta of each bootstrap resample of the seeds (the same resamples for every H)",
        "units": "1"})
    zds.attrs.update(provenance.provenance_attrs(
        config=study.config, title="zeta(H) fitted from eq. 11 (k/(E* L) = zeta (F/(E* h L))^(1/(H+1)))",
        bootstrap_resamples=n_boot, bootstrap_over="seeds", forces="F/(E* L^2)"))
    return df, zds
