"""``roughcontact list axes|models|area-models|claims|quantities``: one line per registered item, or ``--json``."""
from __future__ import annotations

import json

import pytest
from examples import loaded, scoped_registry  # noqa: F401 -- scoped_registry: every test in its own registries

from roughcontact.cli import main
from roughcontact.models import scorecard
from roughcontact.study.config import axes
from roughcontact.study.claims import claims


def _lines(capsys, *argv) -> list[str]:
    assert main(["list", *argv]) == 0
    return capsys.readouterr().out.splitlines()


def _json(capsys, registry) -> list:
    assert main(["list", registry, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_axes_one_line_each(capsys):
    names = [line.split("\t")[0] for line in _lines(capsys, "axes")]
    assert names == list(axes.AXES), f"axes listed: {names}"


def test_axis_line_has_unit_and_paper_value(capsys):
    line = next(x for x in _lines(capsys, "axes") if x.startswith("exponent\t"))
    assert line.split("\t")[1:3] == ["unit 1", "paper 2.0"], f"line: {line!r}"


def test_required_axis_has_no_paper_value(capsys):
    line = next(x for x in _lines(capsys, "axes") if x.startswith("hurst\t"))
    assert line.split("\t")[2] == "paper (required)", f"line: {line!r}"


def test_axes_json_has_name_and_paper(capsys):
    entry = next(item for item in _json(capsys, "axes") if item["name"] == "exponent")
    assert entry["paper"] == 2.0, f"entry: {entry}"


def test_nullable_axis_json_paper_is_null(capsys):
    entry = next(item for item in _json(capsys, "axes") if item["name"] == "hardness")
    assert entry["paper"] is None, f"entry: {entry}"


def test_models_one_line_each(capsys):
    names = [line.split("\t")[0] for line in _lines(capsys, "models")]
    assert names == list(scorecard.models()), f"models listed: {names}"


def test_models_json_has_declared_axes(capsys):
    entry = next(item for item in _json(capsys, "models") if item["name"] == "greenwood_tripp")
    assert entry["axes"] == list(scorecard.models()["greenwood_tripp"].axes), f"entry: {entry}"


def test_area_models_one_line_each(capsys):
    from roughcontact.models import area

    names = [line.split("\t")[0] for line in _lines(capsys, "area-models")]
    assert names == list(area.models()), f"area models listed: {names}"


def test_area_models_json_has_reference(capsys):
    from roughcontact.models import area

    entry = next(item for item in _json(capsys, "area-models") if item["name"] == "persson_area")
    assert entry["reference"] == area.models()["persson_area"].reference, f"entry: {entry}"


def test_quantities_one_line_each(capsys):
    from roughcontact.study.quantities import QUANTITIES

    names = [line.split("\t")[0] for line in _lines(capsys, "quantities")]
    assert names == list(QUANTITIES), f"quantities listed: {names}"


def test_claims_one_line_each(capsys):
    names = [line.split("\t")[0] for line in _lines(capsys, "claims")]
    assert names == list(claims()), f"claims listed: {names}"


@pytest.mark.parametrize("example, registry, kind, key", [("axis_example.py", axes.AXES, "axes", "plateau"),
                                                           ("model_example.py", scorecard.MODELS, "models", "smooth_body"),
                                                           ("claim_example.py", None, "claims", "x")])
def test_a_registered_example_is_listed_last_of_its_module(capsys, example, registry, kind, key):
    """The guide's example, loaded: listed once, after the entries the package had (claims: in letter order)."""
    from roughcontact.study.claims import CLAIMS

    before = [item["name"] for item in _json(capsys, kind) if item["name"] != key]
    with loaded(example, CLAIMS if registry is None else registry, key):
        names = [item["name"] for item in _json(capsys, kind)]
    expected = sorted(before + [key]) if kind == "claims" else before + [key]
    assert names == expected, f"roughcontact list {kind}: {names}"


def test_unknown_registry_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as info:
        main(["list", "presets"])
    assert info.value.code == 2, f"exit code {info.value.code}"


def test_commands_are_the_parser_subcommands():
    """cli.COMMANDS (the generated command-line reference documents each) names every subcommand."""
    from roughcontact import cli

    parser = cli.build_parser()
    choices = next(a.choices for a in parser._subparsers._group_actions if a.choices)
    assert tuple(choices) == cli.COMMANDS, f"subcommands {tuple(choices)} against COMMANDS {cli.COMMANDS}"
