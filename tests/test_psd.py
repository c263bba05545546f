"""Spectrum tables (module roughcontact.surfaces.psd): reading, checking, surfaces."""

import numpy as np
import pytest

from roughcontact import surfaces
from roughcontact.surfaces.psd import (
    CE_SERIES,
    grid_spectrum,
    read_psd,
    surface_from_psd,
)

N, LENGTH, HURST = 64, 2.0, 0.7


def _grid_q(n=N, length=LENGTH):
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=length / n)
    return np.hypot(q1[:, None], q1[None, :])


def _self_affine_table(c0=3.0, hurst=HURST, rows=40):
    """C2D = c0 q^(-2H-2) on log-spaced q covering every nonzero mode of the grid."""
    q = np.geomspace(2 * np.pi / LENGTH * 0.999, np.pi * N / LENGTH * np.sqrt(2) * 1.001, rows)
    return q, c0 * q ** (-2 - 2 * hurst)


def test_rms_height_and_slope_are_the_closed_form_sums():
    q, c = _self_affine_table()
    h = surface_from_psd(q, c, N, length=LENGTH, seed=5)
    qq = _grid_q()
    exact = np.zeros_like(qq)
    exact[qq > 0] = 3.0 * qq[qq > 0] ** (-2 - 2 * HURST)
    assert np.sqrt(np.mean(h ** 2)) == pytest.approx(np.sqrt(exact.sum()) / LENGTH, rel=1e-12)
    assert abs(h.mean()) < 1e-14
    a = np.fft.fft2(h) / N ** 2                         # h = Σ a_q exp(iq·x)
    slope = np.sqrt(np.sum(qq ** 2 * np.abs(a) ** 2))
    assert slope == pytest.approx(np.sqrt(np.sum(qq ** 2 * exact)) / LENGTH, rel=1e-12)
    # finite differences see the same slope up to the lattice's sin(qΔ/2)/(qΔ/2) factor
    gx = np.diff(h, axis=0, append=h[:1]) / (LENGTH / N)
    assert np.sqrt(2 * np.mean(gx ** 2)) == pytest.approx(slope, rel=0.25)


def test_same_phases_as_self_affine():
    q, c = _self_affine_table()
    h = surface_from_psd(q, c, N, length=LENGTH, seed=11)
    ref = surfaces.self_affine(N, hurst=HURST, h_rms=1.0, length=LENGTH, seed=11)
    np.testing.assert_allclose(h / np.sqrt(np.mean(h ** 2)), ref, atol=1e-12)


def test_conventions_agree():
    q, c = _self_affine_table()
    base = surface_from_psd(q, c, 32, length=LENGTH, seed=1)
    ce = surface_from_psd(q, q / np.pi * c, 32, length=LENGTH, seed=1, convention="q/pi*c2d")
    persson = surface_from_psd(q, c / (2 * np.pi) ** 2, 32, length=LENGTH, seed=1,
                               convention="persson")
    np.testing.assert_allclose(ce, base, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(persson, base, rtol=1e-12, atol=1e-15)


def test_zero_outside_the_table():
    q = np.array([10.0, 20.0])
    c2d = grid_spectrum(q, np.array([1.0, 0.25]), N, length=LENGTH)
    qq = _grid_q()
    assert np.all(c2d[(qq < 10 * (1 - 1e-9)) | (qq > 20 * (1 + 1e-9))] == 0)
    inside = (qq >= 10) & (qq <= 20)
    np.testing.assert_allclose(c2d[inside], (qq[inside] / 10) ** -2, rtol=1e-12)  # log-log
    with pytest.raises(ValueError, match="holds no mode of the grid"):
        surface_from_psd([1e4, 2e4], [1.0, 1.0], N, length=LENGTH)


def test_read_plain_table_with_header(tmp_path):
    q, c = _self_affine_table(rows=8)
    path = tmp_path / "psd.csv"
    path.write_text("# my spectrum\nq (1/um), C (um^4)\n" +
                    "".join(f"{float(a)!r}, {float(b)!r}\n" for a, b in zip(q, c)))
    table = read_psd(path)
    np.testing.assert_array_equal(table.q, q)
    np.testing.assert_array_equal(table.c, c)
    assert table.unit == "um" and table.series == ""
    bare = tmp_path / "bare.txt"
    bare.write_text("".join(f"{float(a)!r} {float(b)!r}\n" for a, b in zip(q, c)))
    assert read_psd(bare).unit is None
    np.testing.assert_allclose(read_psd(bare, convention="persson").c, (2 * np.pi) ** 2 * c)


def _ce_export(path, q, y, extra_series=True):
    cols = ["Subject type", "Subject name", "Creator", "Instrument name", "Instrument type",
            "Instrument parameters", "Function name", "Data series", "Wavevector (1/m)",
            "PSD (m³)", "standard error of PSD (m³)", "comment"]
    lines = [";".join(cols)]
    series = [("1D PSD along x", y * 2)] if extra_series else []
    series += [(CE_SERIES, y), (CE_SERIES + " (incl. unreliable data)", y)]
    for name, ys in series:
        for a, b in zip(q, ys):
            lines.append(f'measurement;scan 1;someone;AFM;microscope-based;"{{""tip"": 1}}";'
                         f"Power spectrum;{name};{float(a)!r};{float(b)!r};;")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_read_contact_engineering_export(tmp_path):
    q = np.geomspace(1e6, 1e9, 7)
    c2d = 1e-40 * q ** -3.6
    path = _ce_export(tmp_path / "power-spectrum.csv", q, q / np.pi * c2d)
    table = read_psd(path)
    np.testing.assert_allclose(table.q, q, rtol=1e-15)
    np.testing.assert_allclose(table.c, c2d, rtol=1e-14)
    assert table.unit == "m" and table.series == CE_SERIES
    with pytest.raises(ValueError, match="is a 1D PSD"):
        read_psd(path, series="1D PSD along x")
    with pytest.raises(ValueError, match="no rows of series 'nope'"):
        read_psd(path, series="nope")


@pytest.mark.parametrize("rows, line, text", [
    (["1 2", "2 0", "3 1"], 2, "C = 0 is not > 0"),
    (["1 2", "2 -1", "3 1"], 2, "C = -1 is not > 0"),
    (["-1 2", "2 1"], 1, "q = -1 is not > 0"),
    (["0 2", "2 1"], 1, "q = 0 is not > 0"),
    (["1 2", "2 nan"], 2, "C = nan is not finite"),
    (["1 2", "inf 1"], 2, "q = inf is not finite"),
    (["1 2", "3 1", "2 1"], 3, "q = 2 is not greater than the previous q = 3 (q must increase strictly)"),
    (["1 2", "1 1"], 2, "q = 1 is not greater than the previous q = 1 (q must increase strictly)"),
    (["1 2", "2 abc"], 2, "C 'abc' is not a number"),
    (["1 2", "2"], 2, "expected two columns q and C, got 1"),
])
def test_bad_rows(tmp_path, rows, line, text):
    path = tmp_path / "bad.txt"
    path.write_text("\n".join(rows) + "\n")
    with pytest.raises(ValueError) as info:
        read_psd(path)
    assert str(info.value) == f"{path}: row {line}: {text}"


def test_bad_rows_of_an_export_name_the_file_line(tmp_path):
    q = np.geomspace(1e6, 1e9, 4)
    y = np.array([1e-20, 1e-21, -1e-22, 1e-23])
    path = _ce_export(tmp_path / "x.csv", q, y, extra_series=False)
    with pytest.raises(ValueError) as info:
        read_psd(path)
    assert str(info.value) == f"{path}: row 4: C = -1e-22 is not > 0"


def test_missing_and_empty_files(tmp_path):
    with pytest.raises(ValueError, match="no such file"):
        read_psd(tmp_path / "none.csv")
    empty = tmp_path / "empty.csv"
    empty.write_text("# nothing\n")
    with pytest.raises(ValueError, match="no data rows"):
        read_psd(empty)
    one = tmp_path / "one.csv"
    one.write_text("1, 2\n")
    with pytest.raises(ValueError, match="one row only"):
        read_psd(one)
