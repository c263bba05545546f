"""The ensemble-mean pressure and gap histograms (``fields.histograms``) in normalized units.

Each run keeps its histograms in equal bins from 0 to the largest value of its load
(:mod:`roughcontact.study.quantities.histograms`): the edges differ between runs, so the counts
cannot be averaged as they are. :func:`mean_histograms` puts every run on common edges in
normalized units, where runs of one combination and load are alike:

* the pressure over the contact cells in units of the run's **mean contact pressure**
  ``p̄ = F/A`` (``histogram_force`` over the run's ``contact_area`` at that load);
* the gap over the cells out of contact in units of the combination's **h_rms** (its axis).

A run's counts are moved to the common edges with its cumulative count linear within each of its
own bins (the values spread evenly over a bin: :func:`rebin`); the common edges run in as many equal
bins as a run has (``fields.histograms.bins``) from 0 to the largest normalized value of any run at
that load. Each run's counts become a probability density (over its counts and the common bin width)
and the ensemble's is the mean over the seeds, with its standard error.

Closed form that tests it (``tests/test_histograms_mean.py``): under Hertz's pressure
``p = p₀ √(1 − r²/a²)`` the mean contact pressure is ``p̄ = 2p₀/3``, so ``x = p/p̄`` has the density
``8x/9`` on ``0 ≤ x ≤ 3/2`` (the share below ``x`` is ``(2x/3)²``; K. L. Johnson, Contact Mechanics,
1985, §3.9), whatever the force and radius of each run.
"""
from __future__ import annotations

import numpy as np

__all__ = ["rebin", "mean_histograms", "KINDS"]

#: per histogram: (its variable prefix in stiffness.nc, the normalized value's name, its long name)
KINDS = {"pressure": ("pressure", "pressure_ratio", "pressure over the mean contact pressure p/(F/A)"),
         "gap": ("gap", "gap_ratio", "gap over h_rms out of contact")}


def rebin(counts, edges, new_edges) -> np.ndarray:
    """The *counts* of bins *edges* (increasing, ``len(counts) + 1``) moved to *new_edges*, with the
    cumulative count linear within each old bin; counts beyond the last new edge go to the last new
    bin, so the total is kept. Edges all 0 (every value 0, :func:`~roughcontact.study.quantities.
    histograms.histogram`) put every count in the first new bin."""
    counts = np.asarray(counts, dtype=float)
    edges = np.asarray(edges, dtype=float)
    new_edges = np.asarray(new_edges, dtype=float)
    out = np.zeros(len(new_edges) - 1)
    total = counts.sum()
    if not np.isfinite(edges).all() or not edges[-1] > edges[0]:
        out[0] = total
        return out
    cumulative = np.concatenate([[0.0], np.cumsum(counts)])
    out = np.diff(np.interp(new_edges, edges, cumulative, left=0.0, right=total))
    out[-1] += total - out.sum()
    return out


def _density(counts, edges, scale, new_edges) -> np.ndarray:
    """One run's probability density on *new_edges* of its values over *scale* (NaN without a
    count or a positive scale)."""
    total = float(np.sum(counts))
    if not (scale > 0 and total > 0):
        return np.full(len(new_edges) - 1, np.nan)
    return rebin(counts, np.asarray(edges) / scale, new_edges) / (total * np.diff(new_edges))


def mean_histograms(ds, bins: int | None = None):
    """The ensemble-mean histograms of a merged group *ds* (``stiffness.nc``'s ``sphere`` or ``flat``,
    with ``pressure_histogram`` etc.): an :class:`xarray.Dataset` over every dimension of *ds* but
    ``seed`` and the bins, with for ``kind`` in ``pressure``, ``gap``:

    * ``<kind>_density_mean`` ``(..., histogram_load, <ratio>)``: the mean over the seeds of each
      run's probability density of the normalized value (module docstring; 1/unit of the ratio);
    * ``<kind>_density_sem``: its standard error over the seeds (NaN with one seed);
    * ``<kind>_density`` ``(..., seed, histogram_load, <ratio>)``: each run's;
    * ``<ratio>_edges`` ``(histogram_load, <ratio>_edge)``: the common edges, ``<ratio>`` the bins'
      centres (``pressure_ratio``: ``p/p̄``; ``gap_ratio``: ``g/h_rms``).

    *bins*: the common bins (default: as many as a run's)."""
    import xarray as xr

    loads = ds["histogram_load"].values
    area = ds["contact_area"].isel(force=xr.DataArray(loads, dims="histogram_load"))
    scales = {"pressure": ds["histogram_force"] / area,
              "gap": xr.ones_like(area) * ds["h_rms"]}
    out = xr.Dataset(coords={"histogram_load": loads, "histogram_force": ds["histogram_force"]})
    for kind, (prefix, ratio, long_name) in KINDS.items():
        counts, edges = ds[f"{prefix}_histogram"], ds[f"{prefix}_bin_edges"]
        n_bins = int(bins or counts.sizes[f"{prefix}_bin"])
        scale = scales[kind].broadcast_like(edges.isel({f"{prefix}_edge": -1}))
        with np.errstate(divide="ignore", invalid="ignore"):
            top = (edges.isel({f"{prefix}_edge": -1}) / scale).where(scale > 0)
        other = [d for d in top.dims if d != "histogram_load"]
        top = top.max(other).fillna(1.0).values
        common = np.stack([np.linspace(0.0, t if t > 0 else 1.0, n_bins + 1) for t in top])   # (load, edge)
        common_da = xr.DataArray(common, dims=("histogram_load", f"{ratio}_edge"))
        density = xr.apply_ufunc(_density, counts, edges, scale, common_da,
                                 input_core_dims=[[f"{prefix}_bin"], [f"{prefix}_edge"], [], [f"{ratio}_edge"]],
                                 output_core_dims=[[ratio]], vectorize=True)
        centres = 0.5 * (common[:, 1:] + common[:, :-1])
        density = density.assign_coords({f"{ratio}_centre": (("histogram_load", ratio), centres)})
        attrs = {"long_name": f"probability density of the {long_name}", "units": "1"}
        seeds = density.count("seed")
        out[f"{kind}_density"] = density.assign_attrs(attrs)
        out[f"{kind}_density_mean"] = density.mean("seed").assign_attrs(
            {**attrs, "long_name": "ensemble mean " + attrs["long_name"]})
        out[f"{kind}_density_sem"] = (density.std("seed", ddof=1) / np.sqrt(seeds)).where(seeds > 1).assign_attrs(
            {**attrs, "long_name": "standard error over the seeds of the " + attrs["long_name"]})
        out[f"{ratio}_edges"] = common_da.assign_attrs({"long_name": f"common bin edges of the {long_name}",
                                                        "units": "1"})
    return out
