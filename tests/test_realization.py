"""One realisation on several grids (``self_affine(..., realization_of=N)``): the fine
surface's Fourier low-pass sampled at the coarse nodes, the same physical surface for a grid
convergence study."""
from __future__ import annotations

import numpy as np
import pytest

from roughcontact import surfaces

KW = dict(hurst=0.7, h_rms=9e-3, length=1.0, seed=3)


def _low_pass(fine: np.ndarray, n: int) -> np.ndarray:
    """The modes |k_x|, |k_y| < n/2 of *fine* (a direct FFT filter: the closed form)."""
    k = np.fft.fftfreq(fine.shape[0]) * fine.shape[0]
    keep = (np.abs(k)[:, None] < n / 2) & (np.abs(k)[None, :] < n / 2)
    return np.fft.ifft2(np.fft.fft2(fine) * keep).real


@pytest.mark.parametrize("n, fine", [(33, 99), (65, 195), (64, 192)])
def test_coarse_grid_samples_the_low_pass_of_the_fine_surface(n, fine):
    """Where the fine grid has a node at every coarse node (fine = 3n), the coarse surface is
    the low-pass of the fine one there; FFT round-off ~1e-15 of h_rms."""
    coarse = surfaces.self_affine(n, realization_of=fine, **KW)
    expected = _low_pass(surfaces.self_affine(fine, **KW), n)[::fine // n, ::fine // n]
    error = np.abs(coarse - expected).max() / KW["h_rms"]
    assert error < 1e-12, f"coarse {n} of {fine}: max deviation {error:.2e} h_rms"


def test_realization_of_its_own_grid_is_the_surface():
    own = surfaces.self_affine(65, realization_of=65, **KW)
    error = np.abs(own - surfaces.self_affine(65, **KW)).max() / KW["h_rms"]
    assert error == 0.0, f"realization_of = n changed the surface by {error:.2e} h_rms"


def test_coarse_rms_misses_only_the_dropped_power():
    """rms² of the coarse surface = h_rms² minus the power of the fine modes it drops (Parseval)."""
    fine = surfaces.self_affine(99, **KW)
    dropped = fine - _low_pass(fine, 33)
    expected = np.sqrt(KW["h_rms"] ** 2 - np.mean(dropped**2))
    rms = np.sqrt(np.mean(surfaces.self_affine(33, realization_of=99, **KW) ** 2))
    assert rms == pytest.approx(expected, rel=1e-12), f"coarse rms {rms:.6e}, expected {expected:.6e}"


def test_rough_sphere_carries_the_realization():
    sphere = surfaces.rough_sphere(33, radius=0.5, realization_of=99, **KW)
    expected = surfaces.paraboloid(33, radius=0.5, length=1.0) + surfaces.self_affine(33, realization_of=99, **KW)
    error = np.abs(sphere - expected).max() / KW["h_rms"]
    assert error < 1e-12, f"rough_sphere(realization_of) off by {error:.2e} h_rms"


def test_finer_grid_than_the_realization_is_an_error():
    with pytest.raises(ValueError, match="realization_of"):
        surfaces.self_affine(65, realization_of=33, **KW)
