"""Finite means finite: NaN and infinities are rejected with one line naming
the key, the value and what is allowed -- in the config (resolve_config,
``roughcontact check-config``, ``snakemake -n``), on the command line and in
the argument checks.  ``radius`` alone accepts ``inf`` (a nominally flat surface).
"""

from __future__ import annotations

import contextlib
import copy
import io
import math
from pathlib import Path

import numpy as np
import pytest
import yaml
from snakemake_dry import dry_run

from roughcontact import _validate
from roughcontact import bem
from roughcontact import cli
from roughcontact import errors
from roughcontact import surfaces
from roughcontact.study.config import resolve as config
from roughcontact.study.config.schema import load_schema

ROOT = Path(__file__).resolve().parents[1]
BASE = config.load_config(ROOT / "config.yaml")


def _changed(path: str, value) -> dict:
    """config.yaml with the dotted key *path* set to *value*."""
    cfg = copy.deepcopy(BASE)
    *parents, last = path.split(".")
    node = cfg
    for key in parents:
        node = node[key]
    node[last] = value
    return cfg


# (dotted key, value as written in YAML, the key the message must name, the value it must show)
ISSUE_CASES = [
    ("hurst", "[.nan]", "hurst[0]", "nan"),
    ("h_rms", "[.nan]", "h_rms[0]", "nan"),
    ("h_rms", "[.inf]", "h_rms[0]", "inf"),
    ("radius", "[.nan]", "radius[0]", "nan"),
    ("e_star", ".nan", "e_star", "nan"),
    ("e_star", ".inf", "e_star", "inf"),
    ("grid.length", ".nan", "grid.length", "nan"),
    ("solver.tol", ".nan", "solver.tol", "nan"),
    ("fit.zeta.max_area_fraction", ".nan", "fit.zeta.max_area_fraction", "nan"),
]
MORE_CASES = [
    ("radius", "[0.5, -.inf]", "radius[1]", "-inf"),
    ("radius", "[0.5, nan]", "radius[1]", "nan"),
    ("hurst", "[0.5, NaN]", "hurst[1]", "nan"),
    ("hurst", "[.NaN, .NaN]", "hurst[0]", "nan"),
    ("h_rms", "[Infinity]", "h_rms[0]", "inf"),
    ("seeds", ".nan", "seeds", "nan"),
    ("grid.n", ".inf", "grid.n", "inf"),
    ("forces.sphere.to", ".inf", "forces.sphere.to", "inf"),
    ("forces.flat.from", ".nan", "forces.flat.from", "nan"),
    ("solver.rel_step", ".nan", "solver.rel_step", "nan"),
    ("fit.slopes.high_min_ratio", ".inf", "fit.slopes.high_min_ratio", "inf"),
    ("fit.zeta.sphere_max_force_ratio", "-.inf", "fit.zeta.sphere_max_force_ratio", "-inf"),
    ("radius", "[1e999]", "radius[0]", "1e999"),  # a numeral beyond float range is not silently inf
    ("e_star", "1" + "0" * 400, "e_star", "integer of about 401 digits"),
]


def _cases(table):
    return pytest.mark.parametrize("key, text, named, shown", table, ids=[f"{c[0]}={c[1][:12]}" for c in table])


def _yaml_config(key: str, text: str) -> dict:
    """config.yaml with *key* set to the YAML text *text*, as a user would write it."""
    return _changed(key, yaml.safe_load(f"value: {text}")["value"])


def _rejection(cfg) -> str:
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config(cfg)
    return config.error_line(info.value)


@_cases(ISSUE_CASES + MORE_CASES)
def test_non_finite_value_is_rejected_with_one_line(key, text, named, shown):
    line = _rejection(_yaml_config(key, text))
    assert len(line.splitlines()) == 1, f"more than one line: {line!r}"
    assert line.startswith("Invalid configuration: "), f"not the workflow's prefix: {line!r}"
    assert f"'{named}'" in line, f"does not name {named}: {line!r}"
    assert f"= {shown}" in line or shown in line, f"does not show the value {shown}: {line!r}"
    assert "allowed: " in line, f"does not say what is allowed: {line!r}"


@_cases(ISSUE_CASES)
def test_message_says_finite(key, text, named, shown):
    line = _rejection(_yaml_config(key, text))
    assert "finite number" in line, f"does not say that the number must be finite: {line!r}"


@pytest.mark.parametrize("text", ["[0.5, .inf]", "[0.5, inf]", "[0.5, .Inf]", "[0.5, '+inf']", "[0.5, Infinity]"])
def test_radius_accepts_inf_as_a_flat_surface(text):
    cfg = config.resolve_config(_yaml_config("radius", text))
    assert cfg["radius"][0] == 0.5, f"sphere radius changed: {cfg['radius']}"
    assert cfg["radius"][1] == math.inf, f"{text} did not resolve to a flat surface: {cfg['radius']}"


def _schema_with_axis() -> dict:
    """The schema plus a sweep axis it does not have yet: numbers > 0 or null."""
    schema = copy.deepcopy(load_schema(None))
    schema["properties"]["rolloff"] = {"description": "roll-off wavelengths", "type": "array", "minItems": 1,
                                       "items": {"type": ["number", "null"], "exclusiveMinimum": 0}}
    return schema


@pytest.mark.parametrize("text, named, shown", [("[.nan]", "rolloff[0]", "nan"), ("[null, .inf]", "rolloff[1]", "inf")])
def test_a_new_key_is_checked_without_new_code(text, named, shown):
    cfg = _changed("e_star", 1.0) | {"rolloff": yaml.safe_load(f"value: {text}")["value"]}
    with pytest.raises(errors.ConfigError) as info:
        config.resolve_config(cfg, schema=_schema_with_axis())
    line = config.error_line(info.value)
    assert f"'{named}' = {shown} is not allowed" in line, f"new axis not checked: {line!r}"
    assert "allowed: a finite number > 0 or null" in line, f"new axis not described: {line!r}"


def test_a_new_key_accepts_finite_values_and_null():
    cfg = _changed("e_star", 1.0) | {"rolloff": [None, 0.1]}
    resolved = config.resolve_config(cfg, schema=_schema_with_axis())
    assert resolved["rolloff"] == [None, 0.1], f"rolloff resolved to {resolved['rolloff']}"


def test_default_config_resolves_unchanged():
    """The schema annotation and the finite walk leave the default sweep alone."""
    cfg = config.resolve_config(BASE)
    assert cfg["radius"] == [0.5, math.inf], f"radius axis changed: {cfg['radius']}"
    assert cfg["seeds"] == list(range(6)), f"seeds changed: {cfg['seeds']}"


def _check_config(path: Path) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = cli.main(["check-config", str(path)])
    return code, err.getvalue()


@_cases(ISSUE_CASES)
def test_check_config_prints_the_workflow_line(tmp_path, key, text, named, shown):
    cfg = _yaml_config(key, text)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(cfg))
    code, err = _check_config(path)
    assert code == 2, f"check-config exit code {code} for {key}: {text}"
    assert err.splitlines() == [_rejection(cfg)], f"check-config printed {err!r}"


def test_check_config_unreadable_and_malformed_files(tmp_path):
    missing = tmp_path / "missing.yaml"
    code, err = _check_config(missing)
    assert code == 2, f"exit code {code} for a missing file"
    assert len(err.splitlines()) == 1 and err.startswith("Invalid configuration: cannot read"), err
    broken = tmp_path / "broken.yaml"
    broken.write_text("grid: {n: 65\nhurst: [0.5\n")
    code, err = _check_config(broken)
    assert code == 2, f"exit code {code} for malformed YAML"
    assert len(err.splitlines()) == 1 and "is not valid YAML (line" in err, err


def test_snakemake_dry_run_rejects_each_issue_case(tmp_path):
    """The issue's cases through a real ``snakemake -n``: one line, no job, no Snakemake exception."""
    dirs, lines = [], []
    for i, (key, text, _, _) in enumerate(ISSUE_CASES):
        d = tmp_path / f"case{i}"
        d.mkdir()
        cfg = _yaml_config(key, text)
        (d / "bad.yaml").write_text(yaml.safe_dump(cfg))
        dirs.append(d)
        lines.append(_rejection(cfg))
    for (key, text, _, _), d, line, (code, out) in zip(ISSUE_CASES, dirs, lines,
                                                       dry_run(ROOT / "Snakefile", "bad.yaml", dirs)):
        assert code != 0, f"snakemake -n accepted {key}: {text}\n{out}"
        printed = [l for l in out.splitlines() if "Invalid configuration" in l]
        assert printed == [line], f"{key}: {text}: expected {line!r}, got\n{out}"
        assert "Exception" not in out and "Traceback" not in out, f"{key}: {text}: {out}"
        assert not (d / "results").exists(), f"{key}: {text}: results/ was created"


# ---------------------------------------------------------------------------
# the command line
def _indent(tmp_path, *flags) -> tuple[int, str, Path]:
    out = tmp_path / "run.nc"
    given = {"--hurst": "0.7", "--radius": "0.5", "--h-rms": "9e-3", "--n": "17", "--force-count": "3"}
    given.update(zip(flags[::2], flags[1::2]))
    argv = ["indent", *(f"{flag}={value}" for flag, value in given.items()), "-q", "-o", str(out)]
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        code = cli.main(argv)
    return code, err.getvalue(), out


@pytest.mark.parametrize("flag, value", [("--radius", "nan"), ("--radius", "-inf"), ("--hurst", "nan"),
                                         ("--h-rms", "inf"), ("--e-star", "nan"), ("--length", "inf"),
                                         ("--tol", "nan"), ("--rel-step", "nan"), ("--force-from", "nan"),
                                         ("--force-to", "inf"), ("--e-star", "1e999")])
def test_indent_rejects_non_finite_flags(tmp_path, flag, value):
    code, err, out = _indent(tmp_path, flag, value)
    assert code == 2, f"indent {flag} {value} exit code {code}"
    assert len(err.splitlines()) == 1, f"not one line: {err!r}"
    assert err.startswith(f"roughcontact indent: invalid argument: {flag} ("), f"does not name {flag}: {err!r}"
    assert "finite number" in err, f"does not say what is allowed: {err!r}"
    assert not out.exists(), f"a run file was written for {flag} {value}"


def test_indent_radius_inf_is_a_flat_run():
    args = cli.build_parser().parse_args(["indent", "--hurst", "0.7", "--radius", "inf", "--h-rms", "9e-3", "-o", "x.nc"])
    settings = cli.settings_from_args(args)
    assert settings.kind == "flat", f"--radius inf gave {settings.kind}"
    assert settings.periodic is True, "--radius inf is not periodic"


# ---------------------------------------------------------------------------
# the one rule and the package's argument checks
@pytest.mark.parametrize("value, finite, finite_or_inf", [
    (0.5, True, True), (0, True, True), (-1, True, True), (np.float32(2.0), True, True),
    (math.nan, False, False), (math.inf, False, True), (-math.inf, False, False), (np.nan, False, False),
    (10**400, False, False), (True, False, False), ("1.0", False, False), (None, False, False),
])
def test_is_finite_number(value, finite, finite_or_inf):
    assert _validate.is_finite_number(value) is finite, f"is_finite_number({value!r})"
    assert _validate.is_finite_number(value, allow_inf=True) is finite_or_inf, f"allow_inf: {value!r}"


@pytest.mark.parametrize("radius", [math.nan, -math.inf, 0.0, -1.0, "0.5"])
def test_check_radius_rejects(radius):
    with pytest.raises(ValueError, match="radius must be a finite number > 0 or inf"):
        _validate.check_radius(radius)


@pytest.mark.parametrize("radius", [0.5, 1e300, math.inf])
def test_check_radius_accepts(radius):
    assert _validate.check_radius(radius) is None, f"check_radius({radius!r})"


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, 10**400])
def test_check_finite_positive_rejects(value):
    with pytest.raises(ValueError, match="length must be a finite number > 0"):
        _validate.check_finite_positive("length", value)


@pytest.mark.parametrize("kwargs", [{"hurst": math.nan}, {"h_rms": math.nan}, {"h_rms": math.inf},
                                    {"length": math.nan}, {"radius": math.nan}, {"radius": math.inf}])
def test_rough_sphere_rejects_non_finite(kwargs):
    args = {"radius": 0.5, "hurst": 0.7, "h_rms": 9e-3, "length": 1.0, "seed": 0} | kwargs
    with pytest.raises(ValueError, match="must be"):
        surfaces.rough_sphere(17, **args)


@pytest.mark.parametrize("kwargs", [{"e_star": math.nan}, {"length": math.inf}, {"tol": math.nan}])
def test_solve_rejects_non_finite(kwargs):
    args = {"length": 1.0, "e_star": 1.0, "tol": 1e-8} | kwargs
    with pytest.raises(ValueError, match="must be a finite number"):
        bem.solve(surfaces.paraboloid(17, radius=0.5), force=1e-4, **args)


def test_solve_rejects_non_finite_force():
    with pytest.raises(ValueError, match="force must be a finite number"):
        bem.solve(surfaces.paraboloid(17, radius=0.5), force=math.nan, length=1.0, e_star=1.0)
