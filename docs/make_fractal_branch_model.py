"""The model that holds on both branches (issue 31, item 3): ``docs/results/fractal_branch_model.md``.

    python docs/make_fractal_branch_model.py --calibration DIR [DIR ...] --heldout DIR [DIR ...] --validation DIR [DIR ...]

Each DIR is a directory a preset ran in (``snakemake --cores 2 --configfile presets/NAME.yaml
--directory DIR``): ``calibration-branches``, ``calibration-branches-451`` and
``calibration-branches-447`` for ``--calibration``, ``heldout-branches-a`` and
``heldout-branches-b`` for ``--heldout``, ``validation-branches``, ``validation-branches-2`` and
``validation-branches-3`` for ``--validation``. The page gives, per combination of the held-out
and validation sets, the recommended model's and those of :data:`MODEL` and :data:`COMPARED`
systematic deviation on each branch (with its 95 % interval over seeds), the grid error added
there, the fraction of resolved loads inside the band widened by the grid error and whether the
row holds (:func:`roughcontact.study.analysis.decision.holds`); the calibration sets' table of the
same columns; how the rough sphere approaches Hertz; what a sweep of 16 seeds can tell (the
spread of 16-seed means about the 160-seed mean of held-out sweep A); and one figure of every
held-out combination's deviations. The reading, with the wall times, is
``docs/results/fractal_branch_model_reading.txt``, included verbatim.
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import pandas as pd

from roughcontact.study.analysis import decision
from roughcontact.study.files.directory import StudyDirectory
from roughcontact.study.report.plotting import panel_grid, pyplot, save_png

from make_calibration import _commit, _scores
from make_results import _machine, _table

DOCS = Path(__file__).resolve().parent
OUT = DOCS / "results" / "fractal_branch_model.md"
FIGURE = OUT.with_suffix(".png")
READING = OUT.with_name("fractal_branch_model_reading.txt")
#: the model of the page and the ones it is compared with
MODEL = "contact_scale_tail"
COMPARED = ("contact_scale_h", "contact_scale", "eq16_paper")
#: the seeds of issue 31's first sweep, for the sampling spread
ISSUE_SEEDS = 16
#: the Hertz end of a combination: its resolved loads above this multiple of eq. 17's F_tr
HERTZ_END = 10.0


def _branch(row, branch: str) -> str:
    """``+2.6 [−0.5, +5.8] %, 2 loads, grid 1.6 %`` of one branch of a scorecard row."""
    if not row[f"n_loads_{branch}"]:
        return "no resolved load"
    grid = row.get(f"grid_error_{branch}", np.nan)
    text = "{:+.1f} [{:+.1f}, {:+.1f}] %, {} loads".format(
        *(100 * row[f"systematic_{branch}{c}"] for c in ("", "_ci_low", "_ci_high")), int(row[f"n_loads_{branch}"]))
    return text + (f", grid {100 * grid:.1f} %" if np.isfinite(grid) else ", grid not measured")


def _rows(scores: pd.DataFrame) -> pd.DataFrame:
    """Per combination: the recommended row, then MODEL's and COMPARED's rows (each once), with
    each branch's systematic deviation, its interval, loads and grid error in one cell."""
    keep = scores["recommended"].astype(bool) | scores["model"].isin((MODEL, *COMPARED))
    out = scores[keep].copy()
    out["_order"] = np.where(out["recommended"].astype(bool), 0, 1)
    out = out.sort_values(["study", "combination", "_order", "model"])
    inside = out["inside_band_total"].where(np.isfinite(out["inside_band_total"]), out["inside_band"])
    return pd.DataFrame({
        "study": out["study"], "combination": out["combination"], "model": out["model"],
        "decision": out["decision"], "holds": out["holds"].map({True: "yes", False: "no"}),
        "systematic below F_tr": [_branch(r, "low") for _, r in out.iterrows()],
        "systematic above F_tr": [_branch(r, "high") for _, r in out.iterrows()],
        "inside the band (+ grid error)": [f"{100 * v:.0f} %" for v in inside],
        "S": [f"{100 * v:.1f} %" for v in out["decision_score"]]}).reset_index(drop=True)


def _sampling(workdir: Path, seeds: int = ISSUE_SEEDS, draws: int = 2000) -> pd.DataFrame:
    """Per combination: the 95 % range of the mean of *seeds* seeds drawn (without replacement)
    from all, relative to the mean of all, per resolved load and averaged over each branch's
    resolved loads (F below or above eq. 17's F_tr with eq. 13's ζ): what a perfect model's
    deviation spans on a sweep of *seeds* seeds."""
    from roughcontact.models import paper

    directory = StudyDirectory(workdir)
    ds = directory.groups("stiffness")["sphere"]
    rng = np.random.default_rng(31)
    rows = []
    for h_rms in np.atleast_1d(ds["h_rms"].values):
        sub = ds.sel(h_rms=h_rms).squeeze()
        hurst, radius = float(sub["hurst"]), float(sub["radius"])
        k = sub["stiffness"].transpose("seed", "force").values
        use = sub["contact_cells"].transpose("seed", "force").values.mean(0) >= 20
        f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=float(h_rms), length=1.0, e_star=1.0,
                                     zeta=float(paper.zeta_estimate(hurst)))
        below = sub["force"].values < f_tr
        picks = np.array([rng.choice(k.shape[0], seeds, replace=False) for _ in range(draws)])
        ratio = k[picks].mean(1) / k.mean(0) - 1                       # (draw, force)
        low, high = np.percentile(ratio[:, use], [2.5, 97.5], axis=0)
        row = {"combination": f"H{hurst:g}_R{radius:g}_h{float(h_rms):g}", "seeds of the full mean": k.shape[0],
               "seeds drawn": seeds, "per load, smallest": f"±{100 * np.min((high - low) / 2):.1f} %",
               "per load, largest": f"±{100 * np.max((high - low) / 2):.1f} %"}
        for name, mask in (("below F_tr", use & below), ("above F_tr", use & ~below)):
            if mask.any():
                row[f"branch mean {name}"] = "[{:+.1f}, {:+.1f}] %".format(
                    *(100 * np.percentile(ratio[:, mask].mean(1), [2.5, 97.5])))
        rows.append(row)
    return pd.DataFrame(rows)


def _hertz_end(dirs, above: float = HERTZ_END) -> pd.DataFrame:
    """Per combination with three or more resolved loads above *above* · F_tr (eq. 17 with eq. 13's
    ζ): how the rough sphere approaches Hertz (eq. 9). ``1 − k/k_Hertz`` falls as a power of F; its
    exponent fitted (least squares in log–log) to the ensemble mean, to ``contact_scale_h`` (whose
    p-norm gives ``−(2 − H) p(H)/3`` there) and to ``contact_scale_tail`` (``−2/3`` far from the
    crossover), and the values at the largest load with the ensemble's 95 % half-band."""
    from roughcontact.models import paper, superposition
    from roughcontact.study.analysis.ensemble import combinations

    rows = []
    for workdir in map(Path, dirs):
        for combo, sub in combinations(StudyDirectory(workdir).groups("stiffness")["sphere"]):
            hurst, radius, h_rms = combo["hurst"], combo["radius"], combo["h_rms"]
            k = sub["stiffness"].values
            force, mean = sub["force"].values, k.mean(0)
            f_tr = paper.crossover_force(radius, hurst=hurst, h_rms=h_rms, length=1.0, e_star=1.0,
                                         zeta=float(paper.zeta_estimate(hurst)))
            use = (sub["contact_cells"].values.mean(0) >= 20) & (force > above * f_tr)
            if use.sum() < 3:
                continue
            hertz = paper.hertz_stiffness(force, radius=radius, e_star=1.0)
            sphere = dict(radius=radius, hurst=hurst, h_rms=h_rms, length=1.0, e_star=1.0)
            models = {"contact_scale_h": superposition.hurst_calibrated_stiffness(force, **sphere),
                      "contact_scale_tail": superposition.tail_calibrated_stiffness(force, **sphere)}
            slope = {name: np.polyfit(np.log(force[use]), np.log(1 - value[use] / hertz[use]), 1)[0]
                     for name, value in (("BEM", mean), *models.items())}
            last = np.flatnonzero(use)[-1]
            half_band = 1.96 * k[:, last].std(ddof=1) / np.sqrt(k.shape[0]) / mean[last]
            rows.append({"study": workdir.name, "combination": f"H{hurst:g}_R{radius:g}_h{h_rms:g}",
                         "loads": int(use.sum()), "F/F_tr": f"{force[use][0] / f_tr:.0f}–{force[last] / f_tr:.0f}",
                         "exponent, BEM": f"{slope['BEM']:.2f}",
                         **{f"… {name}": f"{slope[name]:.2f}" for name in models},
                         "1 − k/k_Hertz at the largest load, BEM": f"{100 * (1 - mean[last] / hertz[last]):.2f} %",
                         **{f"… {name} ": f"{100 * (1 - value[last] / hertz[last]):.2f} %"
                            for name, value in models.items()},
                         "95 % half-band there": f"±{100 * half_band:.2f} %"})
    return pd.DataFrame(rows)


def _figure(dirs) -> None:
    curves = []
    for workdir in map(Path, dirs):
        for label, curve in StudyDirectory(workdir).groups("models_fit").items():
            curves.append((f"{workdir.name}: {label}", curve))
    plt = pyplot()
    fig, axes = panel_grid(plt, len(curves), width=4.5, height=3.4, max_columns=2, sharey=True)
    for ax, (title, curve) in zip(axes, curves):
        force = curve["force_normalized"].values
        shown = curve["resolved"].values.astype(bool)
        g = np.abs(np.nan_to_num(curve["grid_error"].values)) if "grid_error" in curve else 0 * force
        ax.fill_between(force[shown], -np.sqrt(curve["band_low"].values[shown] ** 2 + g[shown] ** 2),
                        np.sqrt(curve["band_high"].values[shown] ** 2 + g[shown] ** 2), color="0.9",
                        label="band and grid error")
        ax.fill_between(force[shown], curve["band_low"].values[shown], curve["band_high"].values[shown],
                        color="0.78", label="95 % band")
        ax.axhline(0, color="0.4", lw=0.8)
        for name in (MODEL, *COMPARED):
            if name in curve:
                ax.semilogx(force[shown], curve[name].values[shown], "o-", ms=3, label=name)
        ax.set(title=title, xlabel="F / (E* L²)", ylabel="k_model / k_BEM − 1", ylim=(-0.12, 0.12))
        ax.title.set_fontsize(8)
        ax.legend(fontsize=6)
    fig.tight_layout()
    save_png(fig, FIGURE, dpi=90)


def make_page(calibration, heldout, validation) -> Path:
    tested = [*heldout, *validation]
    _figure(tested)
    lines = [
        "# The fractal branch's model: `contact_scale_tail` and `contact_scale_h` on held-out sweeps",
        "",
        "Generated by `python docs/make_fractal_branch_model.py` from the scorecards (`models.csv`) of the "
        f"presets; machine: {_machine()}. Scorecards: "
        + "; ".join(_commit(Path(d)) for d in [*calibration, *tested]) + ".",
        "",
        READING.read_text(encoding="utf-8").strip() if READING.is_file() else "",
        "",
        "## Held-out sweeps and validation presets",
        "",
        "Per combination: the recommended model (first), `contact_scale_tail`, `contact_scale_h`, `contact_scale` "
        "and `eq16_paper`. "
        "Systematic: the deviation `k_model/k_BEM − 1` averaged over the branch's resolved loads (weighted by "
        "the inverse variance of the ensemble mean), its 95 % interval over seeds, the loads and the mean grid "
        "error added there; inside: the fraction of resolved loads inside the ensemble's 95 % band widened "
        "by the grid error (without it where none is measured); holds: the decision's criterion "
        f"({decision.HOLDS_CRITERION}); S: the decision's score.",
        "",
        _table(_rows(_scores(tested))),
        "",
        "![every held-out combination](fractal_branch_model.png)",
        "",
        "Each held-out combination: the deviation of `contact_scale_tail`, `contact_scale_h`, `contact_scale` "
        "and eq. 16 from the "
        "ensemble mean at the resolved loads, in the ensemble's 95 % band (dark) and that band widened by "
        "the grid error (light).",
        "",
        "## Calibration sets (in-sample)",
        "",
        _table(_rows(_scores(calibration))),
        "",
        "## The Hertz end",
        "",
        f"At loads above {HERTZ_END:g} F_tr the rough sphere is a little softer than Hertz, and the difference "
        "`1 − k/k_Hertz` falls as a power of F. The exponent fitted to the ensemble mean, to "
        "`contact_scale_h` (its p-norm gives `−(2 − H) p(H)/3`) and to `contact_scale_tail` (−2/3 far "
        "above the crossover), and the differences at the largest load:",
        "",
        _table(_hertz_end([*calibration, *tested])),
        "",
        f"## What {ISSUE_SEEDS} seeds can tell",
        "",
        f"Means of {ISSUE_SEEDS} seeds drawn from held-out sweep A's seeds, against the mean of all of them "
        "(a perfect model's deviation on a sweep of that size):",
        "",
        _table(_sampling(Path(heldout[0]))),
        "",
    ]
    OUT.write_text("\n".join(lines), encoding="utf-8")
    return OUT


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--calibration", type=Path, nargs="+", required=True)
    parser.add_argument("--heldout", type=Path, nargs="+", required=True)
    parser.add_argument("--validation", type=Path, nargs="+", required=True)
    args = parser.parse_args(argv)
    print(make_page(args.calibration, args.heldout, args.validation))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
