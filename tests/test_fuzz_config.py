"""A fuzzed configuration: config.yaml with one to three mutations, derived
from the schema (so keys added to the schema join in without edits here).

Every mutated config is either

* accepted: then ``runs.runs``/``runs.run_paths`` give one distinct run path
  per run, and each path parses back (``runs.parse_run_path``) to exactly the
  run's configured values; or
* rejected by ``roughcontact check-config`` (exit code 2) with one line that
  starts with ``Invalid configuration`` and names a key.

Never a traceback.  A fixed, seeded sample also goes through a real
``snakemake -n``, which must agree with ``resolve_config``: the same line, or
a plan with one ``indent`` job per run, and never a Snakemake exception.
"""

from __future__ import annotations

import contextlib
import copy
import io
import math
import random
import re
from collections import Counter
from pathlib import Path

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from snakemake_dry import dry_run
from workflow_paths import RUN_PATTERN

from roughcontact import _validate
from roughcontact import cli
from roughcontact import errors
from roughcontact.study.config import resolve as config
from roughcontact.study.runs import naming as runs
from roughcontact.study.config.schema import load_schema

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = copy.deepcopy(load_schema(None))
BASE = config.load_config(ROOT / "config.yaml")

EXAMPLES = 500  # hypothesis cases in-process
DRY_RUNS = 20  # of which this many (a seeded sample) also through snakemake -n
DRY_ACCEPTED = 6  # ... with at least this many accepted configs among them

DELETE = object()  # mutation: remove the key
PROMOTE = object()  # mutation: move the key to the top level (wrong nesting)


# ---------------------------------------------------------------------------
# the schema: every key path and the node that describes it
def _deref(node: dict) -> dict:
    ref = node.get("$ref", "")
    if ref.startswith("#/"):
        target = SCHEMA
        for part in ref[2:].split("/"):
            target = target[part]
        return {**target, **{k: v for k, v in node.items() if k != "$ref"}}
    return node


def _alternatives(node: dict) -> list[dict]:
    node = _deref(node)
    out = [node]
    for key in ("oneOf", "anyOf", "allOf"):
        for branch in node.get(key, []):
            out += _alternatives(branch)
    return out


def _types(node: dict) -> set[str]:
    kinds = set()
    for alt in _alternatives(node):
        kind = alt.get("type", [])
        kinds |= set(kind if isinstance(kind, list) else [kind])
        if "enum" in alt:
            kinds.add("enum")
    return kinds


def _schema_paths(node: dict, path: tuple = ()) -> list[tuple[tuple, dict]]:
    out = [(path, _deref(node))] if path else []
    for alt in _alternatives(node):
        for name, sub in alt.get("properties", {}).items():
            out += _schema_paths(sub, (*path, name))
        if isinstance(alt.get("items"), dict):
            out += _schema_paths(alt["items"], (*path, 0))
    return out


PATHS = _schema_paths(SCHEMA)


def _numeric_bounds(node: dict) -> list:
    """Each bound of *node* (and its alternatives), on it and on either side.
    Values inside a maximum above 1000 are left out: a seed count of 10^5 is
    a valid sweep of a million runs, too many to name in a test."""
    out = []
    for alt in _alternatives(node):
        integer = "integer" in _types(alt) and "number" not in _types(alt)
        for key in ("minimum", "exclusiveMinimum", "maximum", "exclusiveMaximum"):
            if key not in alt:
                continue
            bound = alt[key]
            near = [bound - 1, bound + 1] if integer else [math.nextafter(bound, -math.inf),
                                                         math.nextafter(bound, math.inf)]
            out += [v for v in (bound, *near) if not ("maximum" in key and bound > 1000 and v <= bound)]
    return out


def _sample_item(node: dict):
    """A value the item node *node* allows (for lists with several values)."""
    kinds = _types(node)
    lo = node.get("minimum", node.get("exclusiveMinimum", 0))
    hi = node.get("maximum", node.get("exclusiveMaximum", lo + 10))
    if "integer" in kinds and "number" not in kinds:
        return int(lo) + 3
    return lo + (min(hi, lo + 10) - lo) * 0.37


NUMBER_TEXT = ["nan", ".nan", "NaN", "inf", "-inf", ".inf", "Infinity", "1e-2", "1e999", "0x10", "1_0", "",
               "  ", "\uff11", "٣", "1.0e+0", "+0.5", "[0.5]"]
ODD_KEYS = ["colour", "hürst", "grid ", "", " ", "a\nb", "\u2028", "ζ", "HURST", "n"]


def candidates(path: tuple, node: dict, current) -> list:
    """Mutated values for the key at *path* (schema node *node*, value now *current*)."""
    kinds = _types(node)
    out: list = [DELETE, None, True, "text", "ünïcode ζ", [], {}]
    if len(path) > 1:
        out.append(PROMOTE)
    if kinds & {"number", "integer"}:
        out += [math.nan, math.inf, -math.inf, -0.0, 0, -1, 0.5, 3, 1e308, 5e-324, 10**400, 2**63, 1e300,
                *_numeric_bounds(node), *NUMBER_TEXT]
        if _validate.is_finite_number(current):
            out += [current * 2, current / 3, str(current), repr(float(current)) + "00000001",
                    f"{float(current):.17e}", [current], {"value": current}]
    if "array" in kinds:
        items = next((alt["items"] for alt in _alternatives(node) if isinstance(alt.get("items"), dict)), {})
        x = current[0] if isinstance(current, list) and current else _sample_item(items)
        y = _sample_item(items)
        out += [[x, x], [x, str(x)], [[x]], [None], [x, math.nan], [x, math.inf], x, f"[{x}, {y}]",
                [x, y] if x != y else [x], [y, x, y]]
        if isinstance(x, float) and _validate.is_finite_number(x):
            out += [[x, float(repr(x) + "00000001")],  # 0.7 and 0.70000000000000001: one float
                    [x, repr(x) + "00000001"], [x, f"{x:.17e}"], [x, math.nextafter(x, math.inf)],
                    [x, x * (1 + 2**-52)], [f"{x:e}", x]]
        if isinstance(x, int) and not isinstance(x, bool):
            out += [[x, float(x)], [x, str(x)], [x, x + 1, x + 2], [2**63 - 1], [2**63]]
    if "object" in kinds:
        props = [p for alt in _alternatives(node) for p in alt.get("properties", {})]
        if isinstance(current, dict):
            out += [{**current, key: 1} for key in ODD_KEYS[:4]]
            out += [{"wrapped": current}, [current], {k: v for k, v in current.items() if k != props[0]}]
    if "enum" in kinds:
        enum = next(alt["enum"] for alt in _alternatives(node) if "enum" in alt)
        out += [*enum, str(enum[0]).upper(), str(enum[0]) + " ", 1]
    if "string" in kinds:
        out += ["", "x" * 300, "\u2028"]
    return out


def _get(cfg, path):
    node = cfg
    for part in path:
        if isinstance(node, dict) and part in node or isinstance(node, list) and isinstance(part, int) and len(node) > part:
            node = node[part]
        else:
            return None
    return node


def _apply(cfg: dict, path: tuple, value) -> None:
    """Set (or delete, or promote) *path* in *cfg*; a path through a non-container is left alone."""
    parent = _get(cfg, path[:-1])
    last = path[-1]
    if isinstance(parent, dict) and isinstance(last, str):
        if value is DELETE:
            parent.pop(last, None)
        elif value is PROMOTE:
            if last in parent:
                cfg[last] = parent.pop(last)
        else:
            parent[last] = copy.deepcopy(value)
    elif isinstance(parent, list) and isinstance(last, int) and len(parent) > last:
        if value is DELETE or value is PROMOTE:
            del parent[last]
        else:
            parent[last] = copy.deepcopy(value)


def _unknown_key(cfg: dict, path: tuple, name: str, value) -> None:
    parent = _get(cfg, path) if path else cfg
    if isinstance(parent, dict):
        parent[name] = value


# ---------------------------------------------------------------------------
# the property
KEY = re.compile(r"(?:unknown |missing )?config key '([^']*)'")


def _yaml_round_trip(cfg: dict) -> tuple[str, object]:
    text = yaml.safe_dump(cfg, allow_unicode=True)
    return text, yaml.safe_load(text)


def _same(a, b) -> bool:
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


def check_accepted(cfg: dict) -> int:
    """The run naming of an accepted config: distinct paths that parse back exactly; returns the run count."""
    table = runs.runs(cfg)
    paths = runs.run_paths(cfg, RUN_PATTERN)
    assert len(paths) == len(table), f"{len(paths)} paths for {len(table)} runs"
    assert len(set(paths)) == len(paths), f"run paths collide: {len(paths) - len(set(paths))} duplicates"
    for run, path in zip(table, paths):
        parsed = runs.parse_run_path(path, RUN_PATTERN)
        for field, value in parsed.items():
            assert _same(value, run[field]), f"{path}: {field} parses to {value!r}, not {run[field]!r}"
    return len(table)


def check_rejected(line: str) -> None:
    assert len(line.splitlines()) == 1, f"not one line: {line!r}"
    assert line.startswith("Invalid configuration: "), f"wrong prefix: {line!r}"
    named = KEY.search(line)
    assert named and named.group(1), f"names no key: {line!r}"


def outcome(cfg: dict) -> tuple[str, str | dict]:
    """('accepted', resolved config) or ('rejected', the one line)."""
    try:
        return "accepted", config.resolve_config(cfg)
    except errors.ConfigError as err:
        assert err.key is not None and f"'{err.key}'" in str(err), f"ConfigError.key {err.key!r} not named: {err}"
        return "rejected", config.error_line(err)


def _check_config_cli(text: str, path: Path) -> tuple[int, str]:
    path.write_text(text, encoding="utf-8")
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = cli.main(["check-config", str(path)])
    return code, err.getvalue()


# ---------------------------------------------------------------------------
# hypothesis: mutations drawn from the schema's catalogue and from generic values
GENERIC = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.text(max_size=6),
    st.booleans(),
    st.none(),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=3),
    st.lists(st.integers(min_value=-3, max_value=10), max_size=3),
)


def _numeric(text: str) -> bool:
    """Whether *text* reads as a number (a command line's "1e-5"), not a name (an enum's choice)."""
    try:
        float(text)
    except ValueError:
        return False
    return True


def allowed_values(node: dict):
    """A strategy for values the schema node allows by itself (cross-checks may still reject them),
    written as numbers or as the text a command line passes; None for mappings."""
    strategies = []
    for alt in _alternatives(node):
        kinds = _types(alt)
        if "enum" in alt:
            strategies.append(st.sampled_from(alt["enum"]))
        elif "array" in kinds and isinstance(alt.get("items"), dict):
            item = allowed_values(alt["items"])
            if item is not None:
                strategies.append(st.lists(item, min_size=max(1, alt.get("minItems", 0)), max_size=4,
                                           unique_by=lambda v: v if isinstance(v, str) and not _numeric(v)
                                           else float(v)))
        elif "integer" in kinds and "number" not in kinds:
            lo = alt.get("minimum", alt.get("exclusiveMinimum", -1) + 1)
            hi = min(alt.get("maximum", alt.get("exclusiveMaximum", lo + 51) - 1), lo + 50)
            strategies.append(st.integers(min_value=lo, max_value=hi))
        elif "number" in kinds:
            numbers = st.floats(min_value=alt.get("minimum", alt.get("exclusiveMinimum")),
                                max_value=alt.get("maximum", alt.get("exclusiveMaximum")),
                                exclude_min="exclusiveMinimum" in alt, exclude_max="exclusiveMaximum" in alt,
                                allow_nan=False, allow_infinity=False)
            numbers = numbers | st.just(math.inf) if alt.get("x-allow-inf") else numbers
            strategies += [numbers, numbers.map(lambda v: f"{v:e}" if math.isfinite(v) else "inf")]
    return st.one_of(strategies) if strategies else None


@st.composite
def mutated_configs(draw):
    cfg = copy.deepcopy(BASE)
    for _ in range(draw(st.integers(min_value=1, max_value=3))):
        how = draw(st.sampled_from(["unknown key", "catalogue", "catalogue", "catalogue", "generic",
                                    "allowed", "allowed", "allowed"]))
        if how == "unknown key":
            parent = draw(st.sampled_from([(), *[p for p, n in PATHS if "object" in _types(n)]]))
            name = draw(st.one_of(st.sampled_from(ODD_KEYS), st.text(min_size=1, max_size=5)))
            _unknown_key(cfg, parent, name, draw(GENERIC))
            continue
        path, node = draw(st.sampled_from(PATHS))
        allowed = allowed_values(node)
        if how == "allowed" and allowed is not None:
            value = draw(allowed)
        elif how == "generic":
            value = draw(GENERIC)
        else:
            value = draw(st.sampled_from(candidates(path, node, _get(cfg, path))))
        _apply(cfg, path, value)
    return cfg


def test_fuzzed_configs_are_accepted_consistently_or_rejected_with_one_line(tmp_path):
    seen = Counter()
    file = tmp_path / "fuzz.yaml"

    @settings(max_examples=EXAMPLES, derandomize=True, deadline=None, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                     HealthCheck.function_scoped_fixture])
    @given(mutated_configs())
    def check(cfg):
        text, loaded = _yaml_round_trip(cfg)
        code, err = _check_config_cli(text, file)
        kind, result = outcome(loaded) if code == 0 else ("rejected", err.rstrip("\n"))
        if code == 0:
            assert kind == "accepted", f"check-config accepted, resolve_config said {result!r}"
            check_accepted(result)
        else:
            assert code == 2, f"check-config exit code {code}: {err!r}"
            check_rejected(result)
        seen[kind] += 1

    check()
    assert seen["accepted"] + seen["rejected"] >= EXAMPLES, f"only {sum(seen.values())} cases ran"
    assert seen["accepted"] >= 50, f"only {seen['accepted']} accepted cases: the property is barely exercised"
    assert seen["rejected"] >= 250, f"only {seen['rejected']} rejected cases"


# ---------------------------------------------------------------------------
# a fixed, seeded sample through snakemake -n
def seeded_sample(seed: int = 20240611) -> list[dict]:
    """DRY_RUNS mutated configs (at least DRY_ACCEPTED accepted), from the same catalogue."""
    rng = random.Random(seed)
    accepted, rejected = [], []
    sweeps = {frozenset(runs.run_paths(config.resolve_config(BASE), RUN_PATTERN))}  # accepted: each a new sweep
    while len(accepted) + len(rejected) < DRY_RUNS:
        cfg = copy.deepcopy(BASE)
        for _ in range(rng.randint(1, 2)):
            if rng.random() < 0.1:
                parents = [(), *[p for p, n in PATHS if "object" in _types(n)]]
                _unknown_key(cfg, rng.choice(parents), rng.choice(ODD_KEYS), rng.choice([1, 0.5, "x", None]))
                continue
            path, node = rng.choice(PATHS)
            _apply(cfg, path, rng.choice(candidates(path, node, _get(cfg, path))))
        _, loaded = _yaml_round_trip(cfg)
        kind, result = outcome(loaded)
        if kind == "accepted":
            paths = frozenset(runs.run_paths(result, RUN_PATTERN))
            if len(paths) <= 100 and paths not in sweeps:  # a few dozen runs keep the dry runs quick
                sweeps.add(paths)
                accepted.append(loaded)
        elif len(rejected) < DRY_RUNS - DRY_ACCEPTED:
            rejected.append(loaded)
    return accepted + rejected


def test_seeded_sample_through_snakemake_dry_run(tmp_path):
    sample = seeded_sample()
    dirs = []
    for i, cfg in enumerate(sample):
        d = tmp_path / f"case{i:02d}"
        d.mkdir()
        (d / "fuzz.yaml").write_text(yaml.safe_dump(cfg, allow_unicode=True), encoding="utf-8")
        dirs.append(d)
    results = dry_run(ROOT / "Snakefile", "fuzz.yaml", dirs)
    kinds = Counter()
    for d, cfg, (code, out) in zip(dirs, sample, results):
        kind, result = outcome(cfg)
        kinds[kind] += 1
        printed = [line for line in out.splitlines() if "Invalid configuration" in line]
        rest = "\n".join(line for line in out.splitlines() if "Invalid configuration" not in line)
        assert "Traceback" not in rest, f"{d.name}: traceback\n{out}"
        assert not re.search(r"(Error|Exception)\b", rest), f"{d.name}: a Snakemake exception\n{out}"
        if kind == "accepted":
            assert code == 0, f"{d.name}: snakemake -n failed on an accepted config\n{out}"
            assert printed == [], f"{d.name}: snakemake -n rejected an accepted config: {printed}"
            # one indent job per combination and block of jobs.batch seeds (rules indent_seeds0_5, ...)
            table = out.split("Job stats:", 1)[-1].split("\n\n", 1)[0]   # the first table (a dry run prints two)
            planned = re.findall(r"^indent(?:_seeds\d+_\d+)?\s+(\d+)$", table, re.MULTILINE)
            assert planned, f"{d.name}: no indent jobs planned\n{out}"
            count = check_accepted(result)
            blocks = runs.seed_blocks(result["seeds"], result["jobs"]["batch"])
            expected = count // len(result["seeds"]) * len(blocks)
            assert sum(map(int, planned)) == expected, f"{d.name}: indent jobs != combinations x blocks\n{out}"
        else:
            assert code != 0, f"{d.name}: snakemake -n accepted {result!r}"
            assert printed == [result], f"{d.name}: expected {result!r}, got\n{out}"
            assert not (d / "results").exists(), f"{d.name}: results/ created for a rejected config"
    assert kinds["accepted"] >= DRY_ACCEPTED, f"only {kinds['accepted']} accepted configs in the sample"
    assert kinds["rejected"] >= DRY_RUNS - DRY_ACCEPTED, f"only {kinds['rejected']} rejected configs in the sample"
