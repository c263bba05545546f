"""The numbers the quick start and the pipeline guide give for ``snakemake --cores 2`` on
``config.yaml`` (load paths, grids, indentation jobs), computed from ``config.yaml`` as the workflow
computes them, and those numbers against a real ``snakemake -n``: the text cannot drift from the
configuration."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from roughcontact.study.config import load_config, resolve_config
from roughcontact.study.config.companions import coarse_config
from roughcontact.study.config.settings import StudySettings
from roughcontact.study.runs import naming as runs

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def default_study() -> dict:
    """What `snakemake --cores 2` presses with config.yaml: the load paths, grid and indent jobs of the
    study and of its grid-error companion (grid.coarse), as workflow/rules/common.smk and indent.smk
    derive them (one job per combination and block of jobs.batch seeds)."""
    cfg = resolve_config(load_config(ROOT / "config.yaml"))
    study, coarse = StudySettings.of(cfg), StudySettings.of(coarse_config(cfg))
    blocks = len(runs.seed_blocks(study.seeds, study.jobs.batch))
    return {"paths": len(runs.runs(study)), "n": study.grid.n, "jobs": len(runs.combinations(study)) * blocks,
            "coarse_paths": len(runs.runs(coarse)), "coarse_n": coarse.grid.n,
            "coarse_jobs": len(runs.combinations(coarse)) * blocks}


def _numbers(pattern: str, text: str) -> tuple:
    found = re.search(pattern, " ".join(text.split()))
    assert found, f"no sentence matching {pattern!r}"
    return tuple(int(number) for number in found.groups())


def test_the_quickstart_counts_the_default_study(default_study):
    text = (ROOT / "docs" / "quickstart.md").read_text()
    said = _numbers(r"\((\d+) load paths on a (\d+)² grid in (\d+) indentation jobs, and their (\d+) sphere paths "
                    r"again on the (\d+)² grid of the grid error in (\d+) more: (\d+) jobs", text)
    d = default_study
    assert said == (d["paths"], d["n"], d["jobs"], d["coarse_paths"], d["coarse_n"], d["coarse_jobs"],
                    d["jobs"] + d["coarse_jobs"])


def test_the_pipeline_guide_counts_the_default_study(default_study):
    text = (ROOT / "docs" / "guide" / "pipeline.md").read_text()
    said = _numbers(r"\((\d+) runs on a (\d+)² grid in (\d+) `indent` jobs and their (\d+) sphere runs on the (\d+)² "
                    r"companion grid in (\d+) `indent_coarse` jobs", text)
    d = default_study
    assert said == (d["paths"], d["n"], d["jobs"], d["coarse_paths"], d["coarse_n"], d["coarse_jobs"])


def test_snakemake_plans_the_jobs_counted(default_study, tmp_path):
    """`snakemake -n` on config.yaml in an empty directory: its job stats' indent and indent_coarse
    jobs are the counts above."""
    done = subprocess.run([sys.executable, "-m", "snakemake", "-s", str(ROOT / "Snakefile"), "-d", str(tmp_path),
                           "--configfile", str(ROOT / "config.yaml"), "-n"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    stats = (done.stdout + done.stderr).split("Job stats:", 1)[1].split("\n\n", 1)[0]
    jobs = {m.group(1): int(m.group(2)) for m in re.finditer(r"^(\w+)\s+(\d+)\s*$", stats, re.M)}
    planned = (sum(n for rule, n in jobs.items() if rule.startswith("indent_seed")),
               sum(n for rule, n in jobs.items() if rule.startswith("indent_coarse_")))
    assert planned == (default_study["jobs"], default_study["coarse_jobs"])
