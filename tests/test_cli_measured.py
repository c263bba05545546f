"""``roughcontact measured``: one tile of a measured scan in physical units from the command line.

A synthetic 64² scan (0.1 µm pixels, written with SurfaceTopography's NetCDF writer as in
``tests/test_measured_pipeline.py``) pressed by the subcommand gives the file the pipeline's
jobs (:func:`roughcontact.study.runs.measured.prepare_surface`, :func:`~roughcontact.study.runs.measured.run_job`)
write for the same resolved config; each bad input exits 2 with one line and writes nothing.
"""
from __future__ import annotations

import tempfile

import numpy as np
import pytest

ST = pytest.importorskip("SurfaceTopography")
xr = pytest.importorskip("xarray")

from roughcontact import cli, surfaces
from roughcontact.study.config import resolve as config, schema
from roughcontact.study.runs import measured
from roughcontact.study.config.settings import ForceRange, UnitSettings

E_STAR = 100.0   # GPa
PIXEL = 0.1      # um
SPHERE = {"from": 1e-5, "to": 3e-3, "count": 4}
FLAT = {"from": 1e-3, "to": 1e-2, "count": 3}


@pytest.fixture
def scan(tmp_path):
    """A 64² scan of 0.1 µm pixels in µm, rms 10 nm."""
    h = surfaces.self_affine(64, hurst=0.8, h_rms=0.01, length=64 * PIXEL, seed=3)
    path = tmp_path / "scan.nc"
    ST.Topography(h, (64 * PIXEL, 64 * PIXEL), unit="µm").to_netcdf(str(path))
    return path


@pytest.fixture
def clean_tmp(tmp_path, monkeypatch):
    """The directory of the subcommand's temporary files (checked empty afterwards)."""
    where = tmp_path / "tmpdir"
    where.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(where))
    return where


def _args(scan, out, radius=20.0, index=1, rng=SPHERE, *extra):
    return ["measured", str(scan), "--unit", "um", "--detrend", "none", "--tile", "32", "--index", str(index),
            "--radius", str(radius), "--e-star", str(E_STAR), "--e-star-unit", "GPa",
            "--force-from", str(rng["from"]), "--force-to", str(rng["to"]), "--force-count", str(rng["count"]),
            "-o", str(out), "-q", *extra]


@pytest.mark.parametrize("radius, index, rng", [(20.0, 1, SPHERE), (float("inf"), 2, FLAT)])
def test_same_file_as_the_pipeline_job(scan, tmp_path, clean_tmp, radius, index, rng):
    """The pipeline's job functions on the config the pipeline resolves for this scan, and the
    subcommand: the same code on the same arrays in one process, so the numbers are identical
    (compared with rtol = 1e-12, room only for a change of summation order, none expected; a
    different tile, unit factor or load path differs by percent) and so is the job's record."""
    kind = "sphere" if radius < float("inf") else "flat"
    cfg = config.resolve_config({
        "units": {"length": "um", "e_star": "GPa"}, "e_star": E_STAR, "tile": 32, "hurst": [], "h_rms": [],
        "radius": [radius], "forces": {kind: rng}, "topography": [{"file": "scan.nc", "detrend": "none"}]},
        base_dir=tmp_path)
    surface = tmp_path / "surface.nc"
    measured.prepare_surface(cfg["topography"][0], surface, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    expected = tmp_path / "pipeline.nc"
    measured.run_job(measured.job_of(cfg, "topography", "scan", radius, index), surface, expected)

    out = tmp_path / "cli" / "run.nc"
    assert cli.main(_args(scan, out, radius, index, rng)) == 0
    assert not any(clean_tmp.iterdir()), "the prepared surface was left behind"
    with xr.open_dataset(out) as a, xr.open_dataset(expected) as b:
        for name in ("stiffness", "stiffness_normalized", "depth", "contact_area", "force", "force_normalized"):
            np.testing.assert_allclose(a[name].values, b[name].values, rtol=1e-12, err_msg=name)
        np.testing.assert_array_equal(a["contact_cells"].values, b["contact_cells"].values)
        assert a.attrs["config"] == b.attrs["config"] and a.attrs["config_hash"] == b.attrs["config_hash"]
        assert a.attrs["half_space"] == b.attrs["half_space"]


def test_output_has_cf_units_in_newtons(scan, tmp_path, clean_tmp):
    out = tmp_path / "run.nc"
    assert cli.main(_args(scan, out)) == 0
    with xr.open_dataset(out) as ds:
        assert ds["force"].attrs["units"] == "N" and ds["stiffness"].attrs["units"] == "N m-1"
        assert ds["force_normalized"].attrs["units"] == "1" and ds["stiffness_normalized"].attrs["units"] == "1"
        assert ds["depth"].attrs["units"] == "um" and ds["contact_area"].attrs["units"] == "um2"
        assert ds.attrs["units_length"] == "um" and ds.attrs["e_star_units"] == "GPa"
        length = float(ds.attrs["length"])   # the tile's side, 3.2 µm (float32 in the scan file)
        assert length == pytest.approx(32 * PIXEL, rel=1e-6)
        # 1 GPa µm² = 1e9 Pa * 1e-12 m² = 1e-3 N; 1 GPa µm = 1e3 N/m
        normalized = np.geomspace(SPHERE["from"], SPHERE["to"], SPHERE["count"])
        np.testing.assert_allclose(ds["force_normalized"].values, normalized, rtol=1e-12)
        np.testing.assert_allclose(ds["force"].values, normalized * E_STAR * length**2 * 1e-3, rtol=1e-12)
        np.testing.assert_allclose(ds["stiffness"].values, ds["stiffness_normalized"].values * E_STAR * length * 1e3,
                                   rtol=1e-12)
        assert np.all(np.diff(ds["stiffness"].values) > 0)


def _bad(capsys, argv, out):
    code = cli.main(argv)
    err = capsys.readouterr().err
    assert code == 2, f"exit {code}: {err!r}"
    assert len(err.strip().splitlines()) == 1, f"not one line: {err!r}"
    assert err.startswith("roughcontact measured: invalid argument: "), err
    assert not out.exists() and not list(out.parent.glob(f".{out.name}.tmp-*")), "a file was written"
    return err


@pytest.mark.parametrize("change, needle", [
    ({"scan": "missing.nc"}, "SCAN (topography[0].file) = "),
    ({"--unit": "inch"}, "--unit (units.length) = 'inch' is not allowed; allowed: one of m, mm, um, nm"),
    ({"--e-star-unit": "psi"}, "--e-star-unit (units.e_star) = 'psi' is not allowed"),
    ({"--detrend": "wavy"}, "--detrend (topography[0].detrend) = 'wavy' is not allowed"),
    ({"--index": "4"}, "--index 4: the scan scan.nc has 4 tile(s) of tile = 32; allowed: 0 <= --index <= 3"),
    ({"--index": "-1"}, "--index -1: the scan scan.nc has 4 tile(s)"),
    ({"--tile": "8"}, "--tile (tile) = 8 is not allowed"),
    ({"--tile": "128"}, "fewer than a tile of tile = 128"),
    ({"--e-star": "nan"}, "--e-star (e_star) = nan is not allowed"),
    ({"--force-to": "0.5"}, "loads whose contact would reach the scan's edge"),
])
def test_bad_input_exits_2_with_one_line(scan, tmp_path, clean_tmp, capsys, change, needle):
    out = tmp_path / "out" / "run.nc"
    argv = _args(scan, out, 20.0, 1, {**SPHERE, "from": 1e-3})
    for flag, value in change.items():
        if flag == "scan":
            argv[1] = str(tmp_path / value)
        else:
            argv[argv.index(flag) + 1] = value
    err = _bad(capsys, argv, out)
    assert needle in err, err
    assert not any(clean_tmp.iterdir()), "the prepared surface was left behind"


def test_unreadable_scan(tmp_path, clean_tmp, capsys):
    bad = tmp_path / "bad.nc"
    bad.write_bytes(bytes(range(256)) * 4)
    out = tmp_path / "run.nc"
    assert "unknown or unreadable file format" in _bad(capsys, _args(bad, out), out)


def test_edge_message_names_the_flag(scan, tmp_path, clean_tmp, capsys):
    out = tmp_path / "run.nc"
    err = _bad(capsys, _args(scan, out, 20.0, 0, {"from": 1e-3, "to": 0.5, "count": 3}), out)
    assert "lower --force-to to 0.001 (F = 0.001024 N) or below" in err, err


def test_units_spelled_with_mu(scan):
    args = cli.build_parser().parse_args(["measured", str(scan), "--unit", "µm", "--radius", "inf", "--e-star", "1",
                                          "--e-star-unit", "MPa", "-o", "x.nc"])
    study = cli.measured_study_from_args(args)
    assert study.units == UnitSettings(length="um", e_star="MPa"), study.units
    assert study.tile is None, study.tile
    default = schema.default_of(schema.load_schema(None), ["forces", "flat"])
    assert study.forces["flat"] == ForceRange(default["from"], default["to"], default["count"]), \
        "the schema's defaults"


def test_measured_is_a_documented_command():
    assert "measured" in cli.COMMANDS
    text = cli.build_parser()._subparsers._group_actions[0].choices["measured"].format_help()
    assert "F/(E* L^2)" in text and "N/m" in text


# --- physical units at the command line -------------------------------------------------------

def _run(argv):
    assert cli.main(argv) == 0, f"roughcontact {' '.join(argv)} failed"


def test_forces_in_a_unit_are_the_forces_of_the_file(scan, tmp_path, clean_tmp):
    """--force-unit mN: the file's force (N) is the given load path (geometric, 1e-3 N per mN)."""
    out = tmp_path / "run.nc"
    argv = _args(scan, out, 20.0, 1, {"from": 1e-4, "to": 1e-2, "count": 3}, "--force-unit", "mN")
    _run(argv)
    with xr.open_dataset(out) as ds:
        np.testing.assert_allclose(ds["force"].values, [1e-7, 1e-6, 1e-5], rtol=1e-12, err_msg="force in N")


def test_forces_in_a_unit_equal_their_normalised_path(scan, tmp_path, clean_tmp):
    """The same loads given in µN and as F/(E* L^2), L = 32 cells of 0.1 µm, E* = 100 GPa:
    F/(E* L^2) = F / (1e11 Pa x (3.2e-6 m)^2), so the same stiffnesses to 1e-12."""
    unit_force = E_STAR * 1e9 * (32 * PIXEL * 1e-6) ** 2          # N per F/(E* L^2)
    normalised = {"from": 1e-4, "to": 3e-3, "count": 3}
    micro = {"from": normalised["from"] * unit_force / 1e-6, "to": normalised["to"] * unit_force / 1e-6, "count": 3}
    a, b = tmp_path / "a.nc", tmp_path / "b.nc"
    _run(_args(scan, a, 20.0, 1, normalised))
    _run(_args(scan, b, 20.0, 1, micro, "--force-unit", "µN"))
    with xr.open_dataset(a) as one, xr.open_dataset(b) as other:
        np.testing.assert_allclose(other["stiffness"].values, one["stiffness"].values, rtol=1e-9,
                                   err_msg="the same loads in two units")


def test_e_star_from_two_bodies(scan, tmp_path, clean_tmp):
    """--e1 210 --nu1 0.3 --e2 210 --nu2 0.3 (GPa): E* = 210/1.82 GPa in the file's provenance."""
    out = tmp_path / "run.nc"
    argv = _args(scan, out, 20.0, 1, SPHERE)
    i = argv.index("--e-star")
    argv[i:i + 2] = ["--e1", "210", "--nu1", "0.3", "--e2", "210", "--nu2", "0.3"]
    _run(argv)
    with xr.open_dataset(out) as ds:
        assert ds.attrs["e_star"] == pytest.approx(210 / 1.82, rel=1e-14), f"E* = {ds.attrs['e_star']}"


def test_progress_lines_in_the_force_unit(scan, tmp_path, clean_tmp, capsys):
    out = tmp_path / "run.nc"
    argv = [a for a in _args(scan, out, 20.0, 1, {"from": 1e-4, "to": 1e-2, "count": 3}, "--force-unit", "mN")
            if a != "-q"]
    _run(argv)
    err = capsys.readouterr().err
    assert "F = 0.01 mN" in err and "N/m" in err, f"progress lines: {err!r}"


@pytest.mark.parametrize("change, needle", [
    (["--e1", "210"], "--e-star (e_star) is given twice: --e-star and --e1"),
    (["--force-unit", "kN"], "--force-unit (force_unit) = 'kN' is not allowed; allowed: one of N, mN, uN, nN"),
])
def test_bad_units_exit_2_with_one_line(scan, tmp_path, clean_tmp, capsys, change, needle):
    out = tmp_path / "out" / "run.nc"
    err = _bad(capsys, _args(scan, out, 20.0, 1, SPHERE, *change), out)
    assert needle in err, err


def test_poisson_ratio_out_of_range_names_its_flag(scan, tmp_path, clean_tmp, capsys):
    out = tmp_path / "out" / "run.nc"
    argv = _args(scan, out, 20.0, 1, SPHERE)
    i = argv.index("--e-star")
    argv[i:i + 2] = ["--e1", "210", "--nu1", "0.7"]
    err = _bad(capsys, argv, out)
    assert "--nu1 (e_star.nu1) = 0.7 is not allowed" in err, err
