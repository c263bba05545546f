"""Which rows of a scorecard are not scored: the model does not model an axis the combination sets.

A model of the registry (:mod:`roughcontact.models.scorecard`) declares the optional sweep axes it
models (:attr:`~roughcontact.models.scorecard.Model.axes`). On a combination off the paper's
setting of an optional axis (:func:`roughcontact.study.config.axes.off_paper`) that the model does not
declare, its prediction ignores that axis: the row of the generated scorecard
(:mod:`roughcontact.study.analysis.scorecard`) and of the measured one
(:mod:`roughcontact.study.analysis.measured_scorecard`) then names those axes in the column
``not_modelled`` (``"hardness = 0.5; cutoff = 0.1"``; empty otherwise), keeps its measured
deviations, but is not scored: no ``rank`` (NaN) and every verdict column
``untested: not modelled: <axes>``, so it is neither a best model nor one that differs. Rows at
the paper's setting, or off it only in axes the model declares, are scored as before.
"""
from __future__ import annotations

import math
from typing import Mapping

import numpy as np

from ...models import scorecard as registry
from ..config import axes

__all__ = ["COLUMN", "not_modelled", "unscored", "rank"]

#: the column that names the undeclared axes off the paper's setting
COLUMN = "not_modelled"


def not_modelled(model: str | registry.Model, combination: Mapping, length: float) -> str:
    """The optional axes at which a combination is off the paper's setting and a model does not declare.

    Parameters
    ----------
    model : str or roughcontact.models.scorecard.Model
        A registered model or its name (a name that is not registered declares no axis).
    combination : Mapping
        Axis name -> merged-file coordinate (a missing optional axis is at the paper's setting,
        :func:`roughcontact.study.config.axes.off_paper`).
    length : float
        The system size ``L`` (the paper's roll-off coordinate).

    Returns
    -------
    str
        ``"name = value; ..."`` in the registry's order of the axes; ``""`` if none.
    """
    if isinstance(model, str):
        model = registry.models().get(model)
    off = axes.off_paper(combination, length)
    missing = off if model is None else model.undeclared(off)
    return "; ".join(f"{name} = {value:g}" for name, value in missing.items())


def unscored(row: dict) -> dict:
    """A scorecard row with its verdicts untested where the model does not model the combination.

    Parameters
    ----------
    row : dict
        One row of a scorecard, with its :data:`COLUMN`.

    Returns
    -------
    dict
        *row* with every verdict column (``*_verdict``) ``untested: not modelled: <axes>`` where
        :data:`COLUMN` names axes; *row* itself otherwise.
    """
    missing = row.get(COLUMN, "")
    if not missing:
        return row
    return {key: f"untested: not modelled: {missing}" if key.endswith("_verdict") else value
            for key, value in row.items()}


def rank(table, by):
    """The rank of each row by ``max_rel_dev`` among the scored rows of its group.

    Parameters
    ----------
    table : pandas.DataFrame
        A scorecard with ``max_rel_dev`` and, if any row is not scored, :data:`COLUMN`.
    by : str or list of str
        The columns whose values form a group (one combination).

    Returns
    -------
    pandas.Series
        Float ranks (1: the best, ties the lowest rank) among the rows whose :data:`COLUMN` is
        empty; NaN for the others.
    """
    scored = (table[COLUMN].fillna("") == "").to_numpy() if COLUMN in table else np.ones(len(table), dtype=bool)
    keys = [table[b] for b in ([by] if isinstance(by, str) else by)]
    ranks = table["max_rel_dev"].where(scored).groupby(keys, dropna=False).rank(method="min")
    return ranks.where(scored, math.nan).astype(float)
