"""The workflow's path patterns, read from ``workflow/rules/common.smk`` (their one home)."""
import re
from pathlib import Path

_COMMON = (Path(__file__).resolve().parents[1] / "workflow/rules/common.smk").read_text()


def _pattern(name: str) -> str:
    match = re.search(rf'^{name} = "([^"]+)"', _COMMON, flags=re.M)
    if match is None:
        raise LookupError(f"workflow/rules/common.smk defines no {name}")
    return match.group(1)


RUN_PATTERN = _pattern("RUN_PATTERN")
LOG_PATTERN = _pattern("LOG_PATTERN")
BENCHMARK_PATTERN = _pattern("BENCHMARK_PATTERN")
