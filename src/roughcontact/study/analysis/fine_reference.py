"""The converged reference of the small loads: the study's sphere runs against the same surfaces on
``grid.fine``, where the fractal branch lives.

With ``grid.fine: N`` the study presses the surfaces of the ``N`` grid seen on its own ``n``
(``grid.realization_of``), and its companion (:func:`roughcontact.study.config.companions.fine_config`)
presses them on ``N`` at the loads up to ``grid.fine_to`` (the windowed solver's cost follows the
contact, small there). Per sphere combination and load of the companion (``fine_reference.csv``):

* ``study_grid_error`` ``g = k̄_n/k̄_N − 1`` with its paired bootstrap interval, and
  ``fine_error_estimate``, Richardson's estimate of the fine grid's own error from it
  (:func:`roughcontact.study.analysis.grid_error.estimate`, ``p = 1``, ``F_s = 0.75``): the columns of
  :func:`~roughcontact.study.analysis.grid_error.grid_error` with the fine grid as the finer one;
* ``grid_error_estimate`` — the study grid's error against the continuum, bounded as the far end of
  the interval of ``g`` plus the fine grid's own estimate: what the model scorecard widens its band
  by at these loads (:func:`combined_grid_error`; the coarse companion's estimate elsewhere);
* with ``grid.coarse`` too: ``richardson_stiffness`` and ``richardson_order`` from the three grids
  ``n_c < n < N`` where the sequence is monotone and converging
  (:func:`~roughcontact.study.analysis.grid_error.richardson`); ``reference_stiffness`` is it, else
  ``k̄_N``;
* ``largest_patch_share`` — the mean over seeds of the largest contact patch's share of the contact
  cells on ``N`` (:func:`roughcontact.bem.contact_patches`), and ``single_asperity`` on the loads
  from the smallest one up to the first where it falls below :data:`SINGLE_ASPERITY_SHARE`: the
  smallest loads, where one asperity carries the load and the sphere is Hertz-like again on that
  asperity's radius (which the grid sets), are measured, not guessed from a cell count, and are not
  the fractal branch (a contact that has merged into one patch at high loads is not flagged).

Forces ``F/(E* L²)``, stiffnesses ``k/(E* L)``.
"""
from __future__ import annotations

import numpy as np

from ..runs import naming as runs
from .grid_error import grid_error, richardson

__all__ = ["SINGLE_ASPERITY_SHARE", "fine_reference", "combined_grid_error"]

#: a load is in the single-asperity regime when the largest contact patch holds at least this share
#: of the contact cells on the fine grid (mean over seeds)
SINGLE_ASPERITY_SHARE = 0.8


#: the columns of fine_reference.csv after the sphere axes (the header of a table without a row)
FINE_REFERENCE_COLUMNS = ("force_normalized", "contact_cells", "study_grid_error", "study_grid_error_ci_low",
                          "study_grid_error_ci_high", "fine_error_estimate", "grid_error_estimate", "stiffness",
                          "fine_stiffness", "largest_patch_share", "single_asperity", "reference_stiffness",
                          "grid_n", "fine_grid_n")


def fine_reference(study_ds, fine_ds, coarse_ds=None, *, n: int, n_fine: int, n_coarse: int | None = None,
                   min_cells: int, bootstrap: int, confidence: float):
    """The table of the module docstring: *study_ds* the study's merged sphere runs (``n``), *fine_ds*
    its fine companion's (``n_fine``, the first loads of the same path), *coarse_ds* its coarse
    companion's (``n_coarse``) or ``None``."""
    loads = fine_ds.sizes["force"]
    head = study_ds.isel(force=slice(0, loads))
    if not np.allclose(head["force"].values, fine_ds["force"].values, rtol=1e-12, atol=0):
        raise ValueError("the fine companion's loads are not the first loads of the study's path")
    fine_ds = fine_ds.assign_coords(force=head["force"].values)   # the same loads, to the last bit
    table = grid_error(head, fine_ds, min_cells=min_cells, bootstrap=bootstrap, confidence=confidence,
                       ratio=n_fine / n)
    table = table.rename(columns={
        "grid_error": "study_grid_error", "grid_error_ci_low": "study_grid_error_ci_low",
        "grid_error_ci_high": "study_grid_error_ci_high", "grid_error_estimate": "fine_error_estimate",
        "contact_cells_coarse": "contact_cells", "grid_resolved": "fine_resolved"})
    table["grid_error_estimate"] = (np.maximum(table["study_grid_error_ci_low"].abs(),
                                               table["study_grid_error_ci_high"].abs())
                                    + table["fine_error_estimate"])
    axes = [c for c in table.columns if c in study_ds.dims and c not in ("seed", "force")]
    seeds = sorted(set(study_ds["seed"].values.tolist()) & set(fine_ds["seed"].values.tolist()))
    fine_forces = fine_ds["force_normalized"].values
    k_study, k_fine, k_coarse, share = [], [], [], []
    for _, r in table.iterrows():
        pick = {a: r[a] for a in axes}
        at = {"force": int(np.argmin(np.abs(fine_forces - r["force_normalized"])))}
        k_study.append(float(head["stiffness"].sel(pick).sel(seed=seeds).isel(at).mean()))
        fine = fine_ds.sel(pick).sel(seed=seeds).isel(at)
        k_fine.append(float(fine["stiffness"].mean()))
        cells = fine["contact_cells"].values.astype(float)
        with np.errstate(divide="ignore", invalid="ignore"):
            share.append(float(np.nanmean(np.where(cells > 0, fine["largest_patch_cells"].values / cells, np.nan))))
        if coarse_ds is not None:
            k_coarse.append(float(coarse_ds["stiffness"].sel(pick).sel(seed=seeds).isel(at).mean()))
    table["stiffness"], table["fine_stiffness"] = k_study, k_fine
    table["largest_patch_share"] = share
    table["single_asperity"] = _leading(table, axes)
    table["reference_stiffness"] = table["fine_stiffness"]
    if coarse_ds is not None and n_coarse is not None:
        table["coarse_stiffness"] = k_coarse
        extrapolated, order = richardson(table["coarse_stiffness"], table["stiffness"], table["fine_stiffness"],
                                         ratio=n_fine / n)
        table["richardson_stiffness"], table["richardson_order"] = extrapolated, order
        table["reference_stiffness"] = np.where(np.isfinite(extrapolated), extrapolated, table["fine_stiffness"])
    table["grid_n"], table["fine_grid_n"] = n, n_fine
    return table


def _leading(table, axes) -> np.ndarray:
    """``single_asperity`` per row: the loads of a combination from its smallest one up to the first
    whose largest patch holds less than :data:`SINGLE_ASPERITY_SHARE` (a contact that has merged into
    one large patch at higher loads is the Hertz branch, not a single asperity)."""
    flag = np.zeros(len(table), dtype=bool)
    for _, rows in table.groupby(axes, sort=False, dropna=False) if axes else [(None, table)]:
        for index in rows.sort_values("force_normalized").index:
            if not table.at[index, "largest_patch_share"] >= SINGLE_ASPERITY_SHARE:
                break
            flag[table.index.get_loc(index)] = True
    return flag


def combined_grid_error(coarse, fine):
    """The grid error table the model scorecard reads: the coarse companion's rows
    (:func:`~roughcontact.study.analysis.grid_error.grid_error`), each replaced by the fine reference's
    ``grid_error_estimate`` at the loads the fine companion pressed; either may be ``None``."""
    import pandas as pd

    if fine is None or not len(fine):
        return coarse
    rows = fine.rename(columns={"study_grid_error": "grid_error"})
    if coarse is None or not len(coarse):
        return rows
    key = [c for c in (*runs.AXES["sphere"], "force_normalized") if c in coarse and c in rows]
    merged = coarse.merge(rows[key + ["grid_error_estimate", "grid_error"]], on=key, how="outer",
                          suffixes=("", "_fine"))
    for column in ("grid_error_estimate", "grid_error"):
        merged[column] = np.where(np.isfinite(merged[f"{column}_fine"]), merged[f"{column}_fine"], merged[column])
    return pd.DataFrame(merged.drop(columns=["grid_error_estimate_fine", "grid_error_fine"]))
