"""The worked examples of ``docs/guide/extending/`` loaded in this process, as the module their
first line names (``# module: roughcontact.<dotted.path>``), and unloaded again: the in-process
tests of the registries run the guide's own text. ``tests/test_extending.py`` copies the same
files into a scratch copy of the package and runs a study with them end to end."""
from __future__ import annotations

import contextlib
import importlib.util
import re
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "docs" / "guide" / "extending"


def module_of(example: Path) -> str:
    """The dotted module an example goes to: its first line, ``# module: roughcontact.<path>``."""
    first = example.read_text().splitlines()[0]
    match = re.fullmatch(r"# module: (roughcontact(?:\.\w+)+)", first.strip())
    if not match:
        raise ValueError(f"{example.name}: first line {first!r} is not '# module: roughcontact.<dotted.path>'")
    return match.group(1)


@contextlib.contextmanager
def loaded(name: str, registry: dict, key: str):
    """Import the example *name* (``model_example.py``) as its module, which registers one entry
    *key* in *registry*; yield the module; afterwards remove the entry and the module."""
    path = EXAMPLES / name
    module = module_of(path)
    spec = importlib.util.spec_from_file_location(module, path)
    loaded_module = importlib.util.module_from_spec(spec)
    sys.modules[module] = loaded_module
    try:
        spec.loader.exec_module(loaded_module)
        yield loaded_module
    finally:
        registry.pop(key, None)
        sys.modules.pop(module, None)
