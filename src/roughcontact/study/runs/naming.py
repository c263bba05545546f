"""The runs of a study: the sweep's combinations, run names and scheduler resources.

One run is one (H, R, h_rms, optional axes, seed) of a resolved configuration
(:func:`roughcontact.study.config.resolve.resolve_config`).  ``radius = inf`` is a nominally flat
self-affine surface on the periodic half-space; a finite radius is a rough sphere on the
free (non-periodic) half-space.  A run's name is :func:`combo_name` plus its seed; the
workflow turns names into paths with its own patterns (:func:`run_path`).
:mod:`roughcontact.study.runs.jobs` gives everything one run needs.
"""
from __future__ import annotations

import dataclasses
import functools
import itertools
import math
import re
import string

from ..config import axes
from ..config.axes import kind_of
from ..config.settings import StudySettings, force_grid

__all__ = [
    "format_value",
    "parse_value",
    "runs",
    "run_path",
    "run_paths",
    "combinations",
    "axis_value",
    "indent_resources",
    "indent_priority",
    "seed_blocks",
    "SeedBlock",
    "force_grid",
    "parse_run_path",
    "combo_name",
    "sphere_names",
    "parse_combo",
    "normal_representative",
    "AXES",
    "DEFAULTS",
    "kind_of",
]

def __getattr__(name: str):
    """``AXES``: the sweep axes of the normal problem of each surface kind, in the order of the
    merged file's dimensions (then ``seed`` and ``force``; the tangential axes, whose
    :attr:`~roughcontact.study.config.axes.Axis.normal` is ``False``, are not among them); ``DEFAULTS``: the paper's setting of the
    optional axes (a paraboloid, no roll-off, no cutoff, elastic), whose runs have the names
    and settings they had before the axes existed. Both read the registry
    :data:`roughcontact.study.config.axes.AXES` when asked, so an axis registered later is in them."""
    if name == "AXES":
        return {kind: axes.names(kind, normal=True) for kind in ("sphere", "flat")}
    if name == "DEFAULTS":
        return {a.name: a.paper for a in axes.optional_axes()}
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# --------------------------------------------------------------------------
# runs and file names
# --------------------------------------------------------------------------
def format_value(x) -> str:
    """Text of a sweep value in a run name: shortest round-trip repr, ``inf``."""
    x = float(x)
    return "inf" if math.isinf(x) else repr(x)


def parse_value(text: str) -> float:
    return float(text)


def coordinate(axis: str, value, length: float) -> float:
    """Value of a run's axis as a coordinate of the merged files (:meth:`axes.Axis.coordinate`):
    the paper's settings as numbers with the same meaning (rolloff null = the system size L,
    cutoff null = 0, i.e. no short wavelength removed, hardness null = inf, elastic)."""
    return axes.axis(axis).coordinate(value, length)


def axis_value(axis: str, coordinate_value: float, length: float):
    """The inverse of :func:`coordinate`: the run's value of an optional axis (``None`` for the
    paper's setting: rolloff = L, cutoff = 0, hardness = inf), else the number."""
    return axes.axis(axis).value_of(coordinate_value, length)


def combinations(study) -> list[dict]:
    """One dict per point of the sweep's axes (:data:`axes.AXES`) in sweep order (the
    registry's order, the last axis fastest); an axis a surface kind does not sweep (a flat
    surface's body exponent) takes its paper value. *study*: a
    :class:`~roughcontact.study.config.settings.StudySettings` (or a resolved configuration)."""
    study = StudySettings.of(study)
    out = []
    for hurst in study.hurst:
        for radius in study.radius:
            kind = kind_of(radius)
            rest = [a for a in axes.AXES.values() if a.name not in ("hurst", "radius")]
            values = [getattr(study, a.name) if kind in a.kinds else [a.paper] for a in rest]
            for point in itertools.product(*values):
                combo = {"hurst": hurst, "radius": radius, **{a.name: v for a, v in zip(rest, point)}}
                out.append({name: combo[name] for name in axes.AXES} | {"kind": kind})
    return out


def runs(study) -> list[dict]:
    """One dict per run: the axes of :func:`combinations`, ``seed`` and ``kind``."""
    study = StudySettings.of(study)
    return [{**combo, "seed": seed} for combo in combinations(study) for seed in study.seeds]


#: the axes every run name carries, in the name's order (the others only off the paper's setting)
_NAMED = tuple(a for a in ("hurst", "radius", "h_rms") if a in axes.AXES)


def combo_name(run: dict) -> str:
    """Name of a run's (H, R, h_rms, ...) directory: ``H0.7_R0.5_h0.009``, plus a tag
    for every optional axis off its paper setting (``_m4``, ``_rolloff0.25``, ...)."""
    name = "_".join(f"{axes.axis(a).tag}{format_value(run[a])}" for a in _NAMED)
    for axis in axes.optional_axes():
        if run.get(axis.name, axis.paper) != axis.paper:
            name += f"_{axis.tag}{format_value(run[axis.name])}"
    return name


@functools.lru_cache(maxsize=4)
def _combo_pattern(registered: tuple) -> re.Pattern:
    """The regular expression of :func:`combo_name` for the *registered* axes."""
    return re.compile("_".join(rf"{axes.axis(a).tag}(?P<{a}>[^_/]+?)" for a in _NAMED)
                      + "".join(rf"(?:_{a.tag}(?P<{a.name}>[^_/]+?))?" for a in axes.optional_axes()) + "$")


def parse_combo(name: str) -> dict:
    """The axes of a run directory name (:func:`combo_name`); ``ValueError`` if it is not one."""
    match = _combo_pattern(tuple(axes.AXES)).match(name)
    if not match:
        raise ValueError(f"{name!r} is not a run name like H0.7_R0.5_h0.009[_m4][_rolloff0.25]...")
    out = {axis: parse_value(match.group(axis)) for axis in _NAMED}
    for axis in axes.optional_axes():
        text = match.group(axis.name)
        out[axis.name] = axis.paper if text is None else parse_value(text)
    return out


def normal_representative(study, run: dict) -> bool:
    """Whether *run* (a dict of :func:`runs` or :func:`combinations`) is the one of its normal
    problem that the normal merged files hold: at the first of the study's values of every axis
    that does not change the normal problem (:attr:`~roughcontact.study.config.axes.Axis.normal`
    ``False``; its paper value for a kind that does not sweep it). Runs differing only in such
    axes have the same normal load path."""
    study = StudySettings.of(study)
    for spec in axes.AXES.values():
        if spec.normal:
            continue
        first = getattr(study, spec.name)[0] if run["kind"] in spec.kinds and getattr(study, spec.name) else spec.paper
        if run.get(spec.name, spec.paper) != first:
            return False
    return True


def sphere_names(study, *, adhesive: bool | None = None) -> list[str]:
    """:func:`combo_name` of every sphere combination of the normal problem of the study
    (:func:`normal_representative`, named without the tangential axes), in sweep order;
    *adhesive*: only those with (``True``) or without (``False``) a work of adhesion."""
    normal = axes.names(normal=True)
    return [combo_name({a: c[a] for a in normal}) for c in combinations(study)
            if c["kind"] == "sphere" and normal_representative(study, c)
            and (adhesive is None or (c.get("work_of_adhesion", 0.0) > 0) == adhesive)]


def run_path(run: dict, pattern: str) -> str:
    """Path of one run (a dict of :func:`runs`) after *pattern*, a format string with the
    fields ``{combo}`` (:func:`combo_name`) and ``{seed}`` (the workflow owns the patterns)."""
    return pattern.format(combo=combo_name(run), seed=int(run["seed"]))


#: what the fields of a run path pattern match (:func:`parse_run_path`)
_PATH_FIELDS = {"combo": r"(?P<combo>[^/]+)", "seed": r"(?P<seed>\d+)"}


def parse_run_path(path: str, pattern: str) -> dict:
    """The axes and seed of a path made by :func:`run_path` with *pattern* (its inverse);
    *path* may carry a leading directory (an absolute path, a ``--directory``)."""
    regex = "".join(re.escape(literal) + (_PATH_FIELDS[field] if field else "")
                    for literal, field, _, _ in string.Formatter().parse(pattern))
    match = re.search(f"(?:^|/){regex}$", str(path).replace("\\", "/"))
    if not match:
        raise ValueError(f"{path!r} is not a run file path like {pattern}")
    return {**parse_combo(match.group("combo")), "seed": int(match.group("seed"))}


def run_paths(study, pattern: str) -> list[str]:
    """:func:`run_path` of every run of the study, in sweep order."""
    return [run_path(r, pattern) for r in runs(study)]


#: peak bytes per grid cell of an indent job's load path (measured, see :func:`indent_resources`)
INDENT_BYTES_PER_CELL = 100
#: seconds of one load (its solve and its punch stiffness) on 513² on one core, and the power of
#: ``n/513`` by which it grows (measured, see :func:`indent_resources`)
INDENT_SECONDS_PER_LOAD = 0.136
INDENT_SECONDS_POWER = 2.4
#: declared runtime over the estimate: a machine twice as slow on a busy day, with room to spare
INDENT_RUNTIME_MARGIN = 3.0


def indent_seconds(n: int, loads: int) -> float:
    """Estimated seconds of one indent run of *loads* loads on an ``n × n`` grid on one core:
    :data:`INDENT_SECONDS_PER_LOAD` ``· (n/513)^``:data:`INDENT_SECONDS_POWER` per load.

    Fitted to one seed of the default sphere's 27 loads (``benchmarks/large_grid.py``, the
    preconditioned solver, 2026-11-29, a loaded machine): the solves took 4.0, 14.4, 68, 328 and
    1884 s on 513², 1025², 2049², 4097² and 8193² (a power of 2.2–2.5 per doubling; the FFT's
    own ``n² log n`` is 2.2) and the punch stiffness of every state 0.43–0.66× as long again
    (`--stiffness`); the estimate is 3.7, 19, 100, 540 and 2830 s."""
    return INDENT_SECONDS_PER_LOAD * (n / 513) ** INDENT_SECONDS_POWER * loads


def indent_resources(study, runs: int = 1) -> dict:
    """Per-job requests for schedulers (SLURM): ``mem_mb`` and ``runtime`` (minutes) of one
    ``indent`` job of *runs* runs (one after another, :func:`seed_blocks`), from the grid and
    load count.

    Memory: :data:`INDENT_BYTES_PER_CELL` bytes per cell over a ~250 MB interpreter, times 1.5
    (the same for a batch: one run is alive at a time). Measured peak RSS of one seed of the
    default sphere's 27 loads (``benchmarks/large_grid.py``, 2026-11-29, the preconditioned
    solver): 0.10, 0.17, 0.43, 1.42 and 4.67 GB on 513², 1025², 2049², 4097² and 8193², that is
    70–100 bytes per cell from 2049² on (heights, lift, two pressures, the window's work arrays,
    one real kernel spectrum per precision, the table of coefficients).
    Runtime: :data:`INDENT_RUNTIME_MARGIN` times :func:`indent_seconds` of the largest load count
    of the study's surface kinds, times *runs*, at least 5 minutes (Snakemake's rules multiply
    both by the attempt).
    """
    study = StudySettings.of(study)
    n = study.grid.n
    count = max(study.forces[kind_of(r)].count for r in study.radius)
    mem = 250 + n * n * INDENT_BYTES_PER_CELL / 1e6
    seconds = INDENT_RUNTIME_MARGIN * indent_seconds(n, count) * runs
    return {"mem_mb": int(math.ceil(1.5 * mem / 100) * 100),
            "runtime": int(max(5, math.ceil(seconds / 60)))}


def indent_priority(study, combo: str, runs: int = 1) -> int:
    """Snakemake ``priority`` of an ``indent`` job of *runs* runs of the combination *combo*
    (:func:`combo_name`) on *study*'s grid: its expected cost, ``n² ln n`` times the load count of
    its surface kind times *runs*, in units of one 65² run of one load (an integer >= 1).

    Two cores run the longest jobs first (the 385² spheres, then the flat surfaces, then the
    grid error's companion on ``grid.coarse``), so that the last jobs to finish are short and
    no core idles long at the end of the run phase; no result depends on it."""
    study = StudySettings.of(study)
    n = study.grid.n
    count = study.forces[kind_of(parse_combo(combo)["radius"])].count
    return max(1, round(n * n * math.log(n) / (65 * 65 * math.log(65)) * count * runs))


@dataclasses.dataclass(frozen=True)
class SeedBlock:
    """The seeds one ``indent`` job runs for a combination (:func:`seed_blocks`).

    Attributes
    ----------
    first, last : int
        The block's range of seed values, ``first = (s // batch) batch``, ``last = first + batch - 1``.
    seeds : tuple of int
        The study's seeds in that range, ascending.
    """

    first: int
    last: int
    seeds: tuple

    @property
    def name(self) -> str:
        """``seeds0_5``: the block in rule, log and benchmark names."""
        return f"seeds{self.first}_{self.last}"


def seed_blocks(seeds, batch: int) -> list[SeedBlock]:
    """The study's *seeds* grouped for ``batch`` runs per job: the seeds ``s`` with the same
    ``s // batch`` form one block (batch 6: 0-5, 6-11, ...), in ascending order. A seed belongs to
    its block by its value, not by its place in the list, so adding a seed changes only the block
    of its value (``jobs.batch``); a sparse list gives blocks of fewer seeds."""
    if int(batch) < 1:
        raise ValueError(f"batch must be a positive number of seeds, not {batch!r}")
    batch = int(batch)
    blocks: dict[int, list[int]] = {}
    for seed in sorted(int(s) for s in seeds):
        blocks.setdefault(seed // batch, []).append(seed)
    return [SeedBlock(first=j * batch, last=j * batch + batch - 1, seeds=tuple(members))
            for j, members in sorted(blocks.items())]
