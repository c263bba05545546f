"""The one study-directory reader (roughcontact.study.files.directory): its paths are the
workflow's rule outputs, a missing file names its rule, and it reads what the workflow wrote."""
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from roughcontact.errors import MergeError
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
