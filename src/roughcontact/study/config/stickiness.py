"""The stickiness sweep of a configuration (its ``stickiness`` section), typed, and its jobs."""
from __future__ import annotations

import dataclasses
from collections.abc import Mapping

from .defaults import capped_tol
from .records import RunRecord
from .renamed import current_layout

__all__ = ["StickinessRun", "StickinessSettings"]


@dataclasses.dataclass(frozen=True, kw_only=True)
class StickinessRun(RunRecord):
    """The resolved settings of one stickiness run: everything it depends on and nothing else.

    Its job record (:class:`~roughcontact.study.config.records.RunRecord`: the grid ``n`` (periodic),
    ``length``, ``e_star`` and ``tol``, capped by
    :func:`roughcontact.study.config.defaults.capped_tol`) with the surface and the approach path
    of this kind. The ``stickiness_run`` rule's ``params`` and the ``config`` (and ``config_hash``)
    its run file records, so that another seed, number or Hurst exponent in the sweep, or a change
    of the merge's interval (``fit.confidence``, ``fit.bootstrap``), reruns no finished run. Built by
    :meth:`StickinessSettings.run`.

    Attributes
    ----------
    hurst, number, seed :
        The run: Hurst exponent, Pastewka–Robbins number, seed of the surface.
    rms_slope : float
        ``h′`` of the surface (dimensionless).
    cutoff : float
        Short-wavelength cutoff in cells.
    range_ratio : float
        ``Δr/g₀`` (dimensionless).
    area : float
        Contact fraction up to which the surface is loaded.
    steps : int
        Approaches of the loading path.
    """

    hurst: float
    number: float
    seed: int
    rms_slope: float
    cutoff: float
    range_ratio: float
    area: float
    steps: int

    @property
    def combination(self) -> str:
        """The name of its (H, N) combination in paths, e.g. ``H0.8_N0.5``."""
        return f"H{self.hurst:g}_N{self.number:g}"

    def describe(self) -> str:
        """The run as logs and error messages name it."""
        return f"stickiness {self.combination} seed {self.seed}"

    def file_spec(self):
        """What this run's file must be (:class:`roughcontact.study.files.runfile.RunFileSpec`, checked by
        :func:`roughcontact.study.files.io.read_run`): the loading path over ``approach``, the run's
        scalars and the ``config_hash`` of :meth:`record`."""
        from ..files import runfile

        return runfile.RunFileSpec(title=runfile.STICKINESS_TITLE,
                                   variables=(*runfile.STICKINESS_VARIABLES, *runfile.STICKINESS_SCALARS),
                                   dims=("approach",), config=self.record())


@dataclasses.dataclass(frozen=True)
class StickinessSettings:
    """The ``stickiness`` section of a resolved configuration (the schema's descriptions).

    Attributes
    ----------
    n : int
        Grid points per side (periodic).
    length, e_star : float
        Side ``L`` of the surfaces (``grid.length``) and ``E*`` (``e_star``).
    hurst, number : tuple of float
        The Hurst exponents and Pastewka–Robbins numbers swept.
    rms_slope : float
        ``h′`` of every surface (dimensionless).
    cutoff : float
        Short-wavelength cutoff in cells.
    range_ratio : float
        ``Δr/g₀``.
    seeds : int
        Surfaces per (H, N): seeds ``0 … seeds−1``.
    area : float
        Contact fraction up to which a surface is loaded and its slope fitted.
    steps : int
        Approaches of a loading path.
    tol, confidence, bootstrap :
        The solver's tolerance (``solver.tol``, capped by
        :func:`~roughcontact.study.config.defaults.capped_tol`) and the interval of the merged table
        (``fit.confidence``, ``fit.bootstrap``).
    """

    n: int
    length: float
    e_star: float
    hurst: tuple
    number: tuple
    rms_slope: float
    cutoff: float
    range_ratio: float
    seeds: int
    area: float
    steps: int
    tol: float
    confidence: float
    bootstrap: int

    @classmethod
    def of(cls, cfg) -> "StickinessSettings | None":
        """The sweep of a resolved configuration (:func:`roughcontact.study.config.resolve.resolve_config`;
        a :class:`~roughcontact.study.config.settings.StudySettings` has it as ``stickiness``; a
        :class:`StickinessSettings` is returned unchanged); ``None`` where it has no
        ``stickiness`` section."""
        if isinstance(cfg, StickinessSettings):
            return cfg
        if not isinstance(cfg, Mapping):
            return cfg.stickiness
        section = cfg.get("stickiness")
        if section is None:
            return None
        fit = current_layout(cfg)["fit"]   # a recorded configuration from before the rename too
        return cls(n=int(section["n"]), length=float(cfg["grid"]["length"]), e_star=float(cfg["e_star"]),
                   hurst=tuple(sorted(float(h) for h in section["hurst"])),
                   number=tuple(sorted(float(x) for x in section["number"])),
                   rms_slope=float(section["rms_slope"]), cutoff=float(section["cutoff"]),
                   range_ratio=float(section["range_ratio"]), seeds=int(section["seeds"]),
                   area=float(section["area"]), steps=int(section["steps"]),
                   tol=capped_tol(float(cfg["solver"]["tol"])), confidence=float(fit["confidence"]),
                   bootstrap=int(fit["bootstrap"]))

    def run(self, *, hurst: float, number: float, seed: int) -> StickinessRun:
        """The :class:`StickinessRun` of the surface (*hurst*, *seed*) at the number *number*: the
        sweep's settings that one run depends on."""
        return StickinessRun(hurst=float(hurst), number=float(number), seed=int(seed), n=self.n, length=self.length,
                             e_star=self.e_star, rms_slope=self.rms_slope, cutoff=self.cutoff,
                             range_ratio=self.range_ratio, area=self.area, steps=self.steps, tol=self.tol)

    def record(self) -> dict:
        """The sweep as a flat mapping of plain values: the merged files' ``config`` and
        ``config_hash`` (what the stickiness merge depends on, nothing else of the configuration)."""
        return dataclasses.asdict(self)

    def jobs(self) -> list[StickinessRun]:
        """Every run, by H, then N, then seed (the order the merge expects)."""
        return [self.run(hurst=h, number=x, seed=s) for h in self.hurst for x in self.number for s in range(self.seeds)]

    def job(self, combination: str, seed) -> StickinessRun:
        """The run of a path's *combination* (``H0.8_N0.5``) and *seed*: the ``stickiness_run``
        rule's ``params``; ``KeyError`` naming the combinations of the sweep for any other."""
        for job in self.jobs():
            if job.combination == combination and job.seed == int(seed):
                return job
        raise KeyError(f"no stickiness run {combination} seed {seed}; the sweep has "
                       f"{sorted({j.combination for j in self.jobs()})} with seeds 0..{self.seeds - 1}")
