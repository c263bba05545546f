"""Pages generated at build time from what they document, so that they cannot go stale:
the configuration reference from the package's JSON schema and the command-line reference
from the argument parser. Written into ``docs/_generated/`` (ignored by git)."""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

import yaml

from roughcontact import cli
from roughcontact.study.config import schema


def _text(node: dict) -> str:
    return " ".join(str(node.get("description", "")).split())


def _allowed(node: dict, root: dict) -> str:
    node = schema.deref(node, root)
    parts = []
    if "enum" in node:
        parts.append(" or ".join(f"`{v}`" for v in node["enum"]))
    kind = node.get("type")
    if kind:
        parts.append(kind if isinstance(kind, str) else " or ".join(kind))
    for key, sign in (("minimum", "≥"), ("exclusiveMinimum", ">"), ("maximum", "≤"), ("exclusiveMaximum", "<")):
        if key in node:
            parts.append(f"{sign} {node[key]}")
    if node.get(schema.ALLOW_INF):
        parts.append("or `.inf`")
    if "items" in node:
        parts.append("of " + _allowed(node["items"], root))
    if "oneOf" in node:
        parts.append("; or ".join(_allowed(branch, root) for branch in node["oneOf"]))
    return ", ".join(p for p in parts if p)


def _rows(node: dict, root: dict, prefix: str, required: set, out: list) -> None:
    for name, sub in node.get("properties", {}).items():
        sub_d = schema.deref(sub, root)
        key = f"{prefix}{name}"
        default = sub.get("default", sub_d.get("default"))
        if name in required:
            status = "**required**"
        elif "properties" in sub_d:
            status = "(its keys)"
        elif default is not None or "default" in sub or "default" in sub_d:
            status = "`" + yaml.safe_dump(default, default_flow_style=True, width=1000).strip().removesuffix("...").strip() + "`"
        else:
            status = "optional"
        out.append(f"| `{key}` | {status} | {_allowed(sub, root)} | {_text(sub) or _text(sub_d)} |")
        if "properties" in sub_d:
            _rows(sub_d, root, key + ".", set(sub_d.get("required", [])), out)


def configuration_reference() -> str:
    root = schema.load_schema(None)
    rows = []
    _rows(root, root, "", set(root.get("required", [])), rows)
    return "\n".join([
        "# Configuration reference",
        "",
        "Generated from the package's JSON schema (`src/roughcontact/study/config/config.schema.yaml`) when the",
        "documentation is built. Only the four sweep axes are required; every other key takes the",
        "default shown. Forces are `F/(E* L²)`; lengths are in the unit of `grid.length`.",
        "",
        "| key | default | allowed | meaning |",
        "|---|---|---|---|",
        *rows,
        "",
    ])


def cli_reference() -> str:
    parts = ["# Command-line reference", "", "Generated from the argument parser when the documentation is built.", ""]
    parts += ["```text", _help([]), "```", ""]
    for name in cli.COMMANDS:
        parts += [f"## `roughcontact {name}`", "", "```text", _help([name]), "```", ""]
    return "\n".join(parts)


def _help(words: list) -> str:
    """What ``roughcontact WORDS --help`` prints."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
        cli.build_parser().parse_args([*words, "--help"])
    return out.getvalue().rstrip()


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def _generate(app) -> None:
    out = Path(app.srcdir) / "_generated"
    _write(out / "configuration_reference.md", configuration_reference())
    _write(out / "cli_reference.md", cli_reference())


def setup(app):
    app.connect("builder-inited", _generate)
    return {"version": "1", "parallel_read_safe": True}
