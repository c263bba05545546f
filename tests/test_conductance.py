"""Barber's conductance from the stiffness (roughcontact.models.conductance) against Holm's
closed form for one circle, C = 4a/(ρ₁ + ρ₂), and in the pipeline's merged files."""
import math

import numpy as np
import pytest

from roughcontact.models import conductance, paper


def test_one_circle_is_holms_conductance():
    """Hertz (k = 2E*a) under F: C = 4a/(ρ₁+ρ₂), a = (3FR/4E*)^(1/3); copper on steel."""
    force, radius, e_star = 10.0, 5e-3, 100e9
    a = float(paper.hertz_contact_radius(force, radius=radius, e_star=e_star))
    k = 2 * e_star * a
    rho = (1.7e-8, 1.0e-7)
    assert conductance.electrical_conductance(k, e_star=e_star, resistivities=rho) == pytest.approx(
        4 * a / sum(rho), rel=1e-14)


def test_thermal_is_electrical_with_inverse_conductivities():
    k, e_star = 3.0e6, 2.0e9
    assert conductance.thermal_conductance(k, e_star=e_star, conductivities=(400.0, 50.0)) == pytest.approx(
        2 * k / (e_star * (1 / 400 + 1 / 50)), rel=1e-14)


@pytest.mark.parametrize("bad", [(1.0,), (-1.0, 1.0), (0.0, 0.0), (math.nan, 1.0)])
def test_bad_resistivities_are_refused(bad):
    with pytest.raises(ValueError, match="resistivities"):
        conductance.electrical_conductance(1.0, e_star=1.0, resistivities=bad)


def test_the_merge_gives_the_conductance_of_each_run(tmp_path):
    """A generated study in µm with copper on copper: stiffness.nc's electrical_conductance is
    2k/(E*(ρ₁+ρ₂)) of each run's stiffness, k/E* = (k/(E* L)) L converted to m."""
    from roughcontact.study.analysis.merge import merge_runs
    from roughcontact.study.config import resolve_config
    from roughcontact.study.runs import indent, jobs, naming

    cfg = resolve_config({"grid": {"n": 33, "length": 10.0}, "units": {"length": "um"}, "hurst": [0.7],
                          "radius": [5.0], "h_rms": [0.02], "seeds": 1,
                          "forces": {"sphere": {"from": 1e-5, "to": 1e-3, "count": 3}},
                          "conductance": {"resistivity": [1.7e-8, 1.7e-8], "conductivity": [400.0, 400.0]}})
    job = jobs.job_settings(cfg, naming.runs(cfg)[0])
    path = tmp_path / "run.nc"
    out = indent.compute_run(job)
    indent.write_run(path, job, out)
    merged = merge_runs(cfg, [path])["sphere"]
    expected = 2 * out["stiffness"] / cfg["e_star"] * 1e-6 / (2 * 1.7e-8)
    assert np.allclose(merged["electrical_conductance"].values.ravel(), expected, rtol=1e-14, atol=0)
    assert merged["thermal_conductance"].attrs["units"] == "W K-1"
