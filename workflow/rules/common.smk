# Shared set-up: the package of this checkout, the validated and resolved config.
import os
import sys
from pathlib import Path

from snakemake.utils import validate

# Use the package of this checkout, also in the jobs (no install needed for the workflow itself).
SRC = str(Path(workflow.basedir) / "src")
sys.path.insert(0, SRC)
# (set, not required: the envvars directive does not apply)
os.environ.update(
    PYTHONPATH=os.pathsep.join(p for p in (SRC, os.environ.get("PYTHONPATH")) if p)
)

from roughcontact import config as rc_config, study  # noqa: E402  (numpy only)

SCHEMA = str(Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml")
try:
    # one line naming the key and what is allowed, before any job starts
    C = rc_config.resolve_config(config, schema=SCHEMA)
except rc_config.ConfigError as err:
    raise SystemExit(rc_config.error_line(err))
# the same schema through Snakemake (passes once resolve_config did)
validate(C, SCHEMA)
config.clear()
config.update(C)  # the report and the jobs see the resolved values
