"""Claims (l) and (m) from the local exponents (:mod:`roughcontact.study.analysis.exponents`) and the ζ fit:
(l) with a roll-off below the system size, ``K ∝ p`` over a range of loads (Pastewka et al.,
Phys. Rev. E 87, 062809 (2013)); (m) the free stiffness exponent of flat surfaces against
Pohrt & Popov, Phys. Rev. Lett. 108, 104301 (2012)."""
from __future__ import annotations

import itertools
import math

from ..analysis.statistics import NOT_SWEPT, OFF_PAPER, UNRESOLVED, judge, untested
from ..config import axes
from .registry import Claim, flat_zeta_rows, register, row

__all__ = ["prl2012_exponent", "exponent_rows"]


def prl2012_exponent(hurst: float) -> float:
    """The free stiffness exponent of nominally flat fractal surfaces of Pohrt & Popov, Phys. Rev.
    Lett. 108, 104301 (2012), doi 10.1103/PhysRevLett.108.104301: 0.77 at fractal dimension
    D = 3 (H → 0) and 0.51 at D = 2 (H = 1), interpolated linearly in H = 3 − D."""
    return 0.77 - 0.26 * hurst


def exponent_rows(exponents, zeta_df, study) -> list[dict]:
    """Claims (l) and (m) from the local exponents (:mod:`roughcontact.study.analysis.exponents`) and the ζ fit.

    (l) With a roll-off below the system size, ``K ∝ p`` over a range of pressures (Pastewka et
    al., Phys. Rev. E 87, 062809 (2013)): per H and roll-off ``λ_r < L``, the largest local
    exponent of the flat runs at the paper's setting of every other optional axis
    (:func:`~roughcontact.study.config.axes.paper_mask`) with its interval; consistent when the interval of some load
    contains 1 (the number of such loads is the reason). (m) The free exponent of the flat runs
    at the paper's setting (``zeta.csv``) against :func:`prl2012_exponent`.
    """
    L = study.grid.length
    n, seeds = study.grid.n, len(study.seeds)
    flat_swept = any(not math.isfinite(r) for r in study.radius)
    rolled = sorted(r for r in study.rolloff if r is not None and r < L)
    statement = "with a roll-off lambda_r < L, K ~ p (local exponent 1) over a range of loads (Pastewka et al. 2013)"
    rows = []
    if not (flat_swept and rolled):
        why = "no flat runs" if not flat_swept else "no roll-off below L swept"
        rows.append(row("l", statement, math.nan, math.nan, math.nan, 1.0, untested(NOT_SWEPT, why)))
    for hurst, rolloff in itertools.product(study.hurst, rolled if flat_swept else []):
        sub = exponents[(exponents["kind"] == "flat") & (exponents["hurst"] == hurst)
                        & (exponents["rolloff"] == rolloff)] if len(exponents) else exponents
        # every other optional axis at the paper's setting: the claim is about the roll-off alone
        sub = sub[axes.paper_mask(sub.drop(columns="rolloff"), L)] if len(sub) else sub
        sweep = f"flat H = {hurst:g}, rolloff = {rolloff:g} (length unit), {seeds} seeds, n = {n}"
        if not len(sub):
            rows.append(row("l", statement, math.nan, math.nan, math.nan, 1.0,
                               untested(UNRESOLVED, "no load with a resolved window"), sweep=sweep, hurst=hurst,
                               rolloff=rolloff))
            continue
        covers = (sub["ci_low"] <= 1.0) & (sub["ci_high"] >= 1.0)
        covered = int(covers.sum())
        # the row shows the load the verdict rests on: the largest exponent whose interval holds 1, else the largest
        top = sub[covers].loc[sub[covers]["local_exponent"].idxmax()] if covered else \
            sub.loc[sub["local_exponent"].idxmax()]
        text = (f"consistent: the interval contains 1 at {covered} of {len(sub)} loads (no correction for "
                f"testing several loads)" if covered else judge(1.0, top["ci_low"], top["ci_high"]))
        rows.append(row("l", statement, float(top["local_exponent"]), float(top["ci_low"]), float(top["ci_high"]), 1.0,
                           text, sweep=sweep, hurst=hurst, rolloff=rolloff,
                           loads=f"{len(sub)} loads with a resolved window, F/(E*L^2) = {sub['force'].min():.3g}..."
                                 f"{sub['force'].max():.3g}; the row's load {top['force']:.3g}",
                           note=("measured: the largest local exponent d ln k/d ln F (exponents.csv) whose interval "
                                 "holds 1, else the largest")))
    statement = ("free stiffness exponent of flat surfaces 0.77 (H -> 0) to 0.51 (H = 1), linear in H "
                 "(Pohrt & Popov, PRL 2012)")
    flat = flat_zeta_rows(zeta_df)
    if not len(flat):
        # flat ζ fits off the paper's setting only (zeta.csv's source names the axis), or none at all
        off = len(zeta_df) and zeta_df["source"].astype(str).str.startswith("flat").any()
        rows.append(row("m", statement, math.nan, math.nan, math.nan, math.nan,
                           untested(OFF_PAPER if off else NOT_SWEPT, "no flat runs at the paper's setting")))
    for _, z in flat.iterrows():
        value = prl2012_exponent(z["hurst"])
        rows.append(row("m", statement, z["exponent"], z["exponent_ci_low"], z["exponent_ci_high"], value,
                           judge(value, z["exponent_ci_low"], z["exponent_ci_high"]), hurst=z["hurst"],
                           sweep=f"flat H = {z['hurst']:g}, {int(z['n_seeds'])} seeds, n = {n}", loads=z["window"],
                           note="measured: the free exponent of the zeta fit (zeta.csv)"))
    return rows


def _rows(letter: str):
    def rows(inputs):
        return [r for r in exponent_rows(inputs.exponents, inputs.zeta, inputs.study) if r["claim"] == letter]
    return rows


register(Claim("l", "with a roll-off lambda_r < L, K ~ p (local exponent 1) over a range of loads", _rows("l"),
               needs=("exponents",)))
register(Claim("m", "free stiffness exponent of flat surfaces 0.77 (H -> 0) to 0.51 (H = 1) (PRL 2012)", _rows("m"),
               needs=("exponents",)))
