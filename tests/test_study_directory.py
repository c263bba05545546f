"""The one study-directory reader (roughcontact.study.files.directory): its paths are the
workflow's rule outputs, a missing file names its rule, and it reads what the workflow wrote."""
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.errors import ConfigError, MergeError
from roughcontact.study.files.directory import FILES, RUN_DIRECTORIES, StudyDirectory
from roughcontact.study.files.io import write_csv, write_groups

RULES = Path(__file__).resolve().parents[1] / "workflow" / "rules"


def _rule_outputs() -> dict:
    """``{rule: text of its block}`` of every rule in workflow/rules/*.smk."""
    out = {}
    for smk in sorted(RULES.glob("*.smk")):
        blocks = re.split(r"^(?:rule|checkpoint) (\w+):$", smk.read_text(), flags=re.M)
        out.update(dict(zip(blocks[1::2], blocks[2::2])))
    return out


@pytest.mark.parametrize("name", list(FILES))
def test_each_file_is_an_output_of_its_rule(name):
    path, rule = FILES[name]
    assert f'"{path}"' in _rule_outputs().get(rule, ""), f"{path} is no output of rule {rule}"


@pytest.mark.parametrize("rule", list(RUN_DIRECTORIES))
def test_each_run_directory_holds_its_rule_runs(rule):
    common = (RULES / "common.smk").read_text()
    assert re.search(rf'"{re.escape(RUN_DIRECTORIES[rule])}/\{{', common), RUN_DIRECTORIES[rule]


def test_a_missing_file_names_its_rule(tmp_path):
    with pytest.raises(MergeError, match="the rule 'crossover' writes it"):
        StudyDirectory(tmp_path).path("crossover")


def test_configuration_and_groups_round_trip(tmp_path):
    ds = xr.Dataset({"stiffness": (("seed", "force"), np.ones((2, 3)))},
                    coords={"seed": [0, 1], "force": [1e-5, 1e-4, 1e-3]})
    (tmp_path / "results").mkdir()
    write_groups(tmp_path / "results" / "stiffness.nc", {"sphere": ds}, {"config": '{"e_star": 2.0}', "grid_n": 33})
    study = StudyDirectory(tmp_path)
    assert study.configuration() == {"e_star": 2.0}
    assert float(study.groups()["sphere"]["stiffness"].sum()) == pytest.approx(6.0, abs=0)


def test_table_reads_the_csv(tmp_path):
    (tmp_path / "results").mkdir()
    write_csv(pd.DataFrame({"zeta": [1.25]}), tmp_path / "results" / "zeta.csv")
    assert StudyDirectory(tmp_path).table("zeta")["zeta"].iloc[0] == 1.25


# One directory, one study: the record of a study's config files and the refusal of another's.

def test_the_default_directory_is_the_checkout_for_config_yaml_and_studies_stem_else(tmp_path):
    from roughcontact.study.files.directory import default_directory

    assert default_directory([tmp_path / "config.yaml"], tmp_path) is None
    assert default_directory([], tmp_path) is None
    assert default_directory([tmp_path / "presets" / "paper.yaml"], tmp_path) == "studies/paper"
    assert default_directory([tmp_path / "a.yaml", tmp_path / "x" / "b.yaml"], tmp_path) == "studies/a+b"


def test_config_names_are_relative_to_the_checkout_or_absolute(tmp_path):
    from roughcontact.study.files.directory import config_names

    elsewhere = tmp_path.parent / "elsewhere.yaml"
    assert config_names([tmp_path / "presets" / "tiny.yaml", elsewhere], tmp_path) == \
        ["presets/tiny.yaml", str(elsewhere)]


def test_a_new_directory_is_recorded_and_then_the_same_study_passes(tmp_path):
    from roughcontact.study.files.directory import RECORD, check_study, record_study

    check_study(tmp_path, ["presets/tiny.yaml"], checkout=tmp_path)   # nothing there: a new study
    record_study(tmp_path, ["presets/tiny.yaml"])
    assert (tmp_path / RECORD).read_text() == "presets/tiny.yaml\n"
    record_study(tmp_path, ["config.yaml"])   # a record is never rewritten
    assert (tmp_path / RECORD).read_text() == "presets/tiny.yaml\n"
    check_study(tmp_path, ["presets/tiny.yaml"], checkout=tmp_path)


def test_another_study_is_refused_in_one_line_naming_both(tmp_path):
    from roughcontact.study.files.directory import check_study, record_study

    record_study(tmp_path, ["config.yaml"])
    with pytest.raises(ConfigError) as err:
        check_study(tmp_path, ["presets/paper.yaml"], checkout=tmp_path, shown_from=tmp_path)
    line = str(err.value)
    assert "\n" not in line
    assert line == ("Not overwriting another study: results/ holds the study of config.yaml, this run's config is "
                    "presets/paper.yaml; run it in a directory of its own (--directory studies/paper), or delete "
                    "results/ to replace that study")


def test_a_second_config_of_the_same_stem_is_sent_elsewhere(tmp_path):
    from roughcontact.study.files.directory import check_study, record_study

    study = tmp_path / "studies" / "paper"
    record_study(study, ["presets/paper.yaml"])
    with pytest.raises(ConfigError, match=r"studies/paper/results/ holds the study of presets/paper\.yaml, this run's "
                                        r"config is mine/paper\.yaml; .*--directory studies/mine-paper\)"):
        check_study(study, ["mine/paper.yaml"], checkout=tmp_path, shown_from=tmp_path)


def _run_file(path: Path, record: dict) -> None:
    from roughcontact.study.files.provenance import canonical_json, config_hash

    path.parent.mkdir(parents=True, exist_ok=True)
    xr.Dataset({"force": ("force", [1.0])},
               attrs={"config": canonical_json(record), "config_hash": config_hash(record)}).to_netcdf(path)


def test_a_directory_without_record_is_refused_where_a_run_has_other_settings(tmp_path):
    """Made before there were records: its run at this study's path, computed with n 385, is not
    this study's (n 129)."""
    from roughcontact.study.files.directory import check_study

    path = "results/runs/H0.7_R0.5_h0.009/seed0.nc"
    _run_file(tmp_path / path, {"n": 385, "tol": 1e-8})
    check_study(tmp_path, ["presets/a.yaml"], checkout=tmp_path, runs=lambda: {path: {"n": 385, "tol": 1e-8}})
    with pytest.raises(ConfigError) as err:
        check_study(tmp_path, ["presets/a.yaml"], checkout=tmp_path, shown_from=tmp_path,
                    runs=lambda: {path: {"n": 129, "tol": 1e-8}})
    line = str(err.value)
    assert "\n" not in line
    assert line.startswith(f"Not overwriting another study: {path} was computed with other settings "
                           f"(differs in n: 385 in the file, 129 now) and results/ records no config file; ")
    assert "--directory studies/a" in line and "write presets/a.yaml into results/configfile.txt" in line
