"""Claims (r)-(t): the tangential contact of the rough sphere (axes ``poisson``, ``friction``).

(r) the full-stick ``k_t/k_n`` equals Mindlin's ``2(1 − ν)/(2 − ν)`` (Mindlin 1949; the MDR's
tangential springs, Popov & Heß 2015), on the fractal branch (resolved loads below ``F_tr``) and on
the Hertz branch (above it), one row each; (s) the tangent ``k_t(Q)`` of the partial-slip path
against Cattaneo–Mindlin's ``k_t(0)(1 − Q/μP)^(1/3)`` above the crossover and against
Ciavarella–Jäger's ``k_t(0) k_n(P − Q/μ)/k_n(P)`` below it; (t) the largest micro-slip at the onset
of gross sliding against Grzemba et al.'s ``δ_max = μ d E*/G*`` (Wear 309, 40 (2014)), per branch.
Each row: the ensemble's value averaged over the branch's loads (and tangential steps), its
percentile bootstrap interval over seeds, the model's value, the verdict (``consistent``: the
model's value inside the interval widened by :data:`NUMERICAL_TOLERANCE` of it on each side, the
method's own accuracy, so that the exact control ``ν = 0`` is not judged on the solver's last digits).
(s) also has Ciavarella–Jäger on the Hertz branch, where it and Cattaneo–Mindlin part: the stick
zone's normal load ``P − Q/μ`` falls onto the fractal branch as ``Q → μP``. ``F_tr`` is the combination's measured crossover force
(``crossover.csv``), eq. 17's where it is not resolved. Estimators:
:mod:`roughcontact.study.analysis.tangential`.
"""
from __future__ import annotations

import math

from ...models import tangential as theory
from ..analysis import tangential as estimate
from ..analysis.ensemble import combinations
from ..analysis.statistics import NOT_SWEPT, UNRESOLVED, judge, untested
from .registry import Claim, describe, register, row

__all__ = ["NUMERICAL_TOLERANCE"]

#: relative accuracy of the tangential quantities, by which each interval is widened: the normal
#: approach d of a contact solve at tol 1e-8 is accurate to ~2e-4 relative (the first-touch cell's
#: penetration; ν = 0 gives δ_max/(μd) = 1 + 1.5e-4 on 129², tests/test_tangential_study.py), the
#: Ciavarella–Jäger stiffness is interpolated log-log between the path's loads
NUMERICAL_TOLERANCE = 1e-3


def _sweep(study, where: dict) -> str:
    return describe(where, study.grid.length, study.grid.n, len(study.seeds))


def _verdict(value: float, est, loads: int, branch: str, split) -> str:
    if not math.isfinite(split.crossover):
        return untested(UNRESOLVED, "no crossover force for this combination (crossover.csv)")
    if not loads:
        return untested(NOT_SWEPT, f"no resolved load on the {branch} branch (F_tr = {split.crossover:.3g})")
    pad = NUMERICAL_TOLERANCE * abs(value)
    return judge(value, est.low - pad, est.high + pad)


_BRANCH = {"fractal": "fractal branch (resolved loads below F_tr)", "hertz": "Hertz branch (loads above F_tr)"}


def _r(inputs):
    """Claim (r) per combination of the ``full_stick`` group and branch."""
    study, out = inputs.study, []
    for where, stick in combinations(inputs.tangential["full_stick"], "tangential_stiffness"):
        split = estimate.combination_branches(stick, inputs.cross, where, study)
        mindlin = theory.stiffness_ratio(where["poisson"])
        for branch in ("fractal", "hertz"):
            mask = getattr(split, branch)
            est = estimate.stiffness_ratio(stick, mask, study)
            forces = stick["force_normalized"].values[mask]
            out.append(row(
                "r", f"full-stick k_t/k_n = 2(1-nu)/(2-nu) (Mindlin) on the {_BRANCH[branch]}", est.value, est.low,
                est.high, mindlin, _verdict(mindlin, est, est.count, branch, split), sweep=_sweep(study, where),
                loads=(f"{est.count} loads, F/(E*L^2) = {forces.min():.2g}...{forces.max():.2g}; F_tr = "
                       f"{split.crossover:.3g} ({split.source})" if est.count else ""),
                note=(f"measured: mean over the loads of the ensemble's k_t/k_n (per load {est.spread[0]:.4g} ... "
                      f"{est.spread[1]:.4g}; {est.value / mindlin - 1:+.2%} from Mindlin)" if est.count else ""),
                **where))
    return out


def _slip_combinations(inputs):
    """``(where, stick, slip, split, branch loads)`` of every combination of the ``partial_slip`` group."""
    for where, stick, slip in estimate.slip_combinations(inputs.tangential):
        split = estimate.combination_branches(stick, inputs.cross, where, inputs.study)
        index = slip["slip_load_index"].values
        loads = {branch: [j for j, i in enumerate(index) if getattr(split, branch)[int(i)]]
                 for branch in ("fractal", "hertz")}
        yield where, stick, slip, split, loads


def _loads_text(slip, loads, split) -> str:
    if not loads:
        return ""
    forces = slip["slip_load"].values[loads]
    return (f"{len(loads)} normal loads, F/(E*L^2) = {forces.min():.2g}...{forces.max():.2g}, "
            f"{slip.sizes['slip_step']} steps Q/(mu P) each; F_tr = {split.crossover:.3g} ({split.source})")


def _s(inputs):
    """Claim (s): Cattaneo–Mindlin on the Hertz branch, Ciavarella–Jäger on the fractal branch."""
    study, out = inputs.study, []
    for where, stick, slip, split, loads in _slip_combinations(inputs):
        cj = "Ciavarella-Jaeger k_t(0) k_n(P-Q/mu)/k_n(P)"
        for branch, model, name in (("hertz", "cattaneo", "Cattaneo-Mindlin k_t(0)(1-Q/muP)^(1/3)"),
                                    ("fractal", "ciavarella-jaeger", cj), ("hertz", "ciavarella-jaeger", cj)):
            est = estimate.slip_shape(stick, slip, loads[branch], study, model=model)
            out.append(row(
                "s", f"partial slip: k_t(Q) = {name} on the {_BRANCH[branch]}", est.value, est.low, est.high, 1.0,
                _verdict(1.0, est, len(loads[branch]), branch, split), sweep=_sweep(study, where),
                loads=_loads_text(slip, loads[branch], split),
                note=(f"measured: mean over loads and steps of the ensemble's k_t(Q)/k_model(Q) (per step "
                      f"{est.spread[0]:.4g} ... {est.spread[1]:.4g})" if est.count else ""), **where))
    return out


def _t(inputs):
    """Claim (t): the largest micro-slip against Grzemba et al., per branch."""
    study, out = inputs.study, []
    for where, _, slip, split, loads in _slip_combinations(inputs):
        for branch in ("fractal", "hertz"):
            est = estimate.micro_slip(slip, loads[branch], where["poisson"], where["friction"], study)
            out.append(row(
                "t", f"largest micro-slip delta_max = mu d E*/G* (Grzemba et al. 2014) on the {_BRANCH[branch]}",
                est.value, est.low, est.high, 1.0, _verdict(1.0, est, len(loads[branch]), branch, split),
                sweep=_sweep(study, where), loads=_loads_text(slip, loads[branch], split),
                note=(f"measured: mean over the loads of the ensemble's delta_max/(mu d E*/G*), d from first touch "
                      f"(per load {est.spread[0]:.4g} ... {est.spread[1]:.4g})" if est.count else ""), **where))
    return out


def _has_slip(inputs) -> bool:
    return "partial_slip" in (inputs.tangential or {})


register(Claim("r", "the rough sphere's full-stick k_t/k_n equals Mindlin's 2(1-nu)/(2-nu)", _r, needs=("tangential",)))
register(Claim("s", "k_t(Q) follows Cattaneo-Mindlin above the crossover and Ciavarella-Jaeger below it",
               lambda inputs: _s(inputs) if _has_slip(inputs) else [], needs=("tangential",)))
register(Claim("t", "the largest micro-slip is mu d E*/G* (Grzemba et al. 2014)",
               lambda inputs: _t(inputs) if _has_slip(inputs) else [], needs=("tangential",)))
