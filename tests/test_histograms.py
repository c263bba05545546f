"""Pressure and gap histograms at chosen loads (``fields.histograms``,
:mod:`roughcontact.study.quantities.histograms`) against Hertz's closed forms, kept in the run file
and the merged file over named dimensions, and the configuration's refusals of what a sweep cannot
give (a histogram at a load its path does not reach, a quantity of a run kind it lacks).

Hertz (K. L. Johnson, Contact Mechanics, 1985, §3.9): a rigid paraboloid ``z = r²/2R`` pressed by
``F`` into a half-space of modulus ``E*`` touches on a circle of radius ``a = (3FR/4E*)^(1/3)`` under
``p(r) = p₀ √(1 − r²/a²)``, ``p₀ = 2aE*/(πR)``. The share of the contact area with ``p < x`` is the
annulus ``a² (1 − (x/p₀)²) < r² < a²`` over ``πa²``: ``(x/p₀)²``. Out of contact the gap
``g(r) = r²/2R − a²/R + u(r)``, ``u(r) = p₀/(2aE*) [(2a² − r²) asin(a/r) + a √(r² − a²)]``, grows
with ``r``: the area with ``0 < g < x`` is ``π (r(x)² − a²)``, ``g(r(x)) = x``, while the circle
``r(x)`` stays on the grid (``r(x) ≤ L/2``).
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from roughcontact import bem, errors
from roughcontact.study import quantities
from roughcontact.study.config import resolve_config
from roughcontact.study.config.companions import coarse_config
from roughcontact.study.config.units import study_units
from roughcontact.study.files import io
from roughcontact.study.quantities.histograms import histogram, load_histograms
from roughcontact.study.runs import indent, jobs, naming

LENGTH, RADIUS, E_STAR = 1.0, 0.5, 1.0
#: a = 0.1 L: 12.9 cells across the contact's radius on 129², 25.6 on 256²
FORCE = 4 * E_STAR * 0.1**3 / (3 * RADIUS)
A = (3 * FORCE * RADIUS / (4 * E_STAR)) ** (1 / 3)
P0 = 2 * A * E_STAR / (math.pi * RADIUS)
BINS = 40


def _hertz_gap(r: float) -> float:
    u = P0 / (2 * A * E_STAR) * ((2 * A * A - r * r) * math.asin(A / r) + A * math.sqrt(r * r - A * A))
    return r * r / (2 * RADIUS) - A * A / RADIUS + u


@pytest.fixture(scope="module", params=[129, 256], ids=["odd", "even"])
def hertz(request):
    """The histograms of Hertz's contact on an odd and an even grid, and the grid's cell side."""
    n = request.param
    x = (np.arange(n) - n // 2) * (LENGTH / n)
    r2 = x[:, None] ** 2 + x[None, :] ** 2
    state = bem.solve(r2 / (2 * RADIUS), force=FORCE, length=LENGTH, e_star=E_STAR)
    load = quantities.Load(settings=None, index=0, total=1, where="load step 1/1 (", cell=(LENGTH / n) ** 2)
    return load_histograms(state, load, BINS), LENGTH / n, state


def test_the_pressure_is_distributed_as_hertz(hertz):
    """The share of the contact cells below each edge against ``(x/p₀)²``, as the largest gap
    between the two cumulative distributions (Kolmogorov's distance). The contact's edge is on the
    grid to a cell Δ: a ring of 2Δ/a of its area may sit on either side of it, where the pressure
    is small (tolerance 2Δ/a = 0.16 on 129², 0.08 on 256²; measured 0.042 and 0.019, 2026-11-29);
    a uniform distribution of p would be 0.25 away."""
    histograms, cell, _ = hertz
    pressure = histograms["pressure"]
    below = np.concatenate([[0], np.cumsum(pressure.counts)]) / pressure.counts.sum()
    hertz_share = np.minimum((pressure.edges / P0) ** 2, 1.0)
    assert np.max(np.abs(below - hertz_share)) < 2 * cell / A


def test_the_largest_pressure_is_hertz_p0(hertz):
    """The last edge is the largest cell pressure, the centre's p₀ to the solver's discretisation
    (tolerance 0.5 %; measured 0.05 % on 129², 0.005 % on 256², 2026-11-29)."""
    histograms, _, _ = hertz
    assert histograms["pressure"].edges[-1] == pytest.approx(P0, rel=5e-3)


def test_the_gap_is_distributed_as_hertz(hertz):
    """The area of the free cells with a gap below each edge against ``π (r(x)² − a²)`` for the
    edges whose circle ``r(x)`` stays on the grid. Counting cells by their centres misses or adds
    at most the cells the two circles cut, ≈ 2π(r + a)Δ, so the relative error is below
    2Δ/(r(x) − a) at each edge (measured at most 0.12 of it on 129², 0.09 on 256², 2026-11-29)."""
    histograms, cell, _ = hertz
    gap = histograms["gap"]
    area = np.concatenate([[0], np.cumsum(gap.counts)]) * cell**2
    on_grid = [i for i, x in enumerate(gap.edges) if 0 < x <= _hertz_gap(LENGTH / 2)]
    radii = np.array([brentq(lambda r, x=gap.edges[i]: _hertz_gap(r) - x, A * (1 + 1e-12), LENGTH) for i in on_grid])
    exact = math.pi * (radii**2 - A * A)
    error = np.abs(area[on_grid] - exact) / exact
    assert np.max(error / (2 * cell / (radii - A))) < 1.0


def test_the_counts_are_the_contact_and_the_free_cells(hertz):
    histograms, _, state = hertz
    assert (histograms["pressure"].counts.sum(), histograms["gap"].counts.sum()) == (
        int(state.contact.sum()), int((~state.contact).sum()))


def test_no_value_above_zero_counts_in_the_first_bin():
    empty = histogram(np.zeros(7), 4)
    assert (empty.counts.tolist(), empty.edges.tolist()) == ([7, 0, 0, 0], [0.0] * 5)


# --------------------------------------------------------------------------
# the run file, the merge, the configuration
# --------------------------------------------------------------------------
CONFIG = {"grid": {"n": 33, "length": 1.0, "coarse": None}, "hurst": [0.7], "radius": [0.5], "h_rms": [2e-3],
          "seeds": 1, "forces": {"sphere": {"from": 1e-5, "to": 1e-3, "count": 5}}}


def _config(**fields):
    return resolve_config({**CONFIG, "fields": fields})


@pytest.fixture(scope="module")
def kept(tmp_path_factory):
    """One run keeping the histograms of its loads nearest 1e-4 and 1e-3 (indices 2 and 4) in 12
    bins, and its largest patch's area; its file and the merged Dataset."""
    from roughcontact.study.analysis.merge import merge_runs

    cfg = _config(histograms={"at": [1e-3, 1e-4], "bins": 12}, quantities=["largest_patch_area"], patches=True)
    job = jobs.job_settings(cfg, naming.runs(cfg)[0])
    path = tmp_path_factory.mktemp("histograms") / "run.nc"
    out = indent.compute_run(job)
    indent.write_run(path, job, out)
    return job, io.read_run(path, job), merge_runs(cfg, [path])["sphere"]


def test_the_run_keeps_the_nearest_loads(kept):
    job, ds, _ = kept
    assert ds["histogram_load"].values.tolist() == [2, 4]


def test_the_run_file_counts_every_contact_cell_of_each_load(kept):
    _, ds, _ = kept
    assert ds["pressure_histogram"].sum("pressure_bin").values.tolist() == ds["contact_cells"].values[[2, 4]].tolist()


def test_the_merged_file_has_named_dimensions(kept):
    _, _, merged = kept
    assert merged["gap_histogram"].dims[-3:] == ("seed", "histogram_load", "gap_bin")


def test_the_merged_histogram_force_is_the_load_s(kept):
    _, ds, merged = kept
    assert np.allclose(merged["histogram_force"].values, ds["force"].values[[2, 4]], rtol=1e-12)


def test_the_largest_patch_area_is_its_cells_times_the_cell_area(kept):
    _, _, merged = kept
    cell = (CONFIG["grid"]["length"] / CONFIG["grid"]["n"]) ** 2
    assert np.allclose(merged["largest_patch_area"].values, merged["largest_patch_cells"].values * cell, rtol=1e-12)


def test_histograms_at_their_defaults_leave_the_run_record():
    plain, with_empty = _config(), _config(histograms={"at": [], "bins": 7})
    assert (jobs.job_settings(with_empty, naming.runs(with_empty)[0]).record()
            == jobs.job_settings(plain, naming.runs(plain)[0]).record())


def test_the_companions_keep_no_histogram_or_opt_in_quantity():
    """Adding them reruns the study's runs only: the grid error's coarse runs stay as they were."""
    base = {**CONFIG, "grid": {"n": 65, "length": 1.0}}
    plain = resolve_config(base)
    more = resolve_config({**base, "fields": {"quantities": ["mean_gap"], "histograms": {"at": [1e-4]}}})
    coarse = [jobs.job_settings(coarse_config(cfg), naming.runs(coarse_config(cfg))[0]) for cfg in (plain, more)]
    assert coarse[0] == coarse[1]


@pytest.mark.parametrize("extra, key", [
    ({"fields": {"histograms": {"at": [1e-2]}}}, "fields.histograms.at[0]"),
    ({"fields": {"histograms": {"at": [1e-4, 5e-6]}}}, "fields.histograms.at[1]"),
    # within the spheres' path, outside the flat runs': no run's histogram is moved to another load
    ({"radius": [0.5, float("inf")], "forces": {"sphere": {"from": 1e-5, "to": 1e-3, "count": 5},
                                                "flat": {"from": 1e-5, "to": 1e-4, "count": 5}},
      "fields": {"histograms": {"at": [5e-4]}}}, "fields.histograms.at[0]"),
    ({"work_of_adhesion": [1e-3], "fields": {"histograms": {"at": [1e-4]}}}, "fields.histograms"),
    ({"fields": {"histograms": {"at": [1e-4], "bins": 1}}}, "fields.histograms.bins"),
    ({"fields": {"histograms": {"every": 2}}}, "fields.histograms"),
    # a flat run's quantity in a sweep of spheres
    ({"fields": {"quantities": ["mean_gap", "relative_contact_area"]}}, "fields.quantities[1]"),
])
def test_what_the_sweep_cannot_give_is_refused_in_one_line_naming_the_key(extra, key):
    with pytest.raises(errors.ConfigError) as err:
        resolve_config({**CONFIG, **extra})
    assert (err.value.key.startswith(key), "\n" in str(err.value)) == (True, False), str(err.value)


def test_a_flat_run_s_quantity_is_kept_by_the_flat_runs_only():
    cfg = resolve_config({**CONFIG, "radius": [0.5, float("inf")],
                          "forces": {"sphere": CONFIG["forces"]["sphere"],
                                     "flat": {"from": 1e-5, "to": 1e-4, "count": 5}},
                          "fields": {"quantities": ["relative_contact_area"]}})
    kept = {run["kind"]: jobs.job_settings(cfg, run).quantities for run in naming.runs(cfg)}
    assert kept == {"sphere": (), "flat": ("relative_contact_area",)}


def test_a_run_computed_before_a_quantity_was_added_is_refused_by_the_merge(tmp_path):
    """Where Snakemake does not rerun it (its params trigger off, files copied without
    ``.snakemake``), the merge says which setting changed and what to do, in one line."""
    plain, more = _config(), _config(quantities=["mean_gap"])
    run = naming.runs(plain)[0]
    job = jobs.job_settings(plain, run)
    path = tmp_path / "run.nc"
    indent.write_run(path, job, indent.compute_run(job))
    with pytest.raises(errors.MergeError) as err:
        io.read_run(path, jobs.job_settings(more, run))
    assert ("quantities: absent in the file, ['mean_gap'] now" in str(err.value), "rerun" in str(err.value),
            "\n" in str(err.value)) == (True, True, False), str(err.value)


def test_units_length_names_the_units_of_the_merged_variables():
    assert (study_units("e_star * length**2", "um", "MPa"), study_units("length**2", "um"),
            study_units("1", "um")) == ("MPa * um**2", "um**2", "1")


def test_the_merged_files_carry_the_configured_units(tmp_path):
    import xarray as xr

    from roughcontact.study.rules import merge

    cfg = resolve_config({**CONFIG, "units": {"length": "um"}, "fields": {"quantities": ["mean_gap"]}})
    job = jobs.job_settings(cfg, naming.runs(cfg)[0])
    path = tmp_path / "run.nc"
    indent.write_run(path, job, indent.compute_run(job))
    merge.run(cfg, runs=[path], stiffness=tmp_path / "stiffness.nc", ensemble=tmp_path / "ensemble.nc")
    with xr.open_dataset(tmp_path / "stiffness.nc", group="sphere") as ds, \
            xr.open_dataset(tmp_path / "ensemble.nc", group="sphere") as ens:
        units = (ds["contact_area"].attrs["units"], ds["mean_gap"].attrs["units"], ds["force"].attrs["units"],
                 ens["mean_gap_mean"].attrs["units"])
    assert units == ("um**2", "um", "e_star * um**2", "um")
