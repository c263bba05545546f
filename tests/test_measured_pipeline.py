"""The measured stage (roughcontact.study.runs.measured, workflow/rules/measured.smk).

A synthetic scan written with SurfaceTopography's NetCDF writer goes through the real
``snakemake`` (about 40 s on 2 cores), a power-law spectrum table through the same jobs in this
process; the merged files are checked for
their dimensions, CF units and provenance, and k(F) of every tile against the same heights
pressed directly with :mod:`roughcontact.bem`. The config- and job-level bad inputs each give
one line and write nothing.
"""
from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from browser import needs_chromium, report_page

ST = pytest.importorskip("SurfaceTopography")

from roughcontact import bem, surfaces
from roughcontact.errors import ConfigError, IndentError, InputFileError
from roughcontact.study.config import resolve as config
from roughcontact.study.analysis.measured_merge import merge_surface
from roughcontact.study.runs import measured
from roughcontact.study.files.io import read_groups

#: runs the Snakemake workflow end to end (left out of the quick subset: -m "not workflow")
pytestmark = pytest.mark.workflow

ROOT = Path(__file__).resolve().parents[1]
SHARED = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES", ROOT.parent / "shared" / "topographies"))
UNITS = {"length": "um", "e_star": "GPa"}
E_STAR = 100.0   # GPa
PIXEL = 0.1      # um


def _scan(path, n=64, seed=3):
    """A 64² scan of 0.1 µm pixels in µm, rms 10 nm: its heights h (what the instrument saw)."""
    h = surfaces.self_affine(n, hurst=0.8, h_rms=0.01, length=n * PIXEL, seed=seed)
    ST.Topography(h, (n * PIXEL, n * PIXEL), unit="µm").to_netcdf(str(path))
    return h


def _psd(path, rows=None):
    """A power-law table C2D ∝ q^-3.6 (H = 0.8) in µm units, 'q (1/um), C (um^4)': on the 33²
    grid of 3.2 µm, h_rms ≈ 17 nm and rms slope ≈ 0.08 (the flat loads stay far from full contact)."""
    q = np.geomspace(1.0, 100.0, 30)
    rows = rows if rows is not None else zip(q, 3e-3 * q ** -3.6)
    path.write_text("q (1/um), C (um^4)\n" + "".join(f"{float(a)!r}, {float(b)!r}\n" for a, b in rows))
    return path


def _cfg(**extra):
    base = {"units": UNITS, "e_star": E_STAR, "radius": [20.0, float("inf")], "tile": 32,
            "forces": {"sphere": {"from": 1e-5, "to": 3e-3, "count": 4},
                       "flat": {"from": 1e-3, "to": 1e-2, "count": 3}},
            "fit": {"bootstrap": 200, "spectrum": {"band": [1.6, 0.25]}}}
    return {**base, **extra}


def _one_line(err) -> str:
    text = str(err.value)
    assert "\n" not in text, text
    return text


# --- config errors: one line naming the key ------------------------------------------------

@pytest.mark.parametrize("changes, needle", [
    ({"topography": ["nope.nc"]}, "config key 'topography[0].file' = 'nope.nc': no such file"),
    ({"topography": ["scan.nc"], "units": {"length": "um"}}, "missing config key 'units.e_star'"),
    ({"topography": ["scan.nc", {"file": "scan.nc"}]}, "config key 'topography[1]' has the name 'scan'"),
    ({"topography": [{"file": "scan.nc", "detrend": "wavy"}]}, "topography[0]"),
    ({"topography": [{"file": "scan.nc", "colour": 1}]}, "topography[0]"),
    ({"topography": ["scan.nc"], "tile": 8}, "config key 'tile' = 8"),
    ({"topography": ["scan.nc"], "units": {"length": "inch", "e_star": "GPa"}}, "units.length"),
    ({"topography": ["scan.nc"], "hurst": [0.8]}, "config key 'h_rms' is empty but 'hurst' is not"),
    ({"spectrum": ["psd.csv"]}, "missing config key 'seeds'"),
    ({"topography": []}, "missing config key 'hurst'"),
])
def test_config_errors(tmp_path, changes, needle):
    _scan(tmp_path / "scan.nc")
    _psd(tmp_path / "psd.csv")
    with pytest.raises(ConfigError) as err:
        config.resolve_config(_cfg(**changes), base_dir=tmp_path)
    assert needle in _one_line(err)


def test_config_resolves_paths_against_its_directory(tmp_path):
    _scan(tmp_path / "scan.nc")
    cfg = config.resolve_config(_cfg(topography=["scan.nc"]), base_dir=tmp_path)
    assert cfg["topography"] == [{"file": str((tmp_path / "scan.nc").resolve()), "name": "scan",
                                  "unit": None, "size": None, "detrend": "height", "interpolate": False}]
    assert cfg["hurst"] == [] and cfg["h_rms"] == [] and cfg["spectrum"] == []


def test_config_directory_is_that_of_the_last_file_naming_inputs(tmp_path):
    from roughcontact.study.config.measured import config_directory

    for sub, text in (("a", "topography: [x.nc]\n"), ("b", "spectrum: [p.csv]\n"), ("c", "hurst: [0.5]\n")):
        (tmp_path / sub).mkdir()
        (tmp_path / sub / "c.yaml").write_text(text)
    files = [tmp_path / "a/c.yaml", tmp_path / "b/c.yaml", tmp_path / "c/c.yaml", tmp_path / "missing.yaml"]
    assert config_directory(files) == str((tmp_path / "b").resolve())
    assert config_directory(files[2:]) is None


def test_generated_configs_are_unchanged():
    """Every preset resolves to what it did, plus the empty measured keys."""
    for preset in sorted((ROOT / "presets").glob("*.yaml")):
        raw = yaml.safe_load(preset.read_text())
        if "topography" in raw:
            continue
        cfg = config.resolve_config(raw)
        assert cfg["topography"] == [] and cfg["spectrum"] == [] and cfg["tile"] is None, preset
        assert cfg["units"] == {"length": None, "e_star": None}, preset


# --- job errors: one line, nothing written ---------------------------------------------------

def _resolved(tmp_path, **extra):
    return config.resolve_config(_cfg(**extra), base_dir=tmp_path)


def test_scan_smaller_than_the_tile(tmp_path):
    _scan(tmp_path / "scan.nc", n=24)
    cfg = _resolved(tmp_path, topography=["scan.nc"], tile=32)
    out = tmp_path / "out" / "surface.nc"
    with pytest.raises(InputFileError) as err:
        measured.prepare_surface(cfg["topography"][0], out, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    assert "fewer than a tile of tile = 32" in _one_line(err)
    assert not out.parent.exists() or not any(out.parent.iterdir())


def test_unreadable_scan_stops_the_config(tmp_path):
    """A file no reader knows is rejected when the configuration is resolved (check-config
    opens every scan), before any job."""
    (tmp_path / "bad.nc").write_bytes(bytes(range(256)) * 4)
    with pytest.raises(ConfigError) as err:
        _resolved(tmp_path, topography=["bad.nc"])
    assert "topography[0].file" in _one_line(err) and "unknown or unreadable file format" in _one_line(err)


def test_constant_scan(tmp_path):
    path = tmp_path / "bad.nc"
    ST.Topography(np.full((64, 64), 2.0), (6.4, 6.4), unit="µm").to_netcdf(str(path))
    cfg = _resolved(tmp_path, topography=["bad.nc"])
    out = tmp_path / "out" / "surface.nc"
    with pytest.raises(InputFileError) as err:
        measured.prepare_surface(cfg["topography"][0], out, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    assert "heights are constant" in _one_line(err)
    assert not out.exists()


def _line_scan(path):
    ST.UniformLineScan(np.arange(64.0) ** 1.5, 6.4, unit="µm").to_netcdf(str(path))


def _mostly_missing(path):
    h = np.ma.masked_array(np.random.default_rng(0).normal(size=(64, 64)), mask=np.zeros((64, 64), bool))
    h.mask[:20] = True
    ST.Topography(h, (6.4, 6.4), unit="µm").to_netcdf(str(path))


def _non_square(path):
    ST.Topography(np.random.default_rng(0).normal(size=(64, 64)), (6.4, 3.2), unit="µm").to_netcdf(str(path))


def _deflection_only(path):
    """A minimal Molecular Imaging file whose one channel is a deflection in volts."""
    lines = [("fileType", "Image"), ("xPixels", 64), ("yPixels", 64), ("xLength", "6.4e-6"),
             ("yLength", "6.4e-6"), ("bufferLabel", "Deflection"), ("bufferUnit", "V"),
             ("bufferRange", "1.0"), ("data", "BINARY")]
    header = "".join(f"{k:<14}{v}\n" for k, v in lines).encode()
    path.write_bytes(header + np.random.default_rng(0).integers(-1000, 1000, (64, 64)).astype("<i2").tobytes())


@pytest.mark.parametrize("write, needle", [
    (_line_scan, "a line scan"),
    (_deflection_only, "no height channel"),
])
def test_scans_the_config_rejects(tmp_path, write, needle):
    """What reading the height channel tells (check-config opens every scan): before any job."""
    name = "bad.mi" if write is _deflection_only else "bad.nc"
    write(tmp_path / name)
    with pytest.raises(ConfigError) as err:
        _resolved(tmp_path, topography=[name])
    assert needle in _one_line(err) and "topography[0].file" in _one_line(err)


@pytest.mark.parametrize("write, needle", [
    (_mostly_missing, "are undefined, more than max_missing"),
    (_non_square, "pixels are not square"),
])
def test_scans_the_stage_rejects(tmp_path, write, needle):
    name = "bad.nc"
    write(tmp_path / name)
    cfg = _resolved(tmp_path, topography=[name])
    out = tmp_path / "out" / "surface.nc"
    with pytest.raises(InputFileError) as err:
        measured.prepare_surface(cfg["topography"][0], out, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    assert needle in _one_line(err)
    assert not out.exists()


def test_non_square_pixels_with_interpolate(tmp_path):
    _non_square(tmp_path / "bad.nc")
    cfg = _resolved(tmp_path, topography=[{"file": "bad.nc", "interpolate": True}])
    measured.prepare_surface(cfg["topography"][0], tmp_path / "surface.nc", length_unit=cfg["units"]["length"], tile=cfg["tile"])
    assert measured.read_surface(tmp_path / "surface.nc")[0].shape == (32, 32)


def test_physical_size_from_neither_file_nor_config(tmp_path):
    np.save(tmp_path / "raw.npy", np.random.default_rng(0).normal(size=(64, 64)))
    with pytest.raises(ConfigError) as err:
        _resolved(tmp_path, topography=["raw.npy"])
    assert "'topography[0].size'" in _one_line(err) and "gives no physical size" in _one_line(err)
    out = tmp_path / "surface.nc"
    cfg = _resolved(tmp_path, topography=[{"file": "raw.npy", "size": 6400, "unit": "nm"}])
    measured.prepare_surface(cfg["topography"][0], out, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    _, length, attrs = measured.read_surface(out)
    assert length == pytest.approx(6.4) and attrs["units_length"] == "um" and attrs["tile_count"] == 4


def test_full_contact_of_a_periodic_surface(tmp_path):
    _psd(tmp_path / "psd.csv")
    cfg = _resolved(tmp_path, spectrum=["psd.csv"], seeds=1, grid={"n": 33, "length": 3.2},
                    forces={"flat": {"from": 1e-2, "to": 10.0, "count": 3}})
    out = tmp_path / "run.nc"
    with pytest.raises(IndentError) as err:
        measured.run_job(measured.job_of(cfg, "spectrum", "psd", float("inf"), 0), tmp_path / "psd.csv", out)
    assert "lower forces.flat.to" in _one_line(err) and not out.exists()


def test_loads_whose_contact_would_reach_the_scan_edge(tmp_path):
    _scan(tmp_path / "scan.nc")
    cfg = _resolved(tmp_path, topography=["scan.nc"],
                    forces={"sphere": {"from": 1e-3, "to": 0.5, "count": 3}})
    surface = tmp_path / "surface.nc"
    measured.prepare_surface(cfg["topography"][0], surface, length_unit=cfg["units"]["length"], tile=cfg["tile"])
    out = tmp_path / "run.nc"
    with pytest.raises(IndentError) as err:
        measured.run_job(measured.job_of(cfg, "topography", "scan", 20.0, 0), surface, out)
    assert "loads whose contact would reach the scan's edge" in _one_line(err)
    assert not out.exists() and not list(tmp_path.glob(".run.nc.tmp-*"))


@pytest.mark.parametrize("rows, needle", [
    ([(1.0, 1.0), (2.0, -1.0)], "C = -1 is not > 0"),
    ([(1.0, 1.0), (2.0, float("nan"))], "is not finite"),
    ([(0.0, 1.0), (2.0, 1.0)], "q = 0 is not > 0"),
])
def test_bad_spectrum(tmp_path, rows, needle):
    """Caught when the config is resolved (before any job), and by the job if the file changed since."""
    _psd(tmp_path / "psd.csv", rows)
    with pytest.raises(ConfigError) as err:
        _resolved(tmp_path, spectrum=["psd.csv"], seeds=1, grid={"n": 33, "length": 3.2})
    assert "config key 'spectrum[0].file'" in _one_line(err) and needle in _one_line(err)
    _psd(tmp_path / "psd.csv")
    cfg = _resolved(tmp_path, spectrum=["psd.csv"], seeds=1, grid={"n": 33, "length": 3.2})
    _psd(tmp_path / "psd.csv", rows)
    out = tmp_path / "run.nc"
    with pytest.raises(InputFileError) as err:
        measured.run_job(measured.job_of(cfg, "spectrum", "psd", float("inf"), 0), tmp_path / "psd.csv", out)
    assert needle in _one_line(err)
    assert not out.exists()


# --- the pipeline end to end -------------------------------------------------------------------

@pytest.fixture(scope="module")
def pipeline(tmp_path_factory):
    work = tmp_path_factory.mktemp("measured")
    (work / "inputs").mkdir()
    h = _scan(work / "inputs" / "scan.nc")
    _psd(work / "inputs" / "psd.csv")
    cfg = _cfg(topography=[{"file": "inputs/scan.nc", "detrend": "none"}], hurst=[], h_rms=[])
    return work, _run_sweep(work, cfg), h, config.resolve_config(cfg, base_dir=work)


def _run_sweep(work, cfg) -> Path:
    """Run the workflow on *cfg* (written to *work*/study.yaml) in *work*/run, on 2 cores; the run directory."""
    (work / "study.yaml").write_text(yaml.safe_dump(cfg))
    run_dir = work / "run"
    run_dir.mkdir()
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "--configfile",
                           str(work / "study.yaml"), "--cores", "2"], cwd=run_dir, capture_output=True,
                          text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    return run_dir


def test_merged_scan_has_units_dims_and_provenance(pipeline):
    work, run_dir, _, _ = pipeline
    import xarray as xr

    path = run_dir / "results/measured_merge/scan.nc"
    with xr.open_datatree(path) as tree:
        attrs = dict(tree.attrs)
    assert attrs["file"] == "scan.nc" and attrs["tile_count"] == 4 and attrs["tile"] == 32
    assert attrs["file_sha256"] == hashlib.sha256((work / "inputs/scan.nc").read_bytes()).hexdigest()
    assert attrs["scan_detrend"] == "none" and attrs["units_length"] == "um" and attrs["e_star_units"] == "GPa"
    for key in ("git_commit", "config_hash", "roughcontact_version"):
        assert key in attrs
    groups = read_groups(path)
    assert tuple(groups["sphere"]["stiffness"].dims) == ("radius", "tile", "force")
    assert tuple(groups["flat"]["stiffness"].dims) == ("tile", "force")
    for ds in groups.values():
        assert ds["force"].attrs["units"] == "N" and ds["stiffness"].attrs["units"] == "N m-1"
        assert ds["force_normalized"].attrs["units"] == "1" and ds["depth"].attrs["units"] == "um"
        assert np.all(ds["k_ci_low"] <= ds["k_mean"]) and np.all(ds["k_mean"] <= ds["k_ci_high"])
    assert (run_dir / "results/measured_figures/scan/stiffness.png").stat().st_size > 0
    assert (run_dir / "results/measured_figures/scan/height_map.png").stat().st_size > 0
    assert (run_dir / "results/measured_figures/scan/spectrum.png").stat().st_size > 0


def test_measured_only_sweep_ends_in_a_landing_page(pipeline):
    """A sweep of one scan and no generated surface (hurst empty) writes results/summary.html: the
    answer says the paper's claims were not tested, and per kind and radius the page names the
    scorecard's rank-1 model with its max_rel_dev to four digits (the CSV's value)."""
    import html

    from roughcontact.study.report.landing_measured import NO_GENERATED
    from roughcontact.study.report.summary import fmt

    _, run_dir, _, _ = pipeline
    page = (run_dir / "results/summary.html").read_text()
    card = pd.read_csv(run_dir / "results/measured_scorecard/scan.csv")
    best = card[card["rank"] == 1].groupby(["kind", "radius"], sort=False).head(1)
    assert html.escape(NO_GENERATED) in page
    assert "Scan scan" in page
    assert len(best) == 2, best          # the sphere of radius 20 um and the flat scan
    for _, row in best.iterrows():
        assert f"<b>{row['model']}</b></td><td style" in page and fmt(row["max_rel_dev"]) in page, row.to_dict()


def test_spectrum_only_sweep_ends_in_a_landing_page(tmp_path):
    """A sweep of one measured spectrum and nothing else (hurst empty, no scan) writes
    results/summary.html: the answer says the paper's claims were not tested; per kind the page
    gives the seeds and counts the loads whose mean contact cells over the seeds reach
    fit.resolved_cells (recounted here from the merged file), and embeds the k(F) figure."""
    import html

    from roughcontact.study.report.landing_measured import NO_GENERATED

    (tmp_path / "inputs").mkdir()
    _psd(tmp_path / "inputs" / "psd.csv")
    cfg = {k: v for k, v in _cfg(hurst=[], h_rms=[], spectrum=["inputs/psd.csv"], seeds=2,
                                 grid={"n": 33, "length": 3.2}).items() if k != "tile"}
    run_dir = _run_sweep(tmp_path, cfg)
    page = (run_dir / "results/summary.html").read_text()
    assert html.escape(NO_GENERATED) in page
    assert "Spectrum psd" in page
    assert page.count('<img alt="k(F) of psd"') == 1
    resolved_cells = config.resolve_config(cfg, base_dir=tmp_path)["fit"]["resolved_cells"]
    for kind, ds in read_groups(run_dir / "results/spectrum_merge/psd.nc").items():
        one = ds.isel(radius=0) if "radius" in ds.dims else ds
        resolved = int((one["contact_cells"].mean("seed").values >= resolved_cells).sum())
        assert f"<td style=\"{_cell()}\">{resolved} of {one.sizes['force']}</td>" in page, kind


def _cell() -> str:
    from roughcontact.study.report.summary import _CELL

    return _CELL


def test_spectrum_fit_and_models(pipeline):
    """The fit of the synthetic scan (H = 0.8) over its 4 tiles and the models at the runs' forces."""
    _, run_dir, _, _ = pipeline
    fit = pd.read_csv(run_dir / "results/measured_spectrum/scan.csv").iloc[0]
    assert fit["tiles"] == 4 and fit["wavelength_max"] == 1.6 and fit["unit"] == "um"
    assert fit["hurst_ci_low"] <= fit["hurst"] <= fit["hurst_ci_high"]
    assert abs(fit["hurst"] - 0.8) < 0.3, fit["hurst"]   # 4 tiles of 32²: a loose check of the plumbing
    models = read_groups(run_dir / "results/measured_spectrum/scan.nc")
    merged = read_groups(run_dir / "results/measured_merge/scan.nc")
    for kind in ("sphere", "flat"):
        np.testing.assert_allclose(models[kind]["force"].values, merged[kind]["force"].values, rtol=1e-12)
        assert models[kind]["stiffness"].attrs["units"] == "N m-1"
        k = models[kind]["stiffness"].sel(model="eq16_paper").values
        assert np.all(np.isfinite(k) & (k > 0)), kind
    assert np.isnan(models["flat"]["stiffness"].sel(model="greenwood_tripp").values).all()


def test_spectrum_runs_and_merge(tmp_path):
    """The jobs of the spectrum_indent and spectrum_merge rules, in this process (the rules are
    the measured ones with another source): seeded surfaces of the table, sphere on the free,
    flat on the periodic half-space, k equal to bem on surface_from_psd's heights."""
    table = _psd(tmp_path / "psd.csv")
    cfg = _resolved(tmp_path, spectrum=["psd.csv"], seeds=2, grid={"n": 33, "length": 3.2})
    files = []
    for radius, seed in measured.run_order(cfg, "spectrum", "psd", 0):
        job = measured.job_of(cfg, "spectrum", "psd", radius, seed)
        files.append(tmp_path / f"R{radius}_seed{seed}.nc")
        out = measured.run_job(job, table, files[-1])
        psd = surfaces.read_psd(table)
        z = surfaces.surface_from_psd(psd.q, psd.c, 33, length=3.2, seed=seed)
        flat = radius == float("inf")
        if not flat:
            z = z + surfaces.paraboloid(33, radius=radius, length=3.2)
        rng = cfg["forces"]["flat" if flat else "sphere"]
        forces = np.geomspace(rng["from"], rng["to"], rng["count"]) * E_STAR * 3.2**2
        states = bem.load_path(z, forces, length=3.2, e_star=E_STAR, periodic=flat)
        np.testing.assert_allclose(out["stiffness"], [bem.stiffness(s) for s in states], rtol=1e-12)
    merge_surface(cfg, "spectrum", "psd", files, tmp_path / "psd.nc")
    groups = read_groups(tmp_path / "psd.nc")
    assert tuple(groups["sphere"]["stiffness"].dims) == ("radius", "seed", "force")
    assert groups["flat"]["seed"].values.tolist() == [0, 1]
    assert np.all(np.isfinite(groups["flat"]["stiffness"].values))
    assert groups["flat"].attrs["half_space"] == "periodic"
    assert groups["sphere"].attrs["half_space"] == "free (non-periodic)"


def test_measured_merge_gives_the_conductance(tmp_path):
    """With conductance.resistivity, the measured merge's electrical_conductance is Barber's
    2k/(E*(rho1 + rho2)) of each run's k (N/m) and E* (GPa -> Pa), in S."""
    table = _psd(tmp_path / "psd.csv")
    rho = [1.7e-8, 2.0e-7]
    cfg = _resolved(tmp_path, spectrum=["psd.csv"], seeds=2, grid={"n": 33, "length": 3.2},
                    conductance={"resistivity": rho})
    files = []
    for radius, seed in measured.run_order(cfg, "spectrum", "psd", 0):
        files.append(tmp_path / f"R{radius}_seed{seed}.nc")
        measured.run_job(measured.job_of(cfg, "spectrum", "psd", radius, seed), table, files[-1])
    merge_surface(cfg, "spectrum", "psd", files, tmp_path / "psd.nc")
    sphere = read_groups(tmp_path / "psd.nc")["sphere"]
    expected = 2 * sphere["stiffness"].values / (E_STAR * 1e9 * sum(rho))
    np.testing.assert_allclose(sphere["electrical_conductance"].values, expected, rtol=1e-14)


def test_tiles_match_the_same_heights_pressed_directly(pipeline):
    """k(F) of every tile equals bem on the same heights: z = -(h - mean h) of the 64² scan, a
    32² block re-centred, plus r²/2R; the file round trip is exact (float64 NetCDF) and the
    length unit is the scan's (factor 1), so both solve identical arrays up to the round-off of
    the means (1e-18 µm): identical paths, k equal to 1e-9. The scan's physical size comes back
    as SurfaceTopography's NetCDF stores it (float32: 6.4 µm within 3e-8), so L is taken from
    the surface file."""
    _, run_dir, h, cfg = pipeline
    groups = read_groups(run_dir / "results/measured_merge/scan.nc")
    z_scan = -(h - h.mean())
    _, _, attrs = measured.read_surface(run_dir / "results/measured_surface/scan.nc")
    tile, length = 32, float(attrs["tile_length"])
    assert length == pytest.approx(32 * PIXEL, rel=1e-7)
    pa_um2 = 1e9 * 1e-12   # N per GPa µm²
    for kind, ds in groups.items():
        radius = 20.0 if kind == "sphere" else float("inf")
        sub = ds.sel(radius=radius) if kind == "sphere" else ds
        rng = cfg["forces"][kind]
        forces = np.geomspace(rng["from"], rng["to"], rng["count"]) * E_STAR * length**2
        np.testing.assert_allclose(sub["force"].values, forces * pa_um2, rtol=1e-14)
        for t in range(4):
            a, b = divmod(t, 2)
            z = z_scan[a * tile:(a + 1) * tile, b * tile:(b + 1) * tile]
            z = z - z.mean()
            if kind == "sphere":
                z = z + surfaces.paraboloid(tile, radius=radius, length=length)
            states = bem.load_path(z, forces, length=length, e_star=E_STAR, periodic=False,
                                   edge_contact=kind == "flat")
            k = np.array([bem.stiffness(s) for s in states])
            np.testing.assert_allclose(sub["stiffness_normalized"].sel(tile=t).values, k / (E_STAR * length),
                                       rtol=1e-9)
            np.testing.assert_allclose(sub["stiffness"].sel(tile=t).values, k * 1e9 * 1e-6, rtol=1e-9)


@pytest.mark.skipif(not (SHARED / "di-6.di").is_file(), reason=f"measured scans not found in {SHARED}")
def test_example_preset_resolves():
    raw = yaml.safe_load((ROOT / "presets/measured.yaml").read_text())
    cfg = config.resolve_config(raw, base_dir=ROOT / "presets")
    assert Path(cfg["topography"][0]["file"]).resolve() == (SHARED / "di-6.di").resolve()
    assert cfg["hurst"] == [] and cfg["tile"] == 256


def test_spectrum_rules_run_one_job_per_radius_and_seed(tmp_path):
    """A spectrum-only config through snakemake (about 20 s): spectrum_indent per (radius, seed),
    one spectrum_merge, no generated surface; the merged file as the jobs in this process make it."""
    _psd(tmp_path / "psd.csv")
    (tmp_path / "study.yaml").write_text(yaml.safe_dump(_cfg(spectrum=["psd.csv"], seeds=2, hurst=[], h_rms=[],
                                                             grid={"n": 33, "length": 3.2})))
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2", "-s", str(ROOT / "Snakefile"),
                           "--configfile", "study.yaml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env=env, check=False)
    assert proc.returncode == 0, proc.stderr[-3000:]
    out = proc.stdout + proc.stderr
    counts = {line.split()[0]: int(line.split()[1]) for line in out.splitlines()
              if len(line.split()) == 2 and line.split()[1].isdigit()}
    assert counts.get("spectrum_indent") == 2 * 2 and counts.get("spectrum_merge") == 1, counts
    assert "indent" not in counts and "merge" not in counts, counts
    groups = read_groups(tmp_path / "results/spectrum_merge/psd.nc")
    assert tuple(groups["sphere"]["stiffness"].dims) == ("radius", "seed", "force")
    assert groups["flat"].attrs["half_space"] == "periodic"
    assert groups["sphere"]["stiffness"].attrs["units"] == "N m-1"
    assert (tmp_path / "results/spectrum_figures/psd/stiffness.png").stat().st_size > 0


def test_snakemake_stops_on_a_missing_scan_before_any_job(tmp_path):
    (tmp_path / "study.yaml").write_text(yaml.safe_dump(_cfg(topography=["scans/none.di"], hurst=[], h_rms=[])))
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "1", "-s", str(ROOT / "Snakefile"),
                           "--configfile", "study.yaml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300, env=env)
    assert proc.returncode != 0
    lines = [line for line in proc.stderr.splitlines() if "Invalid configuration" in line]
    assert len(lines) == 1 and "config key 'topography[0].file' = 'scans/none.di': no such file" in lines[0]
    assert not (tmp_path / "results").exists() and not (tmp_path / "logs").exists()


def test_check_config_resolves_paths_against_the_config_file(tmp_path, monkeypatch, capsys):
    from roughcontact import cli

    (tmp_path / "cfg" / "scans").mkdir(parents=True)
    _scan(tmp_path / "cfg" / "scans" / "scan.nc")
    path = tmp_path / "cfg" / "study.yaml"
    path.write_text(yaml.safe_dump(_cfg(topography=["scans/scan.nc"])))
    monkeypatch.chdir(tmp_path)
    assert cli.main(["check-config", str(path)]) == 0
    assert "measured: 1 scan(s) x 2 radii x their tiles" in capsys.readouterr().out


@needs_chromium
def test_measured_report_is_its_own_and_loads_without_errors(pipeline):
    """The measured report under its own name (the study's report.html untouched): in headless
    Chromium its landing page describes the scan, its scorecard table opens with one row per row of
    the CSV, and the console stays free of errors."""
    work, run_dir, _, _ = pipeline
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
    proc = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "--configfile",
                           str(work / "study.yaml"), "--report", MEASURED_REPORT], cwd=run_dir, capture_output=True,
                          text=True, timeout=600, env=env)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert not (run_dir / "results/report.html").exists(), "the measured report overwrote the study's name"
    rows = len(pd.read_csv(run_dir / "results/measured_scorecard/scan.csv"))
    with report_page(run_dir / MEASURED_REPORT) as (page, errors):
        landing = page.inner_text("body")
        for link in page.locator("a[href^='javascript:']").all():   # a link to a missing result errs
            link.click()
        page.goto((run_dir / MEASURED_REPORT).resolve().as_uri())
        page.get_by_text("Results", exact=True).first.click()
        page.get_by_text("Measured: scan", exact=True).first.click()
        # the "eye" button of the results table's row "model scorecard" shows the page
        page.locator("tr", has_text="model scorecard").first.locator("a[iconname=eye]").click()
        page.wait_for_function("document.querySelector('iframe') !== null", timeout=20_000)
        cells = page.frame_locator("iframe").locator("tbody tr")
        cells.first.wait_for(timeout=20_000)
        count = cells.count()
    assert "Scan scan" in landing and "H = []" not in landing, f"landing page: {landing[:400]!r}"
    assert count == rows, f"{count} rows on the scorecard page for {rows} rows of the CSV"
    assert errors == [], f"console errors: {errors}"


#: the measured report's own file name (docs/guide/measured.md, presets/measured.yaml)
MEASURED_REPORT = "results/measured_report.html"
