"""The ensemble-mean histograms (roughcontact.study.analysis.histograms): runs whose bins differ put
on common edges in normalized units, against Hertz's pressure density in closed form.

Hertz (K. L. Johnson, Contact Mechanics, 1985, §3.9): under ``p = p₀ √(1 − r²/a²)`` the share of
the contact area with ``r² < u a²`` is ``u`` and the mean pressure ``p̄ = 2p₀/3``, so ``x = p/p̄`` has
the cumulative ``(2x/3)²`` on ``0 ≤ x ≤ 3/2``, the density ``8x/9``, for every ``p₀``.
"""
from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from roughcontact.study.analysis.histograms import mean_histograms, rebin
from roughcontact.study.quantities.histograms import histogram

#: cells of each run: the area quantiles u = (k + 1/2)/CELLS of Hertz's contact
CELLS, BINS, FORCE, H_RMS = 40000, 40, 1e-2, 9e-3
#: Hertz's peak pressure of each "seed" (runs of different spheres: their edges differ)
P0 = (0.1, 0.25, 0.4)


def _hertz_runs() -> xr.Dataset:
    """A merged group of three runs at one load, each Hertz's pressure with its own p₀ sampled at
    the contact's area quantiles (force = Σ p × cell area = FORCE), and a gap uniform on (0, 4 h_rms)."""
    u = (np.arange(CELLS) + 0.5) / CELLS
    counts, edges, areas, gap_counts, gap_edges = [], [], [], [], []
    for p0 in P0:
        pressure = p0 * np.sqrt(1 - u)
        h = histogram(pressure, BINS)
        cell = FORCE / pressure.sum()
        counts.append(h.counts), edges.append(h.edges), areas.append(CELLS * cell)
        g = histogram(4 * H_RMS * u * (p0 / P0[-1]), BINS)
        gap_counts.append(g.counts), gap_edges.append(g.edges)
    seed_load = ("seed", "histogram_load")
    return xr.Dataset(
        {"pressure_histogram": ((*seed_load, "pressure_bin"), np.array(counts)[:, None]),
         "pressure_bin_edges": ((*seed_load, "pressure_edge"), np.array(edges)[:, None]),
         "gap_histogram": ((*seed_load, "gap_bin"), np.array(gap_counts)[:, None]),
         "gap_bin_edges": ((*seed_load, "gap_edge"), np.array(gap_edges)[:, None]),
         "contact_area": (("seed", "force"), np.array(areas)[:, None]),
         "histogram_force": (("histogram_load",), [FORCE])},
        coords={"seed": np.arange(len(P0)), "histogram_load": [0], "force": [FORCE], "h_rms": H_RMS})


@pytest.fixture(scope="module")
def mean():
    return mean_histograms(_hertz_runs())


def test_the_runs_bins_differ():
    """The test's premise: the runs' last edges (their largest pressures) differ by 4x."""
    top = _hertz_runs()["pressure_bin_edges"].isel(pressure_edge=-1).values.ravel()
    assert top.max() / top.min() == pytest.approx(4.0, rel=1e-3)


def test_the_mean_pressure_density_is_hertz_s(mean):
    """The cumulative of the ensemble-mean density of p/p̄ at the common edges against (2x/3)²: to
    2e-3 (each run's histogram is exact to a count in 40 000 per bin; moving it to the common edges
    with a linear cumulative within a bin errs by at most f′ w²/8 ≈ 1e-4 with f′ = 8/9, w = 0.0375)."""
    density = mean["pressure_density_mean"].isel(histogram_load=0).values
    edges = mean["pressure_ratio_edges"].isel(histogram_load=0).values
    cumulative = np.concatenate([[0.0], np.cumsum(density * np.diff(edges))])
    assert np.max(np.abs(cumulative - np.minimum((2 * edges / 3) ** 2, 1.0))) < 2e-3


def test_the_common_edges_end_at_hertz_s_largest_ratio(mean):
    """The common edges run to the largest p/p̄ of any run, Hertz's 3/2 (to 1e-3: the largest
    sampled quantile and the sampled mean)."""
    assert mean["pressure_ratio_edges"].values[0, -1] == pytest.approx(1.5, rel=1e-3)


def test_the_seeds_agree_in_normalized_units(mean):
    """Normalized, the three runs are one distribution: their standard error over the seeds is
    below 2 % of the mean density in every bin above x = 0.1."""
    m = mean["pressure_density_mean"].isel(histogram_load=0).values
    sem = mean["pressure_density_sem"].isel(histogram_load=0).values
    centres = mean["pressure_ratio_centre"].isel(histogram_load=0).values
    assert np.max((sem / m)[centres > 0.1]) < 0.02


def test_the_gap_is_in_units_of_h_rms(mean):
    """The gap's common edges end at the largest g/h_rms of any run: 4 (to 1e-3)."""
    assert mean["gap_ratio_edges"].values[0, -1] == pytest.approx(4.0, rel=1e-3)


def test_the_mean_densities_are_on_named_dimensions(mean):
    assert mean["pressure_density_mean"].dims == ("histogram_load", "pressure_ratio")


def test_rebin_keeps_the_counts():
    """Counts 1..5 in bins of width 1 moved to 3 bins from 0 to 4.5: the total is kept, values
    beyond the last new edge in the last bin; [0, 1.5) holds 1 + 2/2 = 2 (linear within a bin)."""
    out = rebin(np.arange(1, 6), np.arange(6.0), np.linspace(0.0, 4.5, 4))
    assert (out.sum(), out[0]) == pytest.approx((15.0, 2.0))


def test_rebin_of_an_all_zero_histogram_is_in_the_first_bin():
    assert rebin([7, 0, 0], np.zeros(4), np.linspace(0.0, 1.0, 3)).tolist() == [7.0, 0.0]
