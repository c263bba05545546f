"""The model scorecard: contact theories against the BEM ensemble of every sphere combination.

Each model of :data:`MODELS` predicts the stiffness ``k(F)`` of a rough sphere from what the
configuration says about the surface (H, h_rms, R, the body exponent m, L, n) and, for
``eq16_fitted``, the ζ(H) fitted on the same study. It is scored on the resolved loads of the
ensemble mean (mean contact cells ≥ ``fit.zeta.min_cells``, as for the verdicts) by

* ``max_rel_dev = max_F |k_model/k_BEM − 1|`` with a 95 % bootstrap-over-seeds interval (the
  ensemble mean recomputed on every resample; the model is deterministic), and
* ``rms_rel_dev``, the root-mean-square of the same deviations.

A model that does not apply to a combination (Greenwood–Tripp off the paraboloid or with a
roll-off or cutoff) has no row for it. Forces are ``F/(E* L²)``, stiffnesses ``k/(E* L)``.
"""
from __future__ import annotations

import itertools
import logging
import math

import numpy as np

from ..models import mdr as mdr_model
from ..models import paper
from ..models import persson as persson_model
from ..models import superposition
from ..models.zeta_law import zeta_law
from ..surfaces.spectra import self_affine_spectrum
from ..models.greenwood_tripp import self_affine_sphere_curve
from . import provenance, runs
from .plotting import pyplot, save_png
from .statistics import bootstrap_indices, interval
from .tables import write_html_table

__all__ = ["MODELS", "Combination", "scorecard", "run_models"]

log = logging.getLogger(__name__)

#: central separations d* (units of GT's σ) of the Greenwood–Tripp curve: F from ~1e-7 to ~20 E*L²
#: on the paper's sphere
_GT_DEPTHS = np.linspace(3.5, -1.5, 11)


class Combination(dict):
    """One sphere combination of the sweep: the axes as merged-file coordinates, plus ``n``,
    ``length``, ``e_star`` and ``zeta_fit`` (the study's fitted ζ(H), NaN if none)."""

    @property
    def paper_setting(self) -> bool:
        """No roll-off, no cutoff and elastic (the axes eqs. 11–17 are written for)."""
        return (self["rolloff"] == self["length"] and self["cutoff"] == 0.0
                and math.isinf(self["hardness"]))


def _eq16(force, c: Combination, zeta: float):
    if not math.isfinite(zeta):
        return None
    return paper.stiffness_from_force(force, radius=c["radius"], hurst=c["hurst"], h_rms=c["h_rms"],
                                      length=c["length"], e_star=c["e_star"], zeta=zeta, exponent=c["exponent"])


def eq16_paper(force, c: Combination):
    """Eq. 16 with ζ = 1.7/(H+1) (eq. 13)."""
    return _eq16(force, c, float(paper.zeta_estimate(c["hurst"])))


def eq16_fitted(force, c: Combination):
    """Eq. 16 with the ζ(H) fitted on this study (eq. 11; flat runs, else the sphere's branch)."""
    return _eq16(force, c, c["zeta_fit"])


def eq16_law(force, c: Combination):
    """Eq. 16 with ζ from the ζ(H) law calibrated on the flat surfaces of ``presets/zeta-law.yaml``
    (:func:`roughcontact.models.zeta_law.zeta_law`, claim c')."""
    return _eq16(force, c, float(zeta_law(c["hurst"])))


def contact_scale(force, c: Combination):
    """This package's model (:mod:`roughcontact.models.superposition`): eqs. 10 and 12 joined by
    a p-norm, ζ = c_ζ · ζ_law(H), and for a spectrum with a roll-off or a cutoff the roughness
    seen at the contact's scale (the grid's spectrum against the pure self-affine one); c_ζ and
    p calibrated on the presets named in :data:`roughcontact.models.superposition.CALIBRATED`."""
    spectra = {}
    if c["rolloff"] != c["length"] or c["cutoff"] != 0.0:
        spectra = dict(spectrum=_grid_spectrum(c), reference=_grid_spectrum(c, band=False))
    return superposition.calibrated_stiffness(
        force, radius=c["radius"], hurst=c["hurst"], h_rms=c["h_rms"], length=c["length"], e_star=c["e_star"],
        exponent=c["exponent"], **spectra)


def greenwood_tripp(force, c: Combination):
    """Greenwood & Tripp (1967) on the summit statistics of the grid's own self-affine spectrum,
    interpolated in log k against log F; NaN outside the solved range. Paraboloid, no roll-off
    or cutoff only (the moments are those of the pure self-affine spectrum)."""
    if c["exponent"] != 2.0 or c["rolloff"] != c["length"] or c["cutoff"] != 0.0:
        return None
    curve = self_affine_sphere_curve(hurst=c["hurst"], h_rms=c["h_rms"], n=c["n"], length=c["length"],
                                     radius=c["radius"], e_star=c["e_star"], depths_star=_GT_DEPTHS)
    ok = np.isfinite(curve.force) & np.isfinite(curve.stiffness) & (curve.force > 0)
    f, k = curve.force[ok], curve.stiffness[ok]
    order = np.argsort(f)
    log_k = np.interp(np.log(force), np.log(f[order]), np.log(k[order]), left=np.nan, right=np.nan)
    return np.exp(log_k)


#: realisations of the MDR ensemble (relative standard error of k ≈ 0.2–1 % on the paper's sphere)
MDR_REALIZATIONS = 1000


def mdr(force, c: Combination):
    """The method of dimensionality reduction: the mean stiffness of :data:`MDR_REALIZATIONS`
    seeded 1D profiles with ``C1D = π q C2D`` of the grid's spectrum on a Winkler foundation,
    the sphere as ``x²/R`` (:func:`roughcontact.models.mdr.sphere_stiffness`). Paraboloid only."""
    if c["exponent"] != 2.0:
        return None
    return mdr_model.sphere_stiffness(
        force, radius=c["radius"], hurst=c["hurst"], h_rms=c["h_rms"], length=c["length"], n=c["n"],
        e_star=c["e_star"], rolloff=runs.axis_value("rolloff", c["rolloff"], c["length"]),
        cutoff=runs.axis_value("cutoff", c["cutoff"], c["length"]), realizations=MDR_REALIZATIONS, seed=0).stiffness


#: logarithmic bins per decade of the grid's spectrum for Persson's model (the grid's shells merged
#: above the lowest modes: 130-220 bins for 129²-1025², stiffness within 2e-7 of all shells)
PERSSON_BINS_PER_DECADE = 100


def _grid_spectrum(c: Combination, *, band: bool = True):
    """The grid's own self-affine spectrum of combination *c*, with its roll-off and cutoff
    (``band=False``: without, the pure self-affine reference), on
    :data:`PERSSON_BINS_PER_DECADE` bins per decade."""
    extra = {axis: runs.axis_value(axis, c[axis], c["length"]) for axis in ("rolloff", "cutoff")} if band else {}
    return self_affine_spectrum(hurst=c["hurst"], h_rms=c["h_rms"], length=c["length"], n=c["n"],
                                **extra).rebinned(PERSSON_BINS_PER_DECADE)


def persson(force, c: Combination):
    """Persson's interfacial law ū(p) from the grid's own discrete spectrum, acting over the
    nominal pressure of the paraboloid (an axisymmetric compliant layer in series with the
    half-space; :func:`roughcontact.models.persson.sphere_stiffness`, ``method="axisymmetric"``,
    γ = 0.42). Paraboloid only."""
    if c["exponent"] != 2.0:
        return None
    return persson_model.sphere_stiffness(force, _grid_spectrum(c), radius=c["radius"], e_star=c["e_star"]).stiffness


#: model name -> function ``(force, combination) -> stiffness`` (``None``: does not apply)
MODELS = {"eq16_paper": eq16_paper, "eq16_fitted": eq16_fitted, "eq16_law": eq16_law, "contact_scale": contact_scale,
          "greenwood_tripp": greenwood_tripp, "mdr": mdr, "persson": persson}


def _combinations(ds, cfg: dict, zeta_of: dict):
    axes = [d for d in ds["stiffness"].dims if d not in ("seed", "force")]
    for position in itertools.product(*(range(ds.sizes[a]) for a in axes)):
        combo = Combination({a: float(ds[a].values[i]) for a, i in zip(axes, position)})
        combo.update(n=cfg["grid"]["n"], length=cfg["grid"]["length"], e_star=cfg["e_star"],
                     zeta_fit=float(zeta_of.get(combo["hurst"], math.nan)))
        yield combo, ds.isel(dict(zip(axes, position))).transpose("seed", "force")


def combo_label(c: Combination) -> str:
    """The run name of a combination (``H0.7_R0.5_h0.009`` and the tags of the optional axes)."""
    run = {axis: c[axis] for axis in ("hurst", "radius", "h_rms", "exponent")}
    run.update({axis: runs.axis_value(axis, c[axis], c["length"]) for axis in ("rolloff", "cutoff", "hardness")})
    return runs.combo_name(run)


def scorecard(groups: dict, zeta_df, cfg: dict):
    """``models.csv`` as a DataFrame (one row per model and sphere combination), and a Dataset of
    the relative deviations ``k_model/k_BEM − 1`` per load with the ensemble's 95 % band."""
    import pandas as pd
    import xarray as xr

    if "sphere" not in groups:
        return pd.DataFrame(), {}
    ds = groups["sphere"]
    L, E = cfg["grid"]["length"], cfg["e_star"]
    min_cells = cfg["fit"]["zeta"]["min_cells"]
    level = float(cfg["fit"]["zeta"]["confidence"])
    indices = bootstrap_indices(ds.sizes["seed"], int(cfg["fit"]["zeta"]["bootstrap"]))
    zeta_of = dict(zip(zeta_df["hurst"], zeta_df["zeta"])) if len(zeta_df) else {}
    force_norm = ds["force"].values / (E * L**2)
    rows, curves = [], {}
    for combo, sub in _combinations(ds, cfg, zeta_of):
        k = sub["stiffness"].values
        k_mean = k.mean(0)
        k_boot = k[indices].mean(1)                               # (resample, force)
        resolved = sub["contact_cells"].values.mean(0) >= min_cells
        band = np.percentile(k_boot / k_mean - 1, [50 * (1 - level), 50 * (1 + level)], axis=0)
        label = combo_label(combo)
        dev_of = {}
        for name, model in MODELS.items():
            k_model = model(sub["force"].values, combo)
            if k_model is None:
                continue
            use = resolved & np.isfinite(k_model)
            dev = k_model / k_mean - 1
            dev_of[name] = dev
            if not use.any():
                continue
            low, high = interval(np.abs(k_model[use] / k_boot[:, use] - 1).max(-1), level)
            rows.append({
                "model": name, **{a: combo[a] for a in runs.AXES["sphere"]}, "combination": label,
                "max_rel_dev": float(np.abs(dev[use]).max()), "max_rel_dev_ci_low": low,
                "max_rel_dev_ci_high": high, "rms_rel_dev": float(np.sqrt(np.mean(dev[use] ** 2))),
                "n_loads": int(use.sum()), "force_min": float(force_norm[use].min()),
                "force_max": float(force_norm[use].max()), "paper_setting": combo.paper_setting,
            })
        curves[label] = xr.Dataset(
            {**{name: ("force", dev, {"long_name": f"k_{name}/k_BEM - 1", "units": "1"})
                for name, dev in dev_of.items()},
             "band_low": ("force", band[0], {"long_name": f"{level:.0%} band of the ensemble mean, low", "units": "1"}),
             "band_high": ("force", band[1], {"long_name": f"{level:.0%} band of the ensemble mean, high", "units": "1"}),
             "resolved": ("force", resolved.astype("i1"), {"long_name": "resolved load (1) or not (0)", "units": "1"})},
            coords={"force_normalized": ("force", force_norm, {"long_name": "F/(E* L^2)", "units": "1"})},
            attrs={k: v for k, v in combo.items()})
    table = pd.DataFrame(rows)
    if len(table):
        table["rank"] = table.groupby("combination")["max_rel_dev"].rank(method="min").astype(int)
    return table, curves


#: the lead paragraph of the scorecard page of the report
SCORECARD_LEAD = ("Each model predicts the rough sphere's stiffness k(F) from the surface's parameters; "
                  "max_rel_dev is the largest |k_model/k_BEM - 1| over the resolved loads of the ensemble "
                  "mean, with its 95 % bootstrap-over-seeds interval, rms_rel_dev the rms of the same "
                  "deviations; rank 1 is the best model of its combination. eq16_paper: eq. 16 with "
                  "zeta = 1.7/(H+1); eq16_fitted: with the zeta fitted on this study; eq16_law: with the "
                  "zeta(H) law calibrated on presets/zeta-law.yaml; contact_scale: this package's model, eqs. 10 and 12 "
                  "joined by a p-norm with the roughness seen at the contact's scale, constants calibrated on "
                  "named presets; "
                  "greenwood_tripp: "
                  "Greenwood & Tripp (1967) on the grid's spectral moments; mdr: the method of dimensionality "
                  "reduction, 1000 seeded 1D profiles on a Winkler foundation; persson: Persson's interfacial "
                  "law from the grid's spectrum as a compliant layer under the paraboloid. models.csv holds "
                  "every digit.")


def _figure(path, label: str, curve, table) -> None:
    plt = pyplot()
    force = curve["force_normalized"].values
    resolved = curve["resolved"].values.astype(bool)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.fill_between(force, curve["band_low"], curve["band_high"], color="0.85", label="BEM ensemble, 95 % band")
    ax.axhline(0, color="0.4", lw=0.8)
    for name in MODELS:
        if name in curve:
            mark = table[(table["combination"] == label) & (table["model"] == name)]
            text = f" (max {float(mark['max_rel_dev'].iloc[0]):.1%})" if len(mark) else ""
            ax.semilogx(force[resolved], curve[name].values[resolved], "o-", ms=3, label=name + text)
    ax.set(xlabel="F / (E* L²)", ylabel="k_model / k_BEM − 1", title=label)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_png(fig, path)


def run_models(cfg, stiffness_nc, zeta_csv, out_csv, out_nc, out_html, figures):
    """``models`` rule: the scorecard table (CSV, HTML), the per-load deviations (NetCDF, one group
    per combination) and one figure per sphere combination (*figures*, in the order of
    :func:`roughcontact.study.runs.sphere_names`)."""
    import pandas as pd

    from .merge import read_groups, write_csv, write_groups

    table, curves = scorecard(read_groups(stiffness_nc), pd.read_csv(zeta_csv), cfg)
    attrs = provenance.provenance_attrs(config=cfg, title="model scorecard: k_model/k_BEM - 1 per load",
                                        bootstrap_over="seeds", forces="F/(E* L^2)")
    write_csv(table, out_csv)
    write_groups(out_nc, curves, attrs)
    write_html_table(table, out_html, title="Model scorecard", lead=SCORECARD_LEAD, verdict_columns=(),
                     first=("combination", "model", "rank", "max_rel_dev", "max_rel_dev_ci_low",
                            "max_rel_dev_ci_high", "rms_rel_dev", "n_loads"))
    names = runs.sphere_names(cfg)
    if len(names) != len(figures):
        raise ValueError(f"run_models got {len(figures)} figure paths for {len(names)} sphere combinations")
    for label, path in zip(names, figures):
        if label not in curves:
            raise ValueError(f"no sphere combination {label} in {stiffness_nc} for the figure {path}")
        _figure(path, label, curves[label], table)
    log.info("scorecard:\n%s", table.to_string() if len(table) else "(no sphere runs)")
