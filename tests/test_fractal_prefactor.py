"""The fractal-branch prefactor of rough spheres from the touch height (models.fractal_prefactor)."""
import numpy as np
import pytest

from roughcontact.models.fractal_prefactor import CALIBRATED, expected_touch_height, fractal_prefactor, touch_height
from roughcontact.models.zeta_law import zeta_law
from roughcontact.surfaces import self_affine


def test_touch_at_the_mean_plane_gives_the_flat_law():
    hurst = np.array([0.3, 0.7, 0.9])
    assert np.allclose(fractal_prefactor(hurst, 0.0), zeta_law(hurst), rtol=1e-15)


def test_exponential_in_the_touch_height():
    # closed form: ζ_s(u)/ζ_s(0) = exp(−β u)
    u = np.array([0.5, 1.0, 3.0])
    ratio = fractal_prefactor(0.7, u) / fractal_prefactor(0.7, 0.0)
    assert np.allclose(ratio, np.exp(-CALIBRATED["beta"] * u), rtol=1e-14)
    assert fractal_prefactor(0.7, 1.0, beta=0.0) == pytest.approx(float(zeta_law(0.7)), rel=1e-15)


def test_touch_height_of_two_cosines():
    # z_r = −cos(2πx/L) − cos(2πy/L) (gaps): rms 1, least value −2 at the nodes x = y = 0 -> u = 2 (flat);
    # a sphere with its apex there touches at the same node
    n, length = 64, 1.0
    x = np.arange(n) * length / n
    z = -np.cos(2 * np.pi * x)[:, None] - np.cos(2 * np.pi * x)[None, :]
    assert touch_height(z, radius=np.inf) == pytest.approx(2.0, rel=1e-12)
    shifted = np.roll(np.roll(z, n // 2, axis=0), n // 2, axis=1)      # the summit under the apex node
    assert touch_height(shifted, radius=0.5) == pytest.approx(2.0, rel=1e-12)


def test_a_small_sphere_touches_at_its_apex():
    # R -> 0: the body's rise beats any roughness one cell away, so x* is the apex node
    z = self_affine(64, hurst=0.7, h_rms=1e-3, seed=3)
    apex = -z[32, 32] / np.sqrt(np.mean(z**2))
    assert touch_height(z, radius=1e-6) == pytest.approx(apex, rel=1e-12)
    assert expected_touch_height(64, radius=1e-6, hurst=0.7, h_rms=1e-3, seeds=[3]) == pytest.approx(apex, rel=1e-12)


def test_flat_touches_higher_than_a_sphere():
    kwargs = dict(hurst=0.7, h_rms=9e-3, seeds=range(4))
    assert expected_touch_height(128, radius=np.inf, **kwargs) > expected_touch_height(128, radius=0.1, **kwargs)
