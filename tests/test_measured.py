"""Measured topographies (roughcontact.surfaces.measured) read with SurfaceTopography.

Synthetic files (NetCDF, X3P, NumPy, MI) are written into ``tmp_path``; the three real
scans of ``shared/topographies`` (``../shared/topographies`` from the project root, or
``$ROUGHCONTACT_TOPOGRAPHIES``) are used where present and skipped otherwise.
"""

import os
import re
from pathlib import Path

import numpy as np
import pytest

ST = pytest.importorskip("SurfaceTopography")

from roughcontact import bem, surfaces
from roughcontact.errors import InputFileError
from roughcontact.surfaces.measured import MeasuredSurface, from_topography
from roughcontact.surfaces.subwindows import edge_jump, tiles

_DEFAULT = Path(__file__).resolve().parents[1].parent / "shared" / "topographies"
SHARED = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES", _DEFAULT))
needs_shared = pytest.mark.skipif(not (SHARED / "di-6.di").is_file(),
                                  reason=f"measured scans not found in {SHARED}")


def _nc(path, heights, sizes=(1.0, 1.0), unit="µm"):
    ST.Topography(heights, sizes, unit=unit).to_netcdf(str(path))
    return path


def _mi(path, unit, label, n=16):
    """A minimal Molecular Imaging file: one channel of ``unit`` data named ``label``."""
    lines = [("fileType", "Image"), ("xPixels", n), ("yPixels", n), ("xLength", "1e-6"),
             ("yLength", "1e-6"), ("bufferLabel", label), ("bufferUnit", unit),
             ("bufferRange", "1.0"), ("data", "BINARY")]
    header = "".join(f"{k:<14}{v}\n" for k, v in lines).encode()
    data = np.random.default_rng(0).integers(-1000, 1000, (n, n)).astype("<i2").tobytes()
    path.write_bytes(header + data)
    return path


def _rough(n=32, seed=1):
    return np.random.default_rng(seed).normal(size=(n, n))


def _raises(match_text, func, *args, **kwargs):
    """Call and check the one-line message (compared literally)."""
    with pytest.raises(InputFileError) as info:
        func(*args, **kwargs)
    message = str(info.value)
    assert "\n" not in message, "the message is not one line"
    assert match_text in message, f"{match_text!r} not in {message!r}"
    return message


# --- Bad inputs: one line each ---------------------------------------------------------

def test_missing_file(tmp_path):
    path = tmp_path / "nope.di"
    assert _raises(": no such file", from_topography, path) == f"{path}: no such file"


def test_unknown_format(tmp_path):
    path = tmp_path / "junk.dat"
    path.write_bytes(bytes(range(256)) * 4)
    msg = _raises("unknown or unreadable file format", from_topography, path)
    assert msg.startswith(str(path))


def test_line_scan(tmp_path):
    path = tmp_path / "line.nc"
    ST.UniformLineScan(np.arange(32.0) ** 1.5, 1.0, unit="µm").to_netcdf(str(path))
    _raises("is a line scan (1-D), not an areal topography", from_topography, path)


def test_no_height_channel(tmp_path):
    path = _mi(tmp_path / "deflection.mi", "V", "Deflection")
    assert _raises("no height channel", from_topography, path) == \
        f"{path}: no height channel (channels: 'Deflection')"
    _raises("channel 'Deflection' holds deflection data, not heights",
            from_topography, path, channel=0)
    _raises("no channel 'Height'", from_topography, path, channel="Height")
    _raises("channel index 3 out of range", from_topography, path, channel=3)


def test_height_channel_of_mi_file(tmp_path):
    path = _mi(tmp_path / "height.mi", "um", "Topography")
    s = from_topography(path, detrend=None)
    assert s.unit == "µm" and s.n == 16 and s.length == pytest.approx(1.0)


def test_mostly_missing(tmp_path):
    h = np.ma.masked_array(_rough(16), mask=np.zeros((16, 16), bool))
    h.mask[:8] = True
    path = _nc(tmp_path / "half.nc", h)
    assert _raises("are undefined", from_topography, path) == (
        f"{path}: 128 of 256 pixels (50.00 %) are undefined, more than max_missing = 0.05")


def test_all_missing(tmp_path):
    h = np.ma.masked_array(_rough(16), mask=np.ones((16, 16), bool))
    path = _nc(tmp_path / "none.nc", h)
    _raises("all 256 pixels are undefined", from_topography, path, max_missing=1.0)


def test_missing_without_fill(tmp_path):
    h = np.ma.masked_array(_rough(16), mask=np.zeros((16, 16), bool))
    h.mask[5, 7] = True
    path = _nc(tmp_path / "one.nc", h)
    _raises("1 pixels are undefined; pass fill='harmonic' to fill them",
            from_topography, path, fill=None)


def test_harmonic_fill_is_exact_on_a_plane(tmp_path):
    x, y = np.meshgrid(np.arange(16.0), np.arange(16.0), indexing="ij")
    h = np.ma.masked_array(0.3 * x - 0.2 * y, mask=np.zeros((16, 16), bool))
    h.mask[[3, 9, 9], [4, 9, 10]] = True
    path = _nc(tmp_path / "plane.nc", h)
    s = from_topography(path, detrend=None)
    expect = -(0.3 * x - 0.2 * y)
    np.testing.assert_allclose(s.heights, expect - expect.mean(), atol=1e-12)
    assert s.record["undefined_pixels"] == 3 and s.record["fill"] == "harmonic"


def test_non_square_pixels(tmp_path):
    path = _nc(tmp_path / "rect.nc", _rough(16), sizes=(1.0, 2.0))
    assert _raises("pixels are not square", from_topography, path) == (
        f"{path}: pixels are not square (0.0625 µm x 0.125 µm); pass interpolate=True "
        f"to resample")


def test_non_square_pixels_interpolated_exactly_on_a_plane(tmp_path):
    nx, ny = 24, 16
    dx, dy = 1.0 / nx, 1.5 / ny
    x, y = np.meshgrid(dx * np.arange(nx), dy * np.arange(ny), indexing="ij")
    path = _nc(tmp_path / "rect.nc", 2.0 * x + 3.0 * y, sizes=(1.0, 1.5))
    s = from_topography(path, detrend=None, interpolate=True, n=12)
    assert s.n == 12 and s.length == pytest.approx(1.0) and s.record["interpolated"] == 1
    step = 1.0 / 12
    xs = np.arange(12) * step
    ys = s.record["window_y0"] + np.arange(12) * step
    expect = -(2.0 * xs[:, None] + 3.0 * ys[None, :])
    np.testing.assert_allclose(s.heights, expect - expect.mean(), atol=1e-12)
    _raises("fewer than the requested 64 cells", from_topography, path, detrend=None,
            interpolate=True, n=64)


def test_no_physical_size(tmp_path):
    path = tmp_path / "raw.npy"
    np.save(path, _rough(16))
    assert _raises("gives no physical size", from_topography, path) == (
        f"{path}: the file gives no physical size; pass length= (the scan's extent along x)")
    s = from_topography(path, length=2.0, unit="um", detrend=None)
    assert s.length == 2.0 and s.unit == "µm"
    assert s.record["physical_size_source"] == "argument"


def test_length_cannot_override_the_file(tmp_path):
    path = _nc(tmp_path / "a.nc", _rough(16))
    _raises("length= cannot override it", from_topography, path, length=3.0)


def test_scan_smaller_than_grid(tmp_path):
    path = _nc(tmp_path / "small.nc", _rough(16))
    assert _raises("is smaller than", from_topography, path, n=32) == (
        f"{path}: the scan (16 x 16 pixels) is smaller than the requested window of "
        f"32 x 32 pixels at (-8, -8)")
    _raises("is smaller than", from_topography, path, n=8, coarsen=4)


def test_constant_heights(tmp_path):
    path = _nc(tmp_path / "flat.nc", np.full((16, 16), 2.5))
    _raises("heights are constant", from_topography, path)
    x, y = np.meshgrid(np.arange(16.0), np.arange(16.0), indexing="ij")
    path = _nc(tmp_path / "tilted.nc", 1.0 + 0.1 * x - 0.3 * y)
    _raises("heights are constant after levelling (detrend='height'", from_topography, path)
    assert from_topography(path, detrend=None).sq > 0


@pytest.mark.parametrize("kwargs, text", [
    (dict(detrend="plane"), "detrend must be one of"),
    (dict(fill="nearest"), "fill must be 'harmonic' or None"),
    (dict(max_missing=1.5), "max_missing must be a number with 0 <= max_missing <= 1"),
    (dict(coarsen=0), "coarsen must be an integer >= 1"),
    (dict(n=4), "n must be an integer >= 8"),
    (dict(unit="furlong"), "unit must be one of"),
    (dict(window=(0, 0)), "window must be (x0, y0, side)"),
    (dict(align="z"), "align must be 'x', 'y' or None"),
])
def test_bad_arguments(tmp_path, kwargs, text):
    path = _nc(tmp_path / "a.nc", _rough(16))
    with pytest.raises(ValueError) as info:
        from_topography(path, **kwargs)
    assert text in str(info.value) and "\n" not in str(info.value)


# --- What it does ----------------------------------------------------------------------

@pytest.mark.parametrize("writer", ["to_netcdf", "to_x3p"])
def test_round_trip_is_identical(tmp_path, writer):
    n, length = 32, 2.0
    z = surfaces.self_affine(n, hurst=0.8, h_rms=0.01, length=length, seed=4)
    path = tmp_path / ("s.nc" if writer == "to_netcdf" else "s.x3p")
    measured = ST.Topography(-z, (length, length), unit="mm")   # the instrument sees h = −z
    getattr(measured, writer)(str(path))
    s = from_topography(path, detrend=None, unit="mm")   # X3P stores metres (ISO 5436-2)
    assert s.unit == "mm" and s.length == pytest.approx(length, rel=1e-15) and s.n == n
    np.testing.assert_allclose(s.heights, z, rtol=0, atol=4e-16 * np.abs(z).max())
    a = bem.solve(z, force=1e-3, length=length, e_star=1.0, periodic=True)
    b = bem.solve(s.heights, force=1e-3, length=length, e_star=1.0, periodic=True)
    np.testing.assert_array_equal(a.contact, b.contact)
    np.testing.assert_allclose(b.pressure, a.pressure, rtol=1e-9, atol=1e-12 * a.pressure.max())
    assert b.depth == pytest.approx(a.depth, rel=1e-9)
    assert bem.stiffness(b) == pytest.approx(bem.stiffness(a), rel=1e-9)


def test_sign_peaks_touch_first(tmp_path):
    h = _rough(32)
    h[10, 20] = 50.0                                  # the highest peak of the scan
    s = from_topography(_nc(tmp_path / "peak.nc", h), detrend=None)
    assert np.unravel_index(np.argmin(s.heights), s.heights.shape) == (10, 20)
    assert abs(s.heights.mean()) < 1e-12 and not s.heights.flags.writeable


def test_window_coarsen_units(tmp_path):
    h = _rough(64)
    path = _nc(tmp_path / "a.nc", h, sizes=(6.4, 6.4), unit="µm")   # 0.1 µm pixels
    s = from_topography(path, detrend=None, window=(1000, 2000, 3200), coarsen=2, unit="nm")
    block = h[10:42, 20:52].reshape(16, 2, 16, 2).mean(axis=(1, 3)) * 1000.0
    np.testing.assert_allclose(s.heights, -(block - block.mean()), rtol=1e-12, atol=1e-9)
    assert (s.n, s.unit) == (16, "nm") and s.length == pytest.approx(3200.0)
    assert (s.record["window_i0"], s.record["window_j0"], s.record["window_pixels"]) == \
        (10, 20, 32)
    _raises("the window does not hold n*coarsen = 16 whole pixels", from_topography, path,
            window=(1.0, 2.0, 3.2), n=8, coarsen=2, detrend=None)
    resampled = from_topography(path, window=(1.0, 2.0, 3.2), n=8, interpolate=True)
    assert resampled.n == 8 and resampled.record["interpolated"] == 1


def test_record_is_flat_netcdf_attributes(tmp_path):
    x = np.arange(32.0)[:, None] * np.ones(32)
    s = from_topography(_nc(tmp_path / "a.nc", _rough(32) + 0.5 * x))
    r = s.record
    assert all(isinstance(k, str) and isinstance(v, (str, int, float)) and
               not isinstance(v, bool) for k, v in r.items())
    assert r["detrend"] == "height" and r["detrend_coefficients"] == 3
    assert r["detrend_coefficient_1"] == pytest.approx(0.5 * 32, rel=0.05)  # x/L_x units
    assert r["sq_raw"] > r["sq_levelled"] and r["sq"] == pytest.approx(s.sq)
    from scipy.io import netcdf_file
    with netcdf_file(tmp_path / "attrs.nc", "w") as f:
        for k, v in r.items():
            setattr(f, k, v)


def test_topography_object_source():
    z = surfaces.self_affine(16, hurst=0.5, h_rms=1.0, seed=2)
    s = from_topography(ST.Topography(-z, (1.0, 1.0)), detrend=None, unit="m")
    np.testing.assert_allclose(s.heights, z, atol=1e-14)
    assert s.unit == "m" and s.record["format"] == "object"


def test_tiles_and_edge_jump(tmp_path):
    z = surfaces.self_affine(64, hurst=0.8, h_rms=1.0, seed=9)
    s = from_topography(ST.Topography(-z, (4.0, 4.0), unit="µm"), detrend=None)
    parts = tiles(s, 16)
    assert len(parts) == 16 and all(isinstance(p, MeasuredSurface) for p in parts)
    assert all(p.n == 16 and p.length == pytest.approx(1.0) for p in parts)
    assert all(abs(p.heights.mean()) < 1e-12 for p in parts)
    p5 = parts[5]
    assert (p5.record["tile_i0"], p5.record["tile_j0"]) == (16, 16)
    block = s.heights[16:32, 16:32]
    np.testing.assert_allclose(p5.heights, block - block.mean(), atol=1e-14)
    with pytest.raises(ValueError, match="size must be <= n = 64"):
        tiles(s, 128)
    periodic = edge_jump(s)                  # a periodic surface: the seam is a neighbour
    assert periodic.is_periodic_like and periodic.edge < 1.5 * periodic.neighbour
    cut = edge_jump(parts[0])                # a cut of it is not periodic
    assert not cut.is_periodic_like and cut.edge_ratio > 3 * cut.neighbour_ratio


# --- The real scans --------------------------------------------------------------------

@needs_shared
def test_shared_scans_match_their_readme():
    di = from_topography(SHARED / "di-6.di", unit="nm")
    assert (di.n, di.length, di.unit) == (512, pytest.approx(10000.0), "nm")
    assert di.sq == pytest.approx(14.3, abs=0.05)
    assert di.record["channel"] == "Height#1" and di.record["format"] == "di"
    opd = from_topography(SHARED / "opd-1.opd", unit="nm")
    assert opd.record["undefined_pixels"] == 116 and opd.record["fill"] == "harmonic"
    assert (opd.record["nb_grid_pts_x"], opd.record["nb_grid_pts_y"]) == (640, 480)
    assert opd.record["sq_levelled"] == pytest.approx(6.7, abs=0.05)
    assert opd.n == 480 and opd.record["window_i0"] == 80
    ps = from_topography(SHARED / "example_ps.tiff", unit="nm")
    assert ps.sq == pytest.approx(3.9, abs=0.05) and ps.length == pytest.approx(1000.0)


@needs_shared
def test_shared_channels_and_bad_limits():
    path = SHARED / "di-6.di"
    assert _raises("2 channels are named 'Height'", from_topography, path,
                   channel="Height").endswith("pick one by id ('Height#1', 'Height#2') or index")
    assert from_topography(path, channel="Height#2", n=64).record["channel_index"] == 1
    _raises("channel 'Phase' has no length unit", from_topography, path, channel=2)
    _raises("is smaller than the requested window of 1024 x 1024", from_topography, path,
            n=1024)
    _raises("116 of 307200 pixels (0.04 %) are undefined, more than max_missing = 0.0001",
            from_topography, SHARED / "opd-1.opd", max_missing=1e-4)
    aligned = from_topography(path, align="x", n=64)
    assert aligned.record["scan_line_alignment"].startswith("x")


@needs_shared
def test_opd_edge_jump_of_a_257_crop():
    """A measured scan is not periodic (README: 1.29 Sq across the edge vs 0.55 Sq).

    Centred 257² crop after whole-scan harmonic fill and tilt removal: the seam jump is
    1.12 Sq, the neighbour jump 0.38 Sq per direction, and √(⟨Δx²⟩+⟨Δy²⟩) = 0.54 Sq (the
    README's 0.55 matches this gradient form); the corner crop gives a seam of 1.38 Sq.
    """
    s = from_topography(SHARED / "opd-1.opd", n=257)
    jump = edge_jump(s)
    assert jump.edge_ratio == pytest.approx(1.12, abs=0.01)
    assert jump.neighbour_ratio == pytest.approx(0.377, abs=0.005)
    assert jump.gradient / jump.sq == pytest.approx(0.535, abs=0.01)
    assert not jump.is_periodic_like
    dx = s.record["pixel_size_x"]
    corner = edge_jump(from_topography(SHARED / "opd-1.opd", window=(0, 0, 257 * dx)))
    assert corner.edge_ratio == pytest.approx(1.37, abs=0.01)
    assert re.fullmatch(r"Raw", s.record["channel"])
