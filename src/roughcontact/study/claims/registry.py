"""The claim registry: what a claim is (:class:`Claim`), what it may read (:class:`ClaimInputs`),
the row every claim writes (:func:`row`) and the paper's setting its verdicts need."""
from __future__ import annotations

import dataclasses
import math
from typing import Callable

import numpy as np

from ..axes import AXES, optional_axes

__all__ = ["Claim", "ClaimInputs", "CLAIMS", "register", "row", "AXIS_COLUMNS", "EFFECT_CLAIM", "paper_values",
           "describe", "off_theory", "is_paper_setting", "flat_zeta_rows"]


@dataclasses.dataclass(frozen=True)
class ClaimInputs:
    """What the claims are estimated from (the ``claims`` rule's inputs).

    Attributes
    ----------
    cross : pandas.DataFrame
        ``crossover.csv``: per sphere combination, eq. 16 fitted with free prefactors, the slopes
        and their intervals (:mod:`roughcontact.study.verdicts`); empty without spheres.
    replicates : xarray.Dataset
        Bootstrap replicates of the crossover force (``crossover.nc``).
    zeta : pandas.DataFrame
        ``zeta.csv``: ζ(H) of eq. 11 with its interval.
    study : roughcontact.study.study_settings.StudySettings
        The study's settings (grid, seeds, sweep, fit windows).
    groups : dict or None
        The merged runs, one Dataset per surface kind (``stiffness.nc``).
    exponents : pandas.DataFrame or None
        The local exponents (``exponents.csv``).
    zeta_replicates : xarray.DataArray or None
        Bootstrap replicates of ζ(H) (``zeta.nc``).
    adhesion : pandas.DataFrame or None
        The pull-off table of the adhesive runs (``adhesion/pull_off.csv``,
        :mod:`roughcontact.study.adhesion.merge`); ``None`` without adhesive runs.
    stickiness : pandas.DataFrame or None
        The stickiness table (``stickiness/stickiness.csv``, :mod:`roughcontact.study.stickiness.merge`);
        ``None`` without the config's ``stickiness`` section.
    """

    cross: object
    replicates: object
    zeta: object
    study: object
    groups: dict | None = None
    exponents: object = None
    zeta_replicates: object = None
    adhesion: object = None
    stickiness: object = None


@dataclasses.dataclass(frozen=True)
class Claim:
    """One quantitative claim.

    Attributes
    ----------
    letter : str
        Its label in the claims table (``a`` ... ``m``, ``c'``); rows are ordered by it.
    statement : str
        The claim in words (each row states it for its combination).
    needs : tuple of str
        The fields of :class:`ClaimInputs` it reads besides ``study``; without one of them
        (``None``) the claim has no rows.
    rows : callable
        ``rows(inputs) -> list of dict``: one :func:`row` per combination it is tested on, each
        with the measured value, its interval, the paper's value and the verdict (the rules of
        :mod:`roughcontact.study.statistics`).
    """

    letter: str
    statement: str
    rows: Callable
    needs: tuple = ()


#: every registered claim, in registration order (the table orders rows by letter)
CLAIMS: dict[str, Claim] = {}


def register(claim: Claim) -> Claim:
    """Add *claim* to :data:`CLAIMS` (one object per letter)."""
    if claim.letter in CLAIMS:
        raise ValueError(f"claim {claim.letter!r} is registered already")
    CLAIMS[claim.letter] = claim
    return claim


def __getattr__(name: str):
    """``AXIS_COLUMNS``: the sweep axes (:data:`roughcontact.study.axes.AXES`), the columns naming the
    combination a row rests on; ``EFFECT_CLAIM``: the claim that tests each optional axis off the
    paper's elastic, purely self-affine setting. Both read the axis registry when asked."""
    if name == "AXIS_COLUMNS":
        return tuple(AXES)
    if name == "EFFECT_CLAIM":
        return {a.name: a.claim for a in optional_axes() if a.claim}
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def row(claim, statement, measured, low, high, paper, verdict_text, *, sweep="", loads="", note="", **where) -> dict:
    """One row of the claims table; *verdict_text* is ``"verdict: reason"``; *where* the
    combination's axes (missing ones NaN)."""
    return {"claim": claim, "statement": statement, **{k: where.get(k, math.nan) for k in AXES},
            "measured": measured, "ci_low": low, "ci_high": high, "paper_value": paper,
            "verdict": verdict_text.split(":")[0], "reason": verdict_text.partition(": ")[2],
            "sweep": sweep, "loads": loads, "note": note}


def paper_values(length: float) -> dict:
    """The paper's setting of the optional axes as merged-file coordinates."""
    return {a.name: a.coordinate(a.paper, length) for a in optional_axes()}


def describe(r, length: float, n: int, seeds: int) -> str:
    """The sweep a row rests on: the combination (optional axes off the paper's setting), seeds, grid."""
    text = f"sphere H = {r['hurst']:g}, R = {r['radius']:g}, h_rms = {r['h_rms']:g}"
    for axis, value in paper_values(length).items():
        if axis in r and r[axis] != value:
            text += f", {axis} = {r[axis]:g}"
    return f"{text}, {seeds} seeds, n = {n}"


def off_theory(r, length: float) -> str:
    """Why eqs. 11–17 do not apply to the combination *r* ('' where they do): an optional axis off
    the paper's setting whose claim tests it (a cutoff, a roll-off or a hardness)."""
    paper = paper_values(length)
    claims = {a.name: a.claim for a in optional_axes() if a.claim}
    off = [f"{axis} = {r[axis]:g} (claim {claim} tests it)" for axis, claim in claims.items()
           if axis in r and r[axis] != paper[axis]]
    if not off:
        return ""
    return "untested: eqs. 11-17 are for an elastic, purely self-affine surface; here " + ", ".join(off)


def is_paper_setting(frame, length):
    """Rows of *frame* at the paper's setting of the optional axes (or all rows if it has no such columns)."""
    keep = np.ones(len(frame), dtype=bool)
    for axis, value in paper_values(length).items():
        if axis in frame:
            keep &= frame[axis].to_numpy(float) == value
    return frame[keep]


def flat_zeta_rows(zeta_df):
    """Rows of zeta.csv fitted on flat runs at the paper's setting (not on a substituted roll-off,
    cutoff or hardness: :func:`roughcontact.study.zeta.fit.paper_setting` says so in the source)."""
    if not len(zeta_df):
        return zeta_df
    return zeta_df[zeta_df["source"].astype(str) == "flat"]
