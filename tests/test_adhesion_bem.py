"""The adhesive boundary-element solve (roughcontact.bem.adhesion) against JKR and Hertz: the smooth
sphere's pull-off converging to -(3/2) pi w R as the contact grows in cells, Hertz without adhesion,
unloading that retraces loading without adhesion and departs from it with, and the units' scaling."""
from __future__ import annotations

import math

import numpy as np
import pytest

from roughcontact.bem.adhesion import adhesive_path, critical_stress
from roughcontact.models import adhesion
from roughcontact.surfaces import paraboloid


def _sphere_path(n: int, cells: float, *, length=1.0, e_star=1.0, radius=1.0, steps=100):
    """Load to 2.5 a_c²/R and unload past JKR's fixed-grips jump-off, with w such that JKR's
    pull-off contact radius is *cells* cells: ``(path, JKR pull-off, JKR jump-off approach)``."""
    a_c = cells * length / n
    w = a_c**3 * 8 * e_star / (9 * math.pi * radius**2)
    force, _ = adhesion.jkr_pull_off(radius=radius, e_star=e_star, work_of_adhesion=w)
    _, _, d_jump = adhesion.jkr_fixed_grips_pull_off(radius=radius, e_star=e_star, work_of_adhesion=w)
    d_max = 2.5 * a_c**2 / radius
    depths = np.concatenate([np.linspace(0, d_max, 20), np.linspace(d_max, 1.5 * d_jump, steps)])
    z = paraboloid(n, radius=radius, length=length)
    return adhesive_path(z, depths, length=length, e_star=e_star, work_of_adhesion=w), force, d_jump


@pytest.fixture(scope="module")
def paths():
    """JKR pull-off radius of 10 cells (64²) and 20 cells (128²)."""
    return {cells: _sphere_path(n, cells) for n, cells in ((64, 10), (128, 20))}


def test_pull_off_tends_to_jkr(paths):
    """20 cells: within 8 % of -(3/2) pi w R (measured: +10.9 % at 10 cells, +5.2 % at 20, +1.4 % at 40)."""
    path, jkr, _ = paths[20]
    assert path.pull_off_force / jkr == pytest.approx(1.0, abs=0.08), f"pull-off {path.pull_off_force / jkr:.4f} x JKR"


def test_pull_off_converges_with_the_cells(paths):
    errors = {cells: abs(path.pull_off_force / jkr - 1) for cells, (path, jkr, _) in paths.items()}
    assert errors[20] < errors[10], f"pull-off errors by contact cells: {errors}"


def test_contact_comes_off_near_jkr_jump_off(paths):
    """Displacement control: the last cell leaves near JKR's fixed-grips instability (within 25 % at
    20 cells; the approach there is a difference of two terms, so it converges slower than F)."""
    path, _, d_jump = paths[20]
    assert path.detach_depth / d_jump == pytest.approx(1.0, abs=0.25), f"detach at {path.detach_depth / d_jump:.3f}"


def test_unloading_is_more_tensile_than_loading(paths):
    """Hysteresis: at the same approach the unloading force lies below the loading force."""
    path, _, _ = paths[20]
    load, unload = slice(0, 20), slice(20, None)
    d_load, f_load = path.depth[load], path.force[load]
    on_unload = (path.depth[unload] > 0) & (path.depth[unload] < d_load[-1] * 0.9)
    f_back = np.interp(path.depth[unload][on_unload], d_load, f_load)
    assert np.all(path.force[unload][on_unload] < f_back), "unloading is not below loading"


def test_without_adhesion_it_is_hertz():
    """w = 1e-14 (sigma_c ~ 1e-6 of the pressures): F = (4/3) E* sqrt(R) d^(3/2) within 3 % where
    the contact radius exceeds 15 cells of 128² (the discretisation error of the area)."""
    n, radius = 128, 1.0
    depths = np.linspace(0.005, 0.04, 8)
    path = adhesive_path(paraboloid(n, radius=radius, length=1.0), depths, length=1.0, e_star=1.0,
                         work_of_adhesion=1e-14)
    hertz = 4 / 3 * math.sqrt(radius) * depths**1.5
    use = path.contact_radius > 15 / n
    np.testing.assert_allclose(path.force[use], hertz[use], rtol=0.03, err_msg="Hertz")


def test_without_adhesion_unloading_retraces_loading():
    depths = np.linspace(0.005, 0.03, 6)
    z = paraboloid(64, radius=1.0, length=1.0)
    path = adhesive_path(z, np.concatenate([depths, depths[::-1]]), length=1.0, e_star=1.0, work_of_adhesion=1e-14)
    np.testing.assert_allclose(path.force[6:], path.force[:6][::-1], rtol=1e-6, err_msg="unloading != loading")


def test_units_scale_the_pull_off():
    """Lengths x 3, E* x 7, w x 21 (so that w/(E* L) is unchanged): forces x 7 x 9, the same ratio to JKR."""
    one, jkr_one, _ = _sphere_path(64, 10)
    other, jkr_other, _ = _sphere_path(64, 10, length=3.0, e_star=7.0, radius=3.0)
    assert other.pull_off_force / jkr_other == pytest.approx(one.pull_off_force / jkr_one, rel=1e-6), "scaling"


def test_critical_stress():
    assert critical_stress(e_star=2.0, work_of_adhesion=0.5, spacing=0.25, constant=2.1) == \
        pytest.approx(math.sqrt(2.1 * 2.0 * 0.5 / 0.25), rel=1e-15)


def test_bad_heights_are_named():
    with pytest.raises(ValueError, match="square"):
        adhesive_path(np.zeros((4, 5)), [0.1], length=1.0, e_star=1.0, work_of_adhesion=0.1)


@pytest.fixture(scope="module")
def force_path():
    """The 64² sphere of 10 cells of JKR pull-off radius under force control: loaded to twice JKR's
    pull-off force, unloaded towards 1.5 times its tension in 10 targets."""
    from roughcontact.bem.adhesion import adhesive_force_path

    n, cells = 64, 10
    a_c = cells / n
    w = a_c**3 * 8 / (9 * math.pi)
    jkr, _ = adhesion.jkr_pull_off(radius=1.0, e_star=1.0, work_of_adhesion=w)
    targets = np.concatenate([[-2 * jkr], np.linspace(-1.5 * jkr, 1.5 * jkr, 10)])
    path = adhesive_force_path(paraboloid(n, radius=1.0, length=1.0), targets, step=a_c**2 / 100, length=1.0,
                               e_star=1.0, work_of_adhesion=w)
    return path, targets, jkr, w


def test_force_control_reaches_its_targets(force_path):
    path, targets, _, _ = force_path
    np.testing.assert_allclose(path.force, targets[:len(path.force)], rtol=1e-5, err_msg="forces reached")


def test_force_control_comes_off_at_the_least_force_of_displacement_control(force_path):
    """The load-controlled pull-off is the least force of the displacement-controlled branch: the
    two paths agree within 1 % (the step's resolution near the minimum is quadratic)."""
    path, _, _, w = force_path
    n, a_c = 64, 10 / 64
    depths = np.concatenate([np.linspace(0, 2.5 * a_c**2, 20), np.linspace(2.5 * a_c**2, -0.5 * a_c**2, 200)])
    displaced = adhesive_path(paraboloid(n, radius=1.0, length=1.0), depths, length=1.0, e_star=1.0,
                              work_of_adhesion=w)
    assert path.pull_off_force == pytest.approx(displaced.pull_off_force, rel=0.01), \
        f"force control {path.pull_off_force:.4g}, displacement control {displaced.pull_off_force:.4g}"


def test_force_control_stops_at_the_pull_off(force_path):
    """Targets below the pull-off are not reached: the path ends with the last target above it."""
    path, targets, _, _ = force_path
    reachable = int(np.sum(targets >= path.pull_off_force))
    assert len(path.force) == reachable, f"{len(path.force)} targets reached, {reachable} above the pull-off"
