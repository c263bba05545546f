# roughcontact parameter study (Pohrt & Popov 2013): `snakemake --cores 2`
# Sweep: config.yaml (or --configfile presets/*.yaml); output: results/; report:
# `snakemake --report results/report.html`.  See README.md.
import os
import sys
from pathlib import Path

from snakemake.utils import min_version, validate

min_version("9.0")

# Use the package of this checkout, also in the jobs (no install needed for the workflow itself).
SRC = str(Path(workflow.basedir) / "src")
sys.path.insert(0, SRC)
# (set, not required: the envvars directive does not apply)
os.environ.update(PYTHONPATH=os.pathsep.join(p for p in (SRC, os.environ.get("PYTHONPATH")) if p))

from roughcontact import study  # noqa: E402  (numpy only)


configfile: "config.yaml"


SCHEMA = "workflow/schemas/config.schema.yaml"
try:
    C = study.resolve_config(config, schema=Path(workflow.basedir) / SCHEMA)
except study.ConfigError as err:
    raise SystemExit(f"Invalid configuration: {err}")
validate(C, SCHEMA)  # the same schema through Snakemake (passes once resolve_config did)
config.clear()
config.update(C)  # the report and the jobs see the resolved values


report: "workflow/report/workflow.rst"


include: "workflow/rules/indent.smk"
include: "workflow/rules/analysis.smk"
include: "workflow/rules/figures.smk"


localrules:
    all,
    merge,
    fit_zeta,
    crossover,
    figures,


rule all:
    input:
        "results/stiffness.nc",
        "results/ensemble.nc",
        "results/zeta.csv",
        "results/zeta.nc",
        "results/crossover.csv",
        FIGURES,
    default_target: True
