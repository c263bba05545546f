"""Merge, ensemble statistics, the ζ(H) fit and the crossover check.

Imports xarray and pandas (the ``pipeline`` extra); ``import roughcontact``
does not import this module.

All forces in the tables are normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from . import provenance, study, theory

__all__ = ["MergeError", "read_run", "merge_runs", "ensemble", "fit_zeta", "crossover",
           "write_netcdf", "write_csv"]


class MergeError(RuntimeError):
    """A run file that cannot be merged; the message names the file and the cause."""


# --------------------------------------------------------------------------
# I/O
# --------------------------------------------------------------------------
def write_netcdf(ds, path) -> None:
    """Atomic NetCDF4 write (temp file, then rename)."""
    with provenance.atomic_path(path) as tmp:
        ds.to_netcdf(tmp, engine="netcdf4")


def write_csv(df, path) -> None:
    with provenance.atomic_path(path) as tmp:
        df.to_csv(tmp, index=False, float_format="%.6g")


def read_run(path, expected: dict | None = None):
    """Open one run file, check it and return it loaded in memory.

    Raises :class:`MergeError` naming *path* for a truncated, foreign or stale
    file.  *expected* (the job settings of the current config) enables the
    stale check.
    """
    import xarray as xr

    path = str(path)
    hint = f"delete {path} and rerun snakemake to recompute it"
    if not os.path.exists(path):
        raise MergeError(f"{path}: run file is missing; rerun snakemake to compute it")
    try:
        with xr.open_dataset(path, engine="netcdf4") as ds:
            ds = ds.load()
    except Exception as exc:
        raise MergeError(f"{path}: not a readable NetCDF file ({type(exc).__name__}: {exc}); "
                         f"it may be truncated; {hint}") from exc
    missing = [v for v in (*study.RUN_VARIABLES, "force", "hurst", "radius", "h_rms", "seed")
               if v not in ds.variables]
    if missing or ds.attrs.get("title") != "roughcontact indentation run":
        what = f"lacks {', '.join(missing)}" if missing else "is not a roughcontact indentation run"
        raise MergeError(f"{path}: foreign NetCDF file ({what}); {hint}")
    if list(ds.dims) != ["force"]:
        raise MergeError(f"{path}: foreign NetCDF file (dimensions {dict(ds.sizes)}, expected only 'force'); {hint}")
    if expected is not None:
        for key in ("hurst", "radius", "h_rms", "seed"):
            got = float(ds[key])
            if not (got == float(expected[key])):
                raise MergeError(f"{path}: holds {key} = {got:g}, expected {float(expected[key]):g} from its name; {hint}")
        want = provenance.config_hash(expected)
        if ds.attrs.get("config_hash") != want:
            raise MergeError(f"{path}: was computed with other settings (config_hash {ds.attrs.get('config_hash')} "
                             f"!= {want} of the current config); {hint} or run snakemake with --rerun-triggers params")
        forces = study.force_grid(expected["forces"]) * expected["e_star"] * expected["length"] ** 2
        if ds.sizes["force"] != len(forces) or not np.allclose(ds["force"].values, forces, rtol=1e-12, atol=0):
            raise MergeError(f"{path}: its force grid differs from the current config; {hint}")
    return ds


# --------------------------------------------------------------------------
# merge and ensemble
# --------------------------------------------------------------------------
def merge_runs(cfg: dict, paths=None):
    """Merge all run files of the resolved config *cfg* into one Dataset with
    dims (hurst, radius, h_rms, seed, force).  Forces that a surface kind does
    not use (spheres and flat surfaces have different grids) are NaN."""
    import xarray as xr

    table = study.runs(cfg)
    if paths is None:
        paths = [study.run_path(r["hurst"], r["radius"], r["h_rms"], r["seed"]) for r in table]
    if len(paths) != len(table):
        raise MergeError(f"merge got {len(paths)} run files for {len(table)} runs of the config")
    L, E = cfg["grid"]["length"], cfg["e_star"]
    kinds = sorted({r["kind"] for r in table})
    force = np.unique(np.concatenate([study.force_grid(cfg["forces"][k]) * E * L**2 for k in kinds]))
    coords = {"hurst": cfg["hurst"], "radius": cfg["radius"], "h_rms": cfg["h_rms"], "seed": cfg["seeds"]}
    shape = tuple(len(v) for v in coords.values()) + (len(force),)
    data = {name: np.full(shape, np.nan) for name in study.RUN_VARIABLES}
    attrs_of = {}
    commits = set()
    for row, path in zip(table, paths):
        expected = study.job_settings(cfg, row["hurst"], row["radius"], row["h_rms"], row["seed"])
        ds = read_run(path, expected)
        idx = (cfg["hurst"].index(row["hurst"]), cfg["radius"].index(row["radius"]),
               cfg["h_rms"].index(row["h_rms"]), cfg["seeds"].index(row["seed"]))
        pos = np.searchsorted(force, ds["force"].values)
        for name in study.RUN_VARIABLES:
            data[name][idx + (pos,)] = ds[name].values.astype(float)
            attrs_of.setdefault(name, dict(ds[name].attrs))
        commits.add(ds.attrs.get("git_commit", "unknown"))
    dims = ("hurst", "radius", "h_rms", "seed", "force")
    variables = {}
    for name in study.RUN_VARIABLES:
        attrs = {k: v for k, v in attrs_of.get(name, {}).items() if k != "coordinates"}
        if name in ("contact_cells", "iterations", "converged"):
            attrs["note"] = "stored as float: NaN where this surface kind has no load at this force"
        variables[name] = (dims, data[name], attrs)
    ds = xr.Dataset(
        variables,
        coords={
            **coords,
            "force": ("force", force, {"long_name": "normal force F", "units": "e_star * length**2"}),
            "force_normalized": ("force", force / (E * L**2), {"long_name": "F/(E* L^2)", "units": "1"}),
        },
    )
    ds["hurst"].attrs.update(long_name="Hurst exponent H", units="1")
    ds["radius"].attrs.update(long_name="sphere radius R (inf: nominally flat, periodic)", units="length")
    ds["h_rms"].attrs.update(long_name="rms roughness height", units="length")
    ds["seed"].attrs.update(long_name="random seed of the surface")
    ds.attrs.update(provenance.provenance_attrs(
        config=cfg, title="roughcontact parameter study: all runs",
        grid_n=cfg["grid"]["n"], grid_length=L, e_star=E, solver_tol=cfg["solver"]["tol"],
        stiffness_method=cfg["solver"]["stiffness"], seeds=cfg["seeds"],
        run_git_commits=sorted(commits),
    ))
    return ds


def ensemble(ds):
    """Mean, standard deviation and standard error of k over seeds (and means
    of depth, contact area and contact cells)."""
    import xarray as xr

    k = ds["stiffness"]
    count = k.notnull().sum("seed")
    mean = k.mean("seed")
    std = k.std("seed", ddof=1) if ds.sizes["seed"] > 1 else xr.full_like(mean, np.nan)
    sem = std / np.sqrt(count.where(count > 0))
    out = xr.Dataset(
        {
            "k_mean": (mean.dims, mean.values, {"long_name": "ensemble mean stiffness", "units": "e_star * length"}),
            "k_std": (std.dims, std.values, {"long_name": "standard deviation of k over seeds (ddof=1)", "units": "e_star * length"}),
            "k_sem": (sem.dims, sem.values, {"long_name": "standard error of the mean k", "units": "e_star * length"}),
            "n_seeds": (count.dims, count.values.astype("int32"), {"long_name": "number of seeds"}),
            "depth_mean": (mean.dims, ds["depth"].mean("seed").values, {"units": "length"}),
            "contact_area_mean": (mean.dims, ds["contact_area"].mean("seed").values, {"units": "length**2"}),
            "contact_cells_mean": (mean.dims, ds["contact_cells"].mean("seed").values, {"units": "1"}),
        },
        coords={c: ds[c] for c in ("hurst", "radius", "h_rms", "force", "force_normalized")},
    )
    out.attrs.update({k: v for k, v in ds.attrs.items()})
    out.attrs["title"] = "roughcontact parameter study: ensemble statistics over seeds"
    return out


# --------------------------------------------------------------------------
# ζ(H)
# --------------------------------------------------------------------------
def _zeta_points(ds, cfg, hurst):
    """Per seed: arrays x = ln(F_r/(E h L)), y = ln(k/(E L)) inside the fit window,
    and the source label.  F_r is F for flat runs and F minus the Hertz force
    at the same k (eq. 16) for spheres."""
    L, E = cfg["grid"]["length"], cfg["e_star"]
    zc = cfg["fit"]["zeta"]
    flat = [r for r in cfg["radius"] if not math.isfinite(r)]
    if flat:
        radii, source = flat, "flat"
    else:
        radii = [r for r in cfg["radius"] if math.isfinite(r)]
        source = ("sphere small-force branch (no flat runs): eq. 16 minus its Hertz term; "
                  "no free exponent (the window is too narrow)")
    points = []
    for seed in cfg["seeds"]:
        xs, ys, fs = [], [], []
        for radius in radii:
            for h in cfg["h_rms"]:
                sub = ds.sel(hurst=hurst, radius=radius, h_rms=h, seed=seed)
                F = sub["force"].values
                k = sub["stiffness"].values
                cells = sub["contact_cells"].values
                ok = np.isfinite(k) & (cells >= zc["min_cells"])
                if math.isfinite(radius):
                    f_tr = theory.crossover_force(radius, hurst, h, L, E, theory.zeta_estimate(hurst))
                    ok &= F <= zc.get("sphere_max_force_ratio", 0.3) * f_tr
                    hertz = E * (k / E) ** 3 / (6 * radius)
                    Fr = F - hertz
                    ok &= Fr > 0.1 * F
                else:
                    ok &= sub["contact_area"].values / L**2 <= zc["max_area_fraction"]
                    Fr = F
                with np.errstate(invalid="ignore", divide="ignore"):
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
    slope = float(np.polyfit(x, y, 1)[0]) if x.size >= 2 and np.ptp(x) > 0 else math.nan
    return math.exp(ln_zeta), slope


def fit_zeta(ds, cfg):
    """ζ(H) from eq. 11 (exponent fixed to 1/(H+1)) and the free exponent, with
    bootstrap-over-seeds confidence intervals.  Returns (DataFrame, Dataset).

    Fit window: loads with at least ``fit.zeta.min_cells`` contact cells and,
    for flat surfaces, a contact area fraction at most
    ``fit.zeta.max_area_fraction``.  Without flat runs the sphere loads below
    ``fit.zeta.sphere_max_force_ratio`` × F_tr (eq. 17, ζ = 1.7/(H+1)) are used
    after subtracting the Hertz force at the same stiffness (eq. 16).
    """
    import pandas as pd

    zc = cfg["fit"]["zeta"]
    n_boot = int(zc.get("bootstrap", 1000))
    level = float(zc.get("confidence", 0.95))
    rows = []
    for hurst in cfg["hurst"]:
        points, source = _zeta_points(ds, cfg, hurst)
        zeta, slope = _zeta_stats(points, hurst)
        flat = source == "flat"
        rng = np.random.default_rng(20130702)  # fixed: identical numbers on every run
        boots = []
        if len(points) > 1 and math.isfinite(zeta):
            for _ in range(n_boot):
                pick = rng.integers(0, len(points), len(points))
                boots.append(_zeta_stats([points[i] for i in pick], hurst))
        boots = np.array(boots) if boots else np.full((1, 2), np.nan)
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
            "zeta_estimate": float(theory.zeta_estimate(hurst)),
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
            "window": (f"contact cells >= {zc['min_cells']}, "
                       + (f"A/L^2 <= {zc['max_area_fraction']}" if source == "flat"
                          else f"F <= {zc.get('sphere_max_force_ratio', 0.3)} F_tr(eq. 17, zeta = 1.7/(H+1))")),
        })
    df = pd.DataFrame(rows)
    zds = df.set_index("hurst").to_xarray()
    zds.attrs.update(provenance.provenance_attrs(
        config=cfg, title="zeta(H) fitted from eq. 11 (k/(E* L) = zeta (F/(E* h L))^(1/(H+1)))",
        bootstrap_resamples=n_boot, bootstrap_over="seeds", forces="F/(E* L^2)"))
    return df, zds


# --------------------------------------------------------------------------
# crossover
# --------------------------------------------------------------------------
def _loglog_slope(F, k, half: int = 1):
    """Local slope d ln k / d ln F: the slope of a least-squares line through
    the 2*half+1 neighbouring loads (``fit.slopes.window``; NaN near the ends).
    half = 1 is the central difference; a wider window trades range for less
    seed noise."""
    x, y = np.log(F), np.log(k)
    s = np.full_like(x, np.nan)
    for i in range(half, x.size - half):
        xs, ys = x[i - half:i + half + 1], y[i - half:i + half + 1]
        xm = xs - xs.mean()
        s[i] = float(np.dot(xm, ys - ys.mean()) / np.dot(xm, xm))
    return s


def _fit_slope(F, k, mask):
    if mask.sum() < 2:
        return math.nan
    return float(np.polyfit(np.log(F[mask]), np.log(k[mask]), 1)[0])


def crossover(ens, zeta_df, cfg):
    """Predicted (eq. 17) and measured crossover per (H, R, h_rms), R finite.

    The measured force is where the local slope d ln k/d ln F of the ensemble
    mean (:func:`_loglog_slope`, resolved loads preferred) crosses 2/(H+4); on the eq. 16 curve that happens at F = 2 F_tr, so
    ``Ftr_measured`` is half that force (``F_slope`` is kept as read off).
    """
    import pandas as pd

    L, E = cfg["grid"]["length"], cfg["e_star"]
    min_cells = cfg["fit"]["zeta"]["min_cells"]
    low, high = cfg["fit"]["slopes"]["low_max_ratio"], cfg["fit"]["slopes"]["high_min_ratio"]
    zeta_of = dict(zip(zeta_df["hurst"], zeta_df["zeta"]))
    rows = []
    for hurst, radius, h in study.combinations(cfg):
        if not math.isfinite(radius):
            continue
        notes = []
        z_est = float(theory.zeta_estimate(hurst))
        z_fit = float(zeta_of.get(hurst, math.nan))
        if not math.isfinite(z_fit):
            notes.append("no fitted zeta: 1.7/(H+1) used")
            z_fit_used = z_est
        else:
            z_fit_used = z_fit
        f_fit = theory.crossover_force(radius, hurst, h, L, E, z_fit_used) / (E * L**2)
        f_est = theory.crossover_force(radius, hurst, h, L, E, z_est) / (E * L**2)
        sub = ens.sel(hurst=hurst, radius=radius, h_rms=h)
        keep = np.isfinite(sub["k_mean"].values)
        F = sub["force"].values[keep] / (E * L**2)
        k = sub["k_mean"].values[keep] / (E * L)
        cells = sub["contact_cells_mean"].values[keep]
        target = 2.0 / (hurst + 4.0)
        s = _loglog_slope(F, k, half=(int(cfg["fit"]["slopes"].get("window", 3)) - 1) // 2)
        d = s - target
        idx = [i for i in range(len(F) - 1) if np.isfinite(d[i]) and np.isfinite(d[i + 1])
               and d[i] > 0 >= d[i + 1]]
        resolved = cells >= min_cells
        idx_resolved = [i for i in idx if resolved[i]]
        idx = idx_resolved or idx
        if idx:
            # several downward crossings (noise): take the one nearest the prediction 2 F_tr
            i = min(idx, key=lambda j: abs(np.log(F[j]) - np.log(2 * f_fit)))
            t = d[i] / (d[i] - d[i + 1])
            f_slope = float(np.exp(np.log(F[i]) + t * (np.log(F[i + 1]) - np.log(F[i]))))
            if len(idx) > 1:
                notes.append(f"{len(idx)} slope crossings, the one nearest 2 F_tr taken")
        else:
            f_slope = math.nan
            notes.append("local slope never crosses 2/(H+4) inside the load range")
        lo_mask = (F <= low * f_fit) & resolved
        hi_mask = F >= high * f_fit
        if lo_mask.sum() < 2:
            notes.append(f"fewer than 2 loads below {low} F_tr with >= {min_cells} cells")
        if hi_mask.sum() < 2:
            notes.append(f"fewer than 2 loads above {high} F_tr")
        k16 = theory.stiffness_from_force(F[resolved] * E * L**2, radius, hurst, h, L, E, z_fit_used) / (E * L)
        dev = np.abs(np.log10(k[resolved] / k16)) if resolved.any() else np.array([np.nan])
        f_meas = f_slope / 2
        rows.append({
            "hurst": hurst, "radius": radius, "h_rms": h,
            "zeta_fit": z_fit, "zeta_estimate": z_est,
            "Ftr_pred_fit": f_fit, "Ftr_pred_estimate": f_est,
            "slope_target": target, "F_slope": f_slope, "Ftr_measured": f_meas,
            "ratio_fit": f_meas / f_fit, "ratio_estimate": f_meas / f_est,
            "slope_low": _fit_slope(F, k, lo_mask), "slope_low_theory": 1 / (hurst + 1),
            "slope_high": _fit_slope(F, k, hi_mask), "slope_high_theory": 1 / 3,
            "max_abs_log10_k_over_eq16": float(np.max(dev)),
            "rms_log10_k_over_eq16": float(np.sqrt(np.mean(dev**2))),
            "n_loads": int(len(F)), "n_loads_resolved": int(resolved.sum()),
            "note": "; ".join(notes),
        })
    columns = ["hurst", "radius", "h_rms", "zeta_fit", "zeta_estimate", "Ftr_pred_fit", "Ftr_pred_estimate",
               "slope_target", "F_slope", "Ftr_measured", "ratio_fit", "ratio_estimate", "slope_low",
               "slope_low_theory", "slope_high", "slope_high_theory", "max_abs_log10_k_over_eq16",
               "rms_log10_k_over_eq16", "n_loads", "n_loads_resolved", "note"]
    return pd.DataFrame(rows, columns=columns)


# --------------------------------------------------------------------------
# entry points used by workflow/scripts
# --------------------------------------------------------------------------
def run_merge(cfg, run_files, out_stiffness, out_ensemble, log=None):
    ds = merge_runs(cfg, list(run_files))
    write_netcdf(ds, out_stiffness)
    write_netcdf(ensemble(ds), out_ensemble)
    _log(log, f"merged {len(run_files)} runs into {out_stiffness} and {out_ensemble}")


def run_fit_zeta(cfg, stiffness_nc, out_csv, out_nc, log=None):
    import xarray as xr

    with xr.open_dataset(stiffness_nc, engine="netcdf4") as ds:
        df, zds = fit_zeta(ds.load(), cfg)
    write_csv(df, out_csv)
    write_netcdf(zds, out_nc)
    _log(log, df.to_string())


def run_crossover(cfg, ensemble_nc, zeta_csv, out_csv, log=None):
    import pandas as pd
    import xarray as xr

    with xr.open_dataset(ensemble_nc, engine="netcdf4") as ens:
        df = crossover(ens.load(), pd.read_csv(zeta_csv), cfg)
    write_csv(df, out_csv)
    _log(log, df.to_string())


def _log(log, text):
    if log:
        Path(log).parent.mkdir(parents=True, exist_ok=True)
        with open(log, "a") as fh:
            fh.write(text + "\n")
