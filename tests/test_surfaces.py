"""Generated surfaces against their defining properties (eqs. 1–3, 15)."""

import numpy as np
import pytest

from roughcontact import surfaces, theory

LENGTH = 2.5


@pytest.mark.parametrize("n", [64, 65])
@pytest.mark.parametrize("hurst", [0.3, 0.7, 1.2])
def test_mean_zero_and_rms_exact(n, hurst):
    z = surfaces.self_affine(n, hurst=hurst, h_rms=3e-3, length=LENGTH, seed=7)
    assert abs(z.mean()) <= 1e-12 * 3e-3, "mean height is not zero"
    assert np.sqrt(np.mean(z**2)) == pytest.approx(3e-3, rel=1e-12), "rms height != h_rms"


@pytest.mark.parametrize("n", [64, 65])
def test_real_and_hermitian(n):
    z = surfaces.self_affine(n, hurst=0.7, h_rms=1.0, length=LENGTH, seed=3)
    assert z.dtype == np.float64 and np.all(np.isfinite(z)), "heights are not finite reals"
    spectrum = np.fft.fft2(z)
    mirrored = np.roll(np.flip(spectrum), 1, axis=(0, 1))
    # A real surface has a Hermitian spectrum, so it is smooth across the
    # periodic boundary in the sense of its Fourier series (no hidden imaginary part).
    assert np.allclose(spectrum, np.conj(mirrored), atol=1e-12 * np.abs(spectrum).max()), \
        "spectrum is not Hermitian"


def radial_psd_slope(n, hurst, seeds, length=1.0):
    q = surfaces.wavevectors(n, length)
    qmin = 2 * np.pi / length
    # Log-spaced annuli between 2 qmin and the largest q inside the circle.
    edges = np.geomspace(2 * qmin, qmin * (n // 2), 12)
    psd = np.zeros(len(edges) - 1)
    bins = [(q >= lo) & (q < hi) for lo, hi in zip(edges[:-1], edges[1:])]
    for seed in seeds:
        z = surfaces.self_affine(n, hurst=hurst, h_rms=1.0, length=length, seed=seed)
        power = np.abs(np.fft.fft2(z)) ** 2
        psd += [power[annulus].mean() for annulus in bins]
    # Each annulus is placed at the geometric mean |q| of the modes it holds.
    centres = np.array([np.exp(np.log(q[annulus]).mean()) for annulus in bins])
    return np.polyfit(np.log(centres), np.log(psd / len(seeds)), 1)[0]


@pytest.mark.parametrize("hurst", [0.3, 0.7, 1.2])
@pytest.mark.parametrize("n", [128, 127])
def test_power_spectrum_slope(hurst, n):
    """C2D ∝ q^(−2H−2) (eq. 1): the radially averaged spectrum over 8 seeds.

    The average of q^(−2H−2) over an annulus exceeds its value at the modes'
    geometric-mean |q| by a factor that varies slowly from bin to bin (the bins
    are log-spaced and hold few modes at small q), biasing the fitted slope by
    < 0.01 on these grids; ±0.05 is the issue's bound.
    """
    slope = radial_psd_slope(n, hurst, seeds=range(8))
    assert slope == pytest.approx(-2 * hurst - 2, abs=0.05), f"PSD slope {slope} for H={hurst}"


def test_same_seed_identical_bytes():
    a = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    b = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    assert a.tobytes() == b.tobytes(), "same seed gave different bytes"


def test_different_seed_differs():
    a = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=11)
    b = surfaces.self_affine(65, hurst=0.7, h_rms=1e-2, length=1.0, seed=12)
    assert np.abs(a - b).max() > 1e-3, "different seeds gave the same surface"


@pytest.mark.parametrize("n", [64, 65])
def test_paraboloid_apex_and_curvature(n):
    z = surfaces.paraboloid(n, radius=0.5, length=1.0)
    assert z[n // 2, n // 2] == 0.0, "apex is not at the centre node"
    dx = 1.0 / n
    assert z[n // 2 + 3, n // 2] == pytest.approx((3 * dx) ** 2 / (2 * 0.5), rel=1e-14), \
        "paraboloid is not r^2/(2R)"


def test_rough_sphere_is_sum():
    kw = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=5)
    z = surfaces.rough_sphere(33, radius=0.5, **kw)
    expected = surfaces.paraboloid(33, radius=0.5, length=1.0) + surfaces.self_affine(33, **kw)
    assert np.array_equal(z, expected), "rough sphere is not paraboloid + roughness"


def test_equivalent_profile_eq15():
    n, hurst, h, zeta = 65, 0.7, 9e-3, 1.0
    z = surfaces.equivalent_profile(n, radius=0.5, hurst=hurst, h_rms=h, length=1.0, zeta=zeta)
    r = 10 / n
    q3d = (2 / zeta) ** (hurst + 1) * (hurst + 1) * h / (2 * hurst * theory.kappa(hurst))
    assert z[n // 2 + 10, n // 2] == pytest.approx(r**2 / 1.0 + q3d * r**hurst, rel=1e-13), \
        "profile differs from eq. 15"


def test_equivalent_profile_flat_has_no_parabola():
    z = surfaces.equivalent_profile(65, radius=np.inf, hurst=0.5, h_rms=1e-2, length=1.0)
    q3d = theory.profile_prefactor(0.5, 1e-2, 1.0, theory.zeta_estimate(0.5))
    assert z[32 + 4, 32] == pytest.approx(q3d * (4 / 65) ** 0.5, rel=1e-13), "z_s != Q3D r^H"


@pytest.mark.parametrize("kwargs, name", [
    (dict(n=7, hurst=0.7, h_rms=1.0), "n"),
    (dict(n=8.0, hurst=0.7, h_rms=1.0), "n"),
    (dict(n=16, hurst=0.0, h_rms=1.0), "hurst"),
    (dict(n=16, hurst=2.0, h_rms=1.0), "hurst"),
    (dict(n=16, hurst=float("nan"), h_rms=1.0), "hurst"),
    (dict(n=16, hurst=0.7, h_rms=0.0), "h_rms"),
    (dict(n=16, hurst=0.7, h_rms=float("inf")), "h_rms"),
    (dict(n=16, hurst=0.7, h_rms=1.0, length=-1.0), "length"),
    (dict(n=16, hurst=0.7, h_rms=1.0, seed=1.5), "seed"),
])
def test_bad_arguments_name_themselves(kwargs, name):
    n = kwargs.pop("n")
    with pytest.raises(ValueError, match=name):
        surfaces.self_affine(n, **kwargs)


def test_bad_radius_names_itself():
    with pytest.raises(ValueError, match="radius"):
        surfaces.paraboloid(16, radius=-0.5)
