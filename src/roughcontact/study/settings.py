"""The settings of one indentation job: a frozen, typed record from the configuration to the job.

:func:`job_settings` picks out of a resolved configuration everything one run depends on and
nothing else, so that adding a seed or a sweep value does not invalidate finished runs. The
Snakemake ``indent`` rule and ``roughcontact indent`` both build a :class:`JobSettings` this way;
:mod:`roughcontact.study.indent` runs it.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..bem import DEFAULT_MAXITER
from .runs import DEFAULTS, force_grid, kind_of, parse_combo

__all__ = ["JobSettings", "job_settings", "settings_from_wildcards"]


@dataclasses.dataclass(frozen=True)
class JobSettings:
    """Everything one indentation run depends on.

    Lengths are in the unit of ``length``; forces are given normalised, ``F/(E* L²)``.

    Attributes
    ----------
    hurst, radius, h_rms, seed :
        The run: Hurst exponent, body radius (``inf``: a nominally flat surface on the
        periodic half-space), rms roughness height, seed of the surface.
    n, length, e_star :
        Grid points per side, side length ``L``, effective modulus ``E*``.
    force_from, force_to, force_count :
        The log-spaced load path, ``F/(E* L²)``.
    tol, maxiter :
        Stopping tolerance and iteration limit of every contact solve of the run
        (:func:`roughcontact.bem.solve`), the stiffness's extra solves included.
    stiffness_method, rel_step :
        How ``k = dF/dd`` is computed (:func:`roughcontact.bem.stiffness`).
    exponent, rolloff, cutoff :
        The optional axes: body ``z = (R/m)(r/R)^m``, roll-off and cutoff wavelengths
        (``None``: none).
    hardness_e_star :
        Penetration hardness in units of ``E*`` (``None``: elastic);
        :attr:`hardness` is the pressure.
    """

    hurst: float
    radius: float
    h_rms: float
    seed: int
    n: int
    length: float
    e_star: float
    force_from: float
    force_to: float
    force_count: int
    tol: float
    stiffness_method: str
    rel_step: float
    maxiter: int = DEFAULT_MAXITER
    exponent: float = DEFAULTS["exponent"]
    rolloff: float | None = DEFAULTS["rolloff"]
    cutoff: float | None = DEFAULTS["cutoff"]
    hardness_e_star: float | None = DEFAULTS["hardness"]

    @property
    def kind(self) -> str:
        """``"sphere"`` (finite radius, free half-space) or ``"flat"`` (periodic)."""
        return kind_of(self.radius)

    @property
    def periodic(self) -> bool:
        """Whether the half-space is periodic (the nominally flat surfaces)."""
        return self.kind == "flat"

    @property
    def hardness(self) -> float | None:
        """Penetration hardness as a pressure (the unit of ``e_star``); ``None``: elastic."""
        return None if self.hardness_e_star is None else self.hardness_e_star * self.e_star

    def forces_normalized(self) -> np.ndarray:
        """The load path ``F/(E* L²)``, log-spaced."""
        return force_grid(self.force_from, self.force_to, self.force_count)

    def forces(self) -> np.ndarray:
        """The load path in force units, ``F = (F/(E* L²)) E* L²``."""
        return self.forces_normalized() * self.e_star * self.length**2

    def axes(self) -> dict:
        """The optional axes off the paper's setting (:data:`~roughcontact.study.runs.DEFAULTS`),
        under their configuration names (``hardness`` in units of ``E*``)."""
        values = {"exponent": self.exponent, "rolloff": self.rolloff, "cutoff": self.cutoff,
                  "hardness": self.hardness_e_star}
        return {axis: value for axis, value in values.items() if value != DEFAULTS[axis]}

    def record(self) -> dict:
        """The settings as a flat mapping of plain values: what a run file's ``config_hash``
        and attributes are made of. Optional axes at the paper's setting are left out."""
        out = {field.name: getattr(self, field.name) for field in dataclasses.fields(self)
               if field.name not in ("exponent", "rolloff", "cutoff", "hardness_e_star")}
        return {**out, **self.axes(), "kind": self.kind, "periodic": self.periodic}

    def describe(self) -> str:
        """One line naming the run, for logs and error messages."""
        r = "inf (flat, periodic)" if not math.isfinite(self.radius) else f"{self.radius:g}"
        extra = "".join(f", {axis} = {value:g}" for axis, value in self.axes().items())
        return f"H = {self.hurst:g}, R = {r}, h_rms = {self.h_rms:g}{extra}, seed = {self.seed}, n = {self.n}"


def job_settings(cfg: dict, run: dict) -> JobSettings:
    """The :class:`JobSettings` of one run (a dict of :func:`roughcontact.study.runs.runs`)
    of the resolved configuration *cfg*."""
    radius = float(run["radius"])
    rng = cfg["forces"][kind_of(radius)]
    solver = cfg["solver"]
    optional = {axis: None if run.get(axis, default) is None else float(run.get(axis, default))
                for axis, default in DEFAULTS.items()}
    return JobSettings(
        hurst=float(run["hurst"]), radius=radius, h_rms=float(run["h_rms"]), seed=int(run["seed"]),
        n=int(cfg["grid"]["n"]), length=float(cfg["grid"]["length"]), e_star=float(cfg["e_star"]),
        force_from=float(rng["from"]), force_to=float(rng["to"]), force_count=int(rng["count"]),
        tol=float(solver["tol"]), stiffness_method=solver["stiffness"], rel_step=float(solver["rel_step"]),
        maxiter=int(solver.get("maxiter", DEFAULT_MAXITER)),
        exponent=optional["exponent"], rolloff=optional["rolloff"], cutoff=optional["cutoff"],
        hardness_e_star=optional["hardness"])


def settings_from_wildcards(cfg: dict, wildcards) -> JobSettings:
    """:func:`job_settings` of the run named by the ``indent`` rule's wildcards ``combo`` and ``seed``."""
    return job_settings(cfg, {**parse_combo(wildcards.combo), "seed": int(wildcards.seed)})
