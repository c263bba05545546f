"""``-o -`` of ``roughcontact indent`` and ``roughcontact measured``: refused in one line suggesting a
path (a NetCDF file on standard output is of no use), and no file named ``-`` written."""
from __future__ import annotations

import pytest

from roughcontact import cli

REFUSED = "-o -: a NetCDF file cannot be written to standard output; give a file path, e.g. -o run.nc"

COMMANDS = {
    "indent": ["indent", "--hurst", "0.7", "--radius", "0.5", "--h-rms", "9e-3", "--n", "17", "--force-count", "3"],
    "measured": ["measured", "scan.nc", "--unit", "um", "--radius", "20", "--e-star", "100", "--e-star-unit", "GPa"],
}


@pytest.fixture
def refused(tmp_path, monkeypatch, capsys, request):
    """The command *request.param* run with ``-o -`` in an empty directory: (exit code, stderr, directory)."""
    monkeypatch.chdir(tmp_path)
    code = cli.main([*COMMANDS[request.param], "-o", "-"])
    return code, capsys.readouterr().err, tmp_path


@pytest.mark.parametrize("refused", list(COMMANDS), indirect=True)
def test_dash_output_exits_2(refused):
    assert refused[0] == 2


@pytest.mark.parametrize("refused,command", [(c, c) for c in COMMANDS], indirect=["refused"])
def test_dash_output_is_refused_in_one_line_suggesting_a_path(refused, command):
    assert refused[1] == f"roughcontact {command}: invalid argument: {REFUSED}\n"


@pytest.mark.parametrize("refused", list(COMMANDS), indirect=True)
def test_dash_output_writes_no_file(refused):
    assert list(refused[2].iterdir()) == []
