# module: roughcontact.study.claims.below_crossover
"""Claim (y): the sweep reaches the fractal branch: the smallest resolved load of every sphere
combination lies below its crossover force (eq. 17 with ζ = 1.7/(H+1), eq. 13).

Below the crossover the rough sphere follows the fractal branch of eq. 16 (k ∝ F^(1/(H+1))),
above it the Hertzian one: a sweep whose resolved loads all lie above F_tr cannot test the
roughness's effect. The claim reads a table of its own, ``results/resolved_loads.csv`` (one row
per sphere combination), made by the rule ``resolved_loads`` (the guide's rule example,
``workflow/rules/extra/resolved_loads.smk``): it registers the table (an :class:`InputTable`),
the ``claims`` rule then asks for the file, so Snakemake runs that rule first, and the claim gets
the table as ``inputs.tables["resolved_loads"]``.
"""
from __future__ import annotations

import math

from ..analysis.statistics import UNRESOLVED, untested, verdict_bound
from ..config.axes import AXES
from .registry import Claim, InputTable, register, register_table, row

STATEMENT = "the smallest resolved load of every sphere combination lies below the crossover force of eq. 17"

register_table(InputTable("resolved_loads", "results/resolved_loads.csv"))


def below_crossover(inputs):
    """One row per sphere combination of the table: the smallest resolved load over eq. 17's
    crossover force, with the interval in which the resolution threshold lies (from the load before
    it to it: the load grid's resolution); consistent where the whole interval is below 1, differs
    where it is above, untested where it holds 1 or no load is resolved."""
    rows = []
    for _, r in inputs.tables["resolved_loads"].iterrows():
        where = {name: float(r[name]) for name in r.index if name in AXES}
        ratio = float(r["first_resolved_ratio"])
        note = (f"measured: smallest resolved F/(E* L^2) = {r['first_resolved_force']:.4g} over F_tr(eq. 17, "
                f"zeta = 1.7/(H+1)) = {r['crossover_force_eq17']:.4g}")
        previous = float(r["previous_ratio"])
        verdict = (verdict_bound(1.0, previous, ratio, side="below") if math.isfinite(ratio)
                   else untested(UNRESOLVED, "no resolved load"))
        rows.append(row("y", STATEMENT, ratio, previous, ratio, 1.0, verdict, note=note,
                        loads=f"{int(r['resolved_loads'])} of {int(r['loads'])} loads resolved", **where))
    return rows


register(Claim("y", STATEMENT, rows=below_crossover, needs=("resolved_loads",)))
