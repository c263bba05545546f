"""The crossover estimator (eq. 16 with free prefactors, bootstrap over seeds)
against synthetic ensembles whose truth is known, and the verdict rules."""
from __future__ import annotations

import math

import numpy as np
import pytest

from roughcontact.models import paper
from roughcontact.study.analysis import statistics
from roughcontact.study.analysis import crossover

# The paper's Fig. 3 (R = 0.5, H = 0.7, h_rms = 9e-3, L = E* = 1, zeta = 1): F_tr = 8.0e-5 E* L^2 (eq. 17).
RADIUS, HURST, H_RMS, LENGTH = 0.5, 0.7, 9e-3, 1.0
# presets/paper.yaml's loads that touch >= 20 contact cells on 513^2 (1e-5 ... 1e-2, 13 loads)
FORCES = np.geomspace(1e-7, 1e-2, 21)[8:]
#: the combination and the windows of the tests: 20 cells, slopes below 0.3 F_tr and above 5 F_tr (the defaults)
CASE = crossover.SphereCase(hurst=HURST, radius=RADIUS, h_rms=H_RMS, length=LENGTH)
WINDOWS = crossover.VerdictWindows(min_cells=20, low_max_ratio=0.3, high_min_ratio=5.0)
# Per-seed scatter of k measured on the paper preset (50 seeds, 2026-11-23): relative standard deviation
# 0.22 at F = 1e-5 falling to 0.05 at 1e-2, and correlation 0.9 between neighbouring loads of one seed.
SCATTER = 0.22 * (FORCES / 1e-5) ** -0.21
NEIGHBOUR_CORRELATION = 0.9


def _ensemble(rng, seeds, k_true):
    """Per-seed stiffnesses k_true * exp(sigma e - sigma^2/2): mean k_true, AR(1)-correlated over loads."""
    noise = np.empty((seeds, k_true.size))
    noise[:, 0] = rng.standard_normal(seeds)
    for i in range(1, k_true.size):
        noise[:, i] = (NEIGHBOUR_CORRELATION * noise[:, i - 1]
                       + math.sqrt(1 - NEIGHBOUR_CORRELATION**2) * rng.standard_normal(seeds))
    return k_true * np.exp(SCATTER * noise - SCATTER**2 / 2)


def test_exact_eq16_gives_its_prefactors_and_eq17():
    """Noise-free eq. 16: A = L/(6R), B = (h/L) zeta^-(H+1) and F_tr of eq. 17, to round-off."""
    k = paper.stiffness_from_force(FORCES, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    fit = crossover.fit_eq16(FORCES, k, HURST)
    assert float(fit.hertz_coefficient) == pytest.approx(LENGTH / (6 * RADIUS), rel=1e-9), "A != L/(6R)"
    assert float(fit.rough_coefficient) == pytest.approx(H_RMS / LENGTH, rel=1e-9), "B != h/L (zeta = 1)"
    f_tr = paper.crossover_force(RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    assert float(fit.crossover_force) == pytest.approx(f_tr, rel=1e-9), "F_tr != eq. 17"


@pytest.mark.parametrize("zeta, radius", [(1.0, 0.5), (1.3, 2.0)])
def test_exact_eq16_other_prefactors(zeta, radius):
    """The fit is not tied to the paper's numbers: another zeta and radius, F_tr of eq. 17 to round-off."""
    f_tr = paper.crossover_force(radius, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=zeta)
    forces = f_tr * np.geomspace(0.05, 100, 15)
    k = paper.stiffness_from_force(forces, radius=radius, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=zeta)
    fit = crossover.fit_eq16(forces, k, HURST)
    assert float(fit.crossover_force) == pytest.approx(f_tr, rel=1e-9), "F_tr != eq. 17"


def test_crossover_estimator_bias_and_coverage():
    """200 synthetic 50-seed ensembles of eq. 16 (F_tr = 8.0e-5) with the measured per-seed scatter on
    the real load grid: the estimate's bias is <= 5 % and the 95 % bootstrap interval covers the
    truth in 90-99 % of the trials (the issue's bounds; a binomial 95 % band around 0.95 with 200
    trials is 0.92-0.98)."""
    rng = np.random.default_rng(7)
    k_true = paper.stiffness_from_force(FORCES, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    f_true = paper.crossover_force(RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    indices = statistics.bootstrap_indices(50, 400)
    log_errors, covered = [], 0
    for _ in range(200):
        k = _ensemble(rng, 50, k_true)
        log_errors.append(math.log(float(crossover.fit_eq16(FORCES, k.mean(0), HURST).crossover_force) / f_true))
        low, high = statistics.interval(crossover.fit_eq16(FORCES, k[indices].mean(1), HURST).crossover_force, 0.95)
        covered += low <= f_true <= high
    bias = math.exp(np.mean(log_errors)) - 1
    assert abs(bias) <= 0.05, f"bias of the F_tr estimate {bias:+.3f}"
    assert 0.90 <= covered / 200 <= 0.99, f"coverage {covered / 200:.3f} of the 95 % interval"


def _verdicts_of(forces, k_seeds, cells=100):
    return crossover.sphere_verdicts(
        forces, k_seeds, np.full(k_seeds.shape, cells), case=CASE, zeta_fit=1.0,
        indices=statistics.bootstrap_indices(k_seeds.shape[0], 200), windows=WINDOWS)


def test_loads_above_the_crossover_are_unresolved():
    """Every load above 10 F_tr: the loads do not bracket the crossover, and the row says so."""
    forces = np.geomspace(1e-3, 1e-2, 8)
    k = paper.stiffness_from_force(forces, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    row = _verdicts_of(forces, np.tile(k, (6, 1)) * np.linspace(0.98, 1.02, 6)[:, None]).row
    assert row["verdict_fit"] == "unresolved", row["verdict_fit"]
    assert "unresolved" in row["note"], row["note"]
    assert math.isnan(row["Ftr_ci_low"]), "an unresolved crossover has no interval"


def test_unresolved_loads_are_left_out():
    """Loads with fewer contact cells than min_cells do not enter the fit: 3 resolved loads are too few."""
    k = paper.stiffness_from_force(FORCES, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    cells = np.where(np.arange(FORCES.size) < FORCES.size - 3, 5, 100)
    row = crossover.sphere_verdicts(
        FORCES, np.tile(k, (4, 1)), np.tile(cells, (4, 1)), case=CASE, zeta_fit=1.0,
        indices=statistics.bootstrap_indices(4, 50), windows=WINDOWS).row
    assert row["n_loads_resolved"] == 3, row["n_loads_resolved"]
    assert row["verdict_estimate"] == "unresolved", row["verdict_estimate"]


def test_exact_ensemble_is_consistent_with_eq17_and_eq16():
    """Seeds scattered symmetrically around eq. 16: F_tr's interval holds eq. 17 and eq. 16 deviates < 1 %."""
    rng = np.random.default_rng(3)
    k_true = paper.stiffness_from_force(FORCES, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    row = _verdicts_of(FORCES, _ensemble(rng, 50, k_true)).row
    assert row["verdict_estimate"] == "consistent", (row["Ftr_ci_low"], row["Ftr_ci_high"])
    assert row["Ftr_ci_low"] < row["Ftr_measured"] < row["Ftr_ci_high"], "estimate outside its interval"
    assert row["k_over_hertz_below_Ftr"] < 1.0, "eq. 16 lies below Hertz below F_tr"


@pytest.mark.parametrize("value, low, high, expected", [
    (1.0, 0.9, 1.1, "consistent"), (1.2, 0.9, 1.1, "differs"), (0.8, 0.9, 1.1, "differs"),
    (1.0, math.nan, math.nan, "untested")])
def test_verdict_of_a_value(value, low, high, expected):
    assert statistics.verdict(value, low, high) == expected


@pytest.mark.parametrize("low, high, expected", [
    (0.7, 0.8, "consistent"), (1.1, 1.2, "differs"), (0.9, 1.1, "untested")])
def test_verdict_of_a_bound(low, high, expected):
    """A claim 'value < 1': the interval wholly below 1 supports it, wholly above rejects it."""
    assert statistics.verdict_bound(1.0, low, high, side="below").split(":")[0] == expected


def test_slopes_of_a_body_shallower_than_the_roughness():
    """A cone (m = 1) with H = 1.4: the body's term k^2 dominates at small forces, so the low-force
    slope tends to 1/(m+1) = 1/2 and the high-force one to 1/(H+1) = 0.417 (eq. 16 with m < H)."""
    zeta = float(paper.zeta_estimate(1.4))
    forces = np.geomspace(1e-5, 5e-3, 12)
    k = paper.stiffness_from_force(forces, radius=RADIUS, hurst=1.4, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=zeta, exponent=1.0)
    row = crossover.sphere_verdicts(
        forces, np.tile(k, (4, 1)), np.full((4, forces.size), 100),
        case=crossover.SphereCase(hurst=1.4, radius=RADIUS, h_rms=H_RMS, length=LENGTH, exponent=1.0), zeta_fit=zeta,
        indices=statistics.bootstrap_indices(4, 50), windows=WINDOWS).row
    assert row["slope_low_theory"] == pytest.approx(1 / 2), "low-force asymptote of m < H"
    assert row["slope_high_theory"] == pytest.approx(1 / 2.4), "high-force asymptote of m < H"


def test_eq16_on_the_fractal_branch_alone_is_the_systematic_offset():
    """Every seed k = 1.05 k_eq16 below F_tr and k_eq16 above: eq. 16's mean and largest deviation on
    the fractal branch alone are +5 % (round-off), the deviation over every load is 5 % too, but
    only the fractal-branch columns are made of the loads below F_tr (the offset's 3 % and 7 %
    seeds keep the mean at 1.05, so the interval is not a point)."""
    k = paper.stiffness_from_force(FORCES, radius=RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0)
    f_tr = float(paper.crossover_force(RADIUS, hurst=HURST, h_rms=H_RMS, length=LENGTH, e_star=1.0, zeta=1.0))
    below = FORCES < f_tr
    offset = np.array([1.03, 1.05, 1.07])[:, None]
    row = _verdicts_of(FORCES, np.where(below, k * offset, k)).row
    assert row["eq16_fractal_mean_rel_dev"] == pytest.approx(0.05, abs=1e-12)
    assert row["eq16_fractal_max_rel_dev"] == pytest.approx(0.05, abs=1e-12)
    assert row["eq16_fractal_mean_rel_dev_ci_low"] < 0.05 < row["eq16_fractal_mean_rel_dev_ci_high"]
