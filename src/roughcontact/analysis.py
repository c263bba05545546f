"""Merge, ensemble statistics and the ζ(H) fit (the verdicts are in :mod:`.verdicts`).

Imports xarray and pandas (the ``pipeline`` extra); ``import roughcontact``
does not import this module.

All forces in the tables are normalised, F/(E* L²); stiffnesses k/(E* L).
"""
from __future__ import annotations

import logging
import math
import os

import numpy as np

from . import provenance, study, theory

__all__ = ["MergeError", "read_run", "merge_runs", "ensemble", "fit_zeta", "write_groups", "read_groups",
           "write_netcdf", "write_csv", "run_merge", "run_fit_zeta"]


log = logging.getLogger(__name__)


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
        df.to_csv(tmp, index=False)  # shortest round-trip repr: values read back are the values written


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
# merge and ensemble: one group per surface kind
# --------------------------------------------------------------------------
#: NetCDF types of the run variables in the merged file (counts stay integers)
_DTYPES = {"depth": "f8", "stiffness": "f8", "contact_area": "f8", "contact_cells": "i8",
           "iterations": "i8", "converged": "i1", "loading_stiffness": "f8", "plastic_cells": "i8"}
_AXIS_ATTRS = {
    "hurst": {"long_name": "Hurst exponent H", "units": "1"},
    "radius": {"long_name": "sphere radius R", "units": "length"},
    "exponent": {"long_name": "exponent m of the body of revolution z = (R/m)(r/R)^m (2: paraboloid)", "units": "1"},
    "h_rms": {"long_name": "rms roughness height", "units": "length"},
    "rolloff": {"long_name": "roll-off wavelength of the spectrum (grid.length: none)", "units": "length"},
    "cutoff": {"long_name": "short-wavelength cutoff of the spectrum (0: none)", "units": "length"},
    "hardness": {"long_name": "penetration hardness (inf: elastic)", "units": "e_star"},
    "seed": {"long_name": "random seed of the surface", "units": "1"},
}


def _force_coords(cfg: dict, kind: str) -> dict:
    L, E = cfg["grid"]["length"], cfg["e_star"]
    force = study.force_grid(cfg["forces"][kind]) * E * L**2
    return {
        "force": ("force", force, {"long_name": "normal force F", "units": "e_star * length**2"}),
        "force_normalized": ("force", force / (E * L**2), {"long_name": "F/(E* L^2)", "units": "1"}),
    }


def merge_runs(cfg: dict, paths=None) -> dict:
    """Merge all run files of the resolved config *cfg*, one Dataset per surface kind.

    Returns ``{"sphere": ds, "flat": ds}`` (the kinds the sweep has): the sphere
    Dataset has dims (hurst, radius, h_rms, seed, force), the flat one (hurst,
    h_rms, seed, force) (:data:`study.AXES`); each kind has its own force grid,
    so no variable is padded, and counts are integers.
    """
    import xarray as xr

    table = study.runs(cfg)
    if paths is None:
        paths = [study.run_path(r) for r in table]
    if len(paths) != len(table):
        raise MergeError(f"merge got {len(paths)} run files for {len(table)} runs of the config")
    groups = {}
    for kind in ("sphere", "flat"):
        rows = [(row, path) for row, path in zip(table, paths) if row["kind"] == kind]
        if not rows:
            continue
        axes = study.AXES[kind]
        L = cfg["grid"]["length"]
        at = {id(row): {axis: study.coordinate(axis, row[axis], L) for axis in axes} for row, _ in rows}
        coords = {axis: sorted({at[id(row)][axis] for row, _ in rows}) for axis in axes}
        coords["seed"] = list(cfg["seeds"])
        count = cfg["forces"][kind]["count"]
        shape = tuple(len(v) for v in coords.values()) + (count,)
        plastic = any(row["hardness"] is not None for row, _ in rows)
        names = study.RUN_VARIABLES + (study.PLASTIC_VARIABLES if plastic else ())
        data = {name: np.zeros(shape, dtype=_DTYPES[name]) for name in names}
        attrs_of, commits = {}, set()
        for row, path in rows:
            ds = read_run(path, study.job_settings(cfg, row))
            idx = tuple(coords[axis].index(at[id(row)][axis]) for axis in axes) + (coords["seed"].index(row["seed"]),)
            for name in names:
                # an elastic run's loading tangent is its stiffness, and nothing flows
                values = ds[name] if name in ds else (ds["stiffness"] if name == "loading_stiffness" else 0)
                data[name][idx] = getattr(values, "values", values)
                if name in ds:
                    attrs_of.setdefault(name, {k: v for k, v in ds[name].attrs.items() if k != "coordinates"})
            commits.add(ds.attrs.get("git_commit", "unknown"))
        dims = (*axes, "seed", "force")
        ds = xr.Dataset(
            {name: (dims, data[name], attrs_of.get(name, {})) for name in names},
            coords={**{axis: (axis, coords[axis], _AXIS_ATTRS[axis]) for axis in (*axes, "seed")},
                    **_force_coords(cfg, kind)},
            attrs={"surface_kind": kind, "half_space": "periodic" if kind == "flat" else "free (non-periodic)",
                   "run_git_commits": provenance.canonical_json(sorted(commits))},
        )
        groups[kind] = ds
    return groups


def ensemble(ds):
    """Mean, standard deviation and standard error of k over seeds (and means
    of depth, contact area and contact cells) of one kind's Dataset."""
    k = ds["stiffness"]
    n_seeds = ds.sizes["seed"]
    std = k.std("seed", ddof=1) if n_seeds > 1 else k.isel(seed=0) * np.nan
    per_load = {
        "k_mean": (k.mean("seed"), {"long_name": "ensemble mean stiffness", "units": "e_star * length"}),
        "k_std": (std, {"long_name": "standard deviation of k over seeds (ddof=1)", "units": "e_star * length"}),
        "k_sem": (std / math.sqrt(n_seeds), {"long_name": "standard error of the mean k", "units": "e_star * length"}),
        "depth_mean": (ds["depth"].mean("seed"), {"long_name": "mean indentation depth", "units": "length"}),
        "contact_area_mean": (ds["contact_area"].mean("seed"), {"long_name": "mean contact area", "units": "length**2"}),
        "contact_cells_mean": (ds["contact_cells"].mean("seed"), {"long_name": "mean contact cells", "units": "1"}),
    }
    if "loading_stiffness" in ds:
        per_load["loading_k_mean"] = (ds["loading_stiffness"].mean("seed"), {
            "long_name": "ensemble mean loading tangent along the plastic path", "units": "e_star * length"})
        per_load["plastic_cells_mean"] = (ds["plastic_cells"].mean("seed"), {"long_name": "mean plastic cells",
                                                                                "units": "1"})
    import xarray as xr

    return xr.Dataset({name: value.assign_attrs(attrs) for name, (value, attrs) in per_load.items()},
                      attrs={**ds.attrs, "n_seeds": n_seeds})


def write_groups(path, groups: dict, attrs: dict) -> None:
    """Write ``{kind: Dataset}`` as the groups of one NetCDF4 file (atomic);
    *attrs* become the root group's attributes (provenance)."""
    import xarray as xr

    tree = xr.DataTree.from_dict({"/": xr.Dataset(attrs=attrs), **groups})
    with provenance.atomic_path(path) as tmp:
        tree.to_netcdf(tmp, engine="netcdf4")


def read_groups(path) -> dict:
    """``{kind: Dataset}`` of a file written by :func:`write_groups`, loaded in memory."""
    import xarray as xr

    with xr.open_datatree(path, engine="netcdf4") as tree:
        return {name: node.to_dataset().load() for name, node in tree.children.items()}


# --------------------------------------------------------------------------
# ζ(H)
# --------------------------------------------------------------------------
def paper_setting(ds, length: float):
    """*ds* at the paper's setting of the optional axes (paraboloid, no roll-off,
    no cutoff, elastic: :data:`study.DEFAULTS`), those dimensions dropped; where the
    sweep lacks the paper's value, its first value is taken. Returns the selection
    and a note naming such substitutions ("" if none)."""
    pick, notes = {}, []
    for axis, default in study.DEFAULTS.items():
        if axis not in ds.dims:
            continue
        value = study.coordinate(axis, default, length)
        if value not in ds[axis].values:
            value = float(ds[axis].values[0])
            notes.append(f"{axis} = {value:g}")
        pick[axis] = value
    return ds.sel(pick), ("with " + ", ".join(notes)) if notes else ""


def _zeta_points(groups, cfg, hurst):
    """Per seed: arrays x = ln(F_r/(E h L)), y = ln(k/(E L)) inside the fit window,
    and the source label.  F_r is F for flat runs and F minus the Hertz force
    at the same k (eq. 16) for spheres."""
    L, E = cfg["grid"]["length"], cfg["e_star"]
    zc = cfg["fit"]["zeta"]
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
    for seed in cfg["seeds"]:
        xs, ys, fs = [], [], []
        for radius in radii:
            for h in ds["h_rms"].values.tolist():
                sub = ds.sel(hurst=hurst, h_rms=h, seed=seed)
                if math.isfinite(radius):
                    sub = sub.sel(radius=radius)
                F = sub["force"].values
                k = sub["stiffness"].values
                ok = sub["contact_cells"].values >= zc["min_cells"]
                if math.isfinite(radius):
                    m = float(sub["exponent"]) if "exponent" in sub.coords else 2.0
                    f_tr = theory.crossover_force(radius, hurst, h, L, E, theory.zeta_estimate(hurst), exponent=m)
                    ok &= F <= zc.get("sphere_max_force_ratio", 0.3) * f_tr
                    # eq. 16: the roughness carries F minus the smooth body's force at the same k = 2 E* a
                    Fr = F - theory.body_indentation(k / (2 * E), radius, E, exponent=m).force
                    ok &= Fr > 0.1 * F
                else:
                    ok &= sub["contact_area"].values / L**2 <= zc["max_area_fraction"]
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
    slope = float(np.polyfit(x, y, 1)[0]) if x.size >= 2 and np.ptp(x) > 0 else math.nan
    return math.exp(ln_zeta), slope


def fit_zeta(groups, cfg):
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
        points, source = _zeta_points(groups, cfg, hurst)
        zeta, slope = _zeta_stats(points, hurst)
        flat = source.startswith("flat")
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
                       + (f"A/L^2 <= {zc['max_area_fraction']}" if flat
                          else f"F <= {zc.get('sphere_max_force_ratio', 0.3)} F_tr(eq. 17, zeta = 1.7/(H+1))")),
        })
    df = pd.DataFrame(rows)
    zds = df.set_index("hurst").to_xarray()
    zds.attrs.update(provenance.provenance_attrs(
        config=cfg, title="zeta(H) fitted from eq. 11 (k/(E* L) = zeta (F/(E* h L))^(1/(H+1)))",
        bootstrap_resamples=n_boot, bootstrap_over="seeds", forces="F/(E* L^2)"))
    return df, zds


# --------------------------------------------------------------------------
# entry points used by workflow/scripts
# --------------------------------------------------------------------------
def run_merge(cfg, run_files, out_stiffness, out_ensemble):
    """``merge`` rule: run files -> stiffness.nc and ensemble.nc (one group per kind)."""
    groups = merge_runs(cfg, list(run_files))
    attrs = provenance.provenance_attrs(
        config=cfg, title="roughcontact parameter study: all runs", layout="one group per surface kind (sphere, flat)",
        grid_n=cfg["grid"]["n"], grid_length=cfg["grid"]["length"], e_star=cfg["e_star"],
        solver_tol=cfg["solver"]["tol"], stiffness_method=cfg["solver"]["stiffness"], seeds=cfg["seeds"])
    write_groups(out_stiffness, groups, attrs)
    attrs["title"] = "roughcontact parameter study: ensemble statistics over seeds"
    write_groups(out_ensemble, {kind: ensemble(ds) for kind, ds in groups.items()}, attrs)
    log.info("merged %d runs (%s) into %s and %s", len(run_files), ", ".join(groups), out_stiffness, out_ensemble)


def run_fit_zeta(cfg, stiffness_nc, out_csv, out_nc):
    """``fit_zeta`` rule: stiffness.nc -> zeta.csv and zeta.nc (eq. 11)."""
    df, zds = fit_zeta(read_groups(stiffness_nc), cfg)
    write_csv(df, out_csv)
    write_netcdf(zds, out_nc)
    log.info("zeta(H):\n%s", df.to_string())
