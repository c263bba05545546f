"""Every bad instrument file is one line naming the file: truncated, garbage, empty, misnamed and
unreadable files of the formats of the shared scans (Bruker .di, Wyko .opd, Park .tiff), through
the package, ``roughcontact measured`` and ``roughcontact check-config``, nothing printed on
the way."""
from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from roughcontact import cli, surfaces
from roughcontact.errors import InputFileError

pytest.importorskip("SurfaceTopography")

#: the shared scans: ../shared/topographies beside the checkout (as CI has it), or the directory
#: ROUGHCONTACT_TOPOGRAPHIES names (as tests/test_measured.py reads them)
SCANS = Path(os.environ.get("ROUGHCONTACT_TOPOGRAPHIES",
                            Path(__file__).resolve().parents[1].parent / "shared" / "topographies"))
FORMATS = {"di": "di-6.di", "opd": "opd-1.opd", "tiff": "example_ps.tiff"}

pytestmark = pytest.mark.skipif(not all((SCANS / f).is_file() for f in FORMATS.values()),
                                reason=f"the shared scans are not at {SCANS}")


def _make(tmp_path: Path, case: str, extension: str) -> Path:
    """A bad file of *case* with *extension*, made from the shared scan of that format."""
    source = SCANS / FORMATS[extension]
    data = source.read_bytes()
    path = tmp_path / f"{case}.{extension}"
    if case == "cut_header":
        path.write_bytes(data[:5000])
    elif case == "cut_half":
        path.write_bytes(data[: len(data) // 2])
    elif case == "cut_tail":
        path.write_bytes(data[:-100])
    elif case == "garbage":
        path.write_bytes(os.urandom(4096))
    elif case == "empty":
        path.write_bytes(b"")
    elif case == "misnamed":   # another format's scan under this extension
        other = next(e for e in FORMATS if e != extension)
        path.write_bytes((SCANS / FORMATS[other]).read_bytes())
    elif case == "text":
        path.write_text("x y z\n1 2 3\n")
    elif case == "directory":
        path.mkdir()
    return path


CASES = ["cut_header", "cut_half", "cut_tail", "garbage", "empty", "misnamed", "text", "directory"]


def _bad_or_readable(path: Path):
    """The InputFileError of reading *path*, or None where the file still reads (a tail of
    metadata cut off may leave every pixel)."""
    try:
        surfaces.from_topography(path, unit="um")
    except InputFileError as err:
        return err
    return None


@pytest.mark.parametrize("extension", sorted(FORMATS))
@pytest.mark.parametrize("case", CASES)
def test_package_error_is_one_line_naming_the_file(tmp_path, capfd, case, extension):
    path = _make(tmp_path, case, extension)
    err = _bad_or_readable(path)
    out, printed = capfd.readouterr()
    assert out == "" and printed == "", f"printed on the way: {out!r} {printed!r}"
    if err is None:
        assert case == "cut_tail", f"{case}.{extension} read without an error"
        return
    assert len(str(err).splitlines()) == 1, f"not one line: {err!r}"
    assert path.name in str(err), f"does not name the file: {err}"


def test_unreadable_file_is_one_line(tmp_path, monkeypatch):
    path = tmp_path / "scan.di"
    shutil.copy(SCANS / FORMATS["di"], path)
    real_open = open

    def denied(name, *args, **kwargs):
        if os.fspath(name) == os.fspath(path):
            raise PermissionError(13, "Permission denied")
        return real_open(name, *args, **kwargs)

    monkeypatch.setattr("builtins.open", denied)
    with pytest.raises(InputFileError, match=r"scan\.di: cannot open the file \(Permission denied\)"):
        surfaces.from_topography(path, unit="um")


@pytest.mark.parametrize("case, said", [("cut_header", "cut short"), ("empty", "the file is empty"),
                                        ("garbage", "unknown or unreadable file format"),
                                        ("misnamed", "not as the .opd its name says")])
def test_cli_prints_one_line_and_exits_2(tmp_path, capsys, case, said):
    path = _make(tmp_path, case, "opd")
    code = cli.main(["measured", str(path), "--unit", "um", "--radius", "20", "--e-star", "100",
                     "--e-star-unit", "GPa", "-o", str(tmp_path / "out.nc"), "-q"])
    out, err = capsys.readouterr()
    assert code == 2, f"exit status {code}: {err}"
    assert out == "", f"stdout: {out!r}"
    assert len(err.strip().splitlines()) == 1, f"not one line: {err!r}"
    assert said in err and path.name in err, f"line: {err!r}"
    assert not (tmp_path / "out.nc").exists(), "wrote an output for a bad scan"


def test_cli_names_its_flag_for_a_missing_size(tmp_path, capsys):
    """A scan without a physical size (a plain-text height table): the CLI asks for --size."""
    path = tmp_path / "heights.asc"
    path.write_text("\n".join(" ".join(str((i * j) % 7) for j in range(32)) for i in range(32)) + "\n")
    code = cli.main(["measured", str(path), "--unit", "um", "--radius", "20", "--e-star", "100",
                     "--e-star-unit", "GPa", "-o", str(tmp_path / "out.nc"), "-q"])
    err = capsys.readouterr().err
    assert code == 2, f"exit status {code}: {err}"
    assert "--size (topography[0].size)" in err and "length=" not in err, f"line: {err!r}"


@pytest.mark.parametrize("case", ["cut_header", "garbage", "misnamed"])
def test_check_config_opens_each_scan(tmp_path, capsys, case):
    path = _make(tmp_path, case, "di")
    config = tmp_path / "config.yaml"
    config.write_text(f"topography: [{path.name}]\nradius: [20.0]\nunits: {{length: um, e_star: GPa}}\n"
                      "e_star: 100\n")
    code = cli.main(["check-config", str(config)])
    out, err = capsys.readouterr()
    assert code == 2, f"exit status {code}: {out} {err}"
    assert len(err.strip().splitlines()) == 1, f"not one line: {err!r}"
    assert "topography[0].file" in err and path.name in err, f"line: {err!r}"
