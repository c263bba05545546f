"""The model scorecard: contact theories against the BEM ensemble of every sphere combination.

Each model of the registry (:mod:`roughcontact.models.scorecard`) predicts the stiffness ``k(F)`` of a rough sphere from what the
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

from ..models import paper
from ..models import scorecard as registry
from . import provenance, runs
from .ensemble import resolved
from .plotting import pyplot, save_png
from .statistics import bootstrap_indices, interval, verdict
from .tables import write_html_table

__all__ = ["Combination", "scorecard", "run_models", "combo_label"]

log = logging.getLogger(__name__)


class Combination(dict):
    """One sphere combination of the sweep: the axes as merged-file coordinates, plus ``n``,
    ``length``, ``e_star`` and ``zeta_fit`` (the study's fitted ζ(H), NaN if none)."""

    @property
    def paper_setting(self) -> bool:
        """No roll-off, no cutoff and elastic (the axes eqs. 11–17 are written for)."""
        return (self["rolloff"] == self["length"] and self["cutoff"] == 0.0
                and math.isinf(self["hardness"]))

    def surface(self) -> registry.Surface:
        """What the models read (:class:`roughcontact.models.scorecard.Surface`)."""
        length = self["length"]
        return registry.Surface(
            hurst=self["hurst"], h_rms=self["h_rms"], radius=self["radius"], length=length, n=int(self["n"]),
            e_star=self["e_star"], exponent=self["exponent"], zeta_fit=self["zeta_fit"],
            rolloff=runs.axis_value("rolloff", self["rolloff"], length),
            cutoff=runs.axis_value("cutoff", self["cutoff"], length))


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


def _crossover(c: Combination) -> float:
    """The branches' border ``F/(E* L²)``: eq. 17 with the study's fitted ζ, else eq. 13's."""
    zeta = c["zeta_fit"] if math.isfinite(c["zeta_fit"]) else float(paper.zeta_estimate(c["hurst"]))
    return float(paper.crossover_force(c["radius"], hurst=c["hurst"], h_rms=c["h_rms"], length=c["length"],
                                       e_star=c["e_star"], zeta=zeta, exponent=c["exponent"])
                 / (c["e_star"] * c["length"] ** 2))


def _systematic(k_model, k_mean, k_boot, use, branch: str, level: float) -> dict:
    """The systematic deviation of a model on one branch: the mean of ``k_model/k_BEM − 1`` over the
    loads *use*, each weighted by the inverse variance of the ensemble mean there (its bootstrap),
    with the interval of the same mean over the bootstrap's ensembles and the verdict on 0
    (``differs``: the deviation is significant)."""
    keys = [f"systematic_{branch}", f"systematic_{branch}_ci_low", f"systematic_{branch}_ci_high"]
    if use.sum() < 1:
        return {**dict.fromkeys(keys, math.nan), f"systematic_{branch}_verdict": "untested: no resolved load",
                f"n_loads_{branch}": 0}
    relative = k_boot[:, use] / k_mean[use]
    weight = 1.0 / np.maximum(relative.var(axis=0, ddof=1), np.finfo(float).eps ** 2)   # no scatter: equal weights
    value = float(np.sum(weight * (k_model[use] / k_mean[use] - 1)) / weight.sum())
    low, high = interval((k_model[use] / k_boot[:, use] - 1) @ weight / weight.sum(), level)
    return {keys[0]: value, keys[1]: low, keys[2]: high, f"systematic_{branch}_verdict": verdict(0.0, low, high),
            f"n_loads_{branch}": int(use.sum())}


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
        use_load = resolved(sub["contact_cells"].values.mean(0), min_cells)
        band = np.percentile(k_boot / k_mean - 1, [50 * (1 - level), 50 * (1 + level)], axis=0)
        label = combo_label(combo)
        f_tr = _crossover(combo)
        dev_of = {}
        for name, k_model in registry.predict(sub["force"].values, combo.surface()).items():
            use = use_load & np.isfinite(k_model)
            dev = k_model / k_mean - 1
            dev_of[name] = dev
            if not use.any():
                continue
            low, high = interval(np.abs(k_model[use] / k_boot[:, use] - 1).max(-1), level)
            inside = (dev[use] >= band[0][use]) & (dev[use] <= band[1][use])
            rows.append({
                "model": name, **{a: combo[a] for a in runs.AXES["sphere"]}, "combination": label,
                "max_rel_dev": float(np.abs(dev[use]).max()), "max_rel_dev_ci_low": low,
                "max_rel_dev_ci_high": high, "rms_rel_dev": float(np.sqrt(np.mean(dev[use] ** 2))),
                "n_loads": int(use.sum()), "force_min": float(force_norm[use].min()),
                "force_max": float(force_norm[use].max()), "paper_setting": combo.paper_setting,
                "inside_band": float(inside.mean()), "crossover_force": f_tr,
                **_systematic(k_model, k_mean, k_boot, use & (force_norm < f_tr), "low", level),
                **_systematic(k_model, k_mean, k_boot, use & (force_norm >= f_tr), "high", level),
            })
        curves[label] = xr.Dataset(
            {**{name: ("force", dev, {"long_name": f"k_{name}/k_BEM - 1", "units": "1"})
                for name, dev in dev_of.items()},
             "band_low": ("force", band[0], {"long_name": f"{level:.0%} band of the ensemble mean, low", "units": "1"}),
             "band_high": ("force", band[1], {"long_name": f"{level:.0%} band of the ensemble mean, high", "units": "1"}),
             "resolved": ("force", use_load.astype("i1"), {"long_name": "resolved load (1) or not (0)", "units": "1"})},
            coords={"force_normalized": ("force", force_norm, {"long_name": "F/(E* L^2)", "units": "1"})},
            attrs={k: v for k, v in combo.items()})
    table = pd.DataFrame(rows)
    if len(table):
        table["rank"] = table.groupby("combination")["max_rel_dev"].rank(method="min").astype(int)
    return table, curves


def scorecard_lead() -> str:
    """The lead paragraph of the scorecard page of the report (the registered models' summaries)."""
    summaries = "; ".join(model.summary for model in registry.models().values())
    return ("Each model predicts the rough sphere's stiffness k(F) from the surface's parameters; "
            "max_rel_dev is the largest |k_model/k_BEM - 1| over the resolved loads of the ensemble "
            "mean, with its 95 % bootstrap-over-seeds interval, rms_rel_dev the rms of the same "
            "deviations; rank 1 is the best model of its combination; inside_band the fraction of those loads "
            "where the model lies inside the ensemble's band; systematic_low and systematic_high the mean "
            "deviation below and above the crossover force (eq. 17), weighted by the inverse variance of the "
            "ensemble mean, with its interval and verdict on 0 (differs: a significant systematic deviation). "
            f"{summaries}. models.csv holds every digit.")


def _figure(path, label: str, curve, table) -> None:
    plt = pyplot()
    force = curve["force_normalized"].values
    shown = curve["resolved"].values.astype(bool)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.fill_between(force, curve["band_low"], curve["band_high"], color="0.85", label="BEM ensemble, 95 % band")
    ax.axhline(0, color="0.4", lw=0.8)
    for name in registry.models():
        if name in curve:
            mark = table[(table["combination"] == label) & (table["model"] == name)]
            text = f" (max {float(mark['max_rel_dev'].iloc[0]):.1%})" if len(mark) else ""
            ax.semilogx(force[shown], curve[name].values[shown], "o-", ms=3, label=name + text)
    ax.set(xlabel="F / (E* L²)", ylabel="k_model / k_BEM − 1", title=label)
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_png(fig, path)


def run_models(cfg, stiffness_nc, zeta_csv, out_csv, out_nc, out_html, figures):
    """``models`` rule: the scorecard table (CSV, HTML), the per-load deviations (NetCDF, one group
    per combination) and one figure per sphere combination (*figures*, in the order of
    :func:`roughcontact.study.runs.sphere_names`)."""
    import pandas as pd

    from .io import read_groups, write_csv, write_groups

    table, curves = scorecard(read_groups(stiffness_nc), pd.read_csv(zeta_csv), cfg)
    attrs = provenance.provenance_attrs(config=cfg, title="model scorecard: k_model/k_BEM - 1 per load",
                                        bootstrap_over="seeds", forces="F/(E* L^2)")
    write_csv(table, out_csv)
    write_groups(out_nc, curves, attrs)
    write_html_table(table, out_html, title="Model scorecard", lead=scorecard_lead(),
                     verdict_columns=("systematic_low_verdict", "systematic_high_verdict"),
                     first=("combination", "model", "rank", "max_rel_dev", "max_rel_dev_ci_low",
                            "max_rel_dev_ci_high", "rms_rel_dev", "inside_band", "systematic_low",
                            "systematic_low_verdict", "systematic_high", "systematic_high_verdict", "n_loads"))
    names = runs.sphere_names(cfg)
    if len(names) != len(figures):
        raise ValueError(f"run_models got {len(figures)} figure paths for {len(names)} sphere combinations")
    for label, path in zip(names, figures):
        if label not in curves:
            raise ValueError(f"no sphere combination {label} in {stiffness_nc} for the figure {path}")
        _figure(path, label, curves[label], table)
    log.info("scorecard:\n%s", table.to_string() if len(table) else "(no sphere runs)")
