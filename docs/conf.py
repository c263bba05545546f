"""Sphinx configuration of the roughcontact documentation.

Sphinx (with numpydoc and MyST) because the package's docstrings are numpydoc, as in numpy,
scipy, xarray and ContactMechanics, and autodoc/autosummary turn them into the API reference;
MyST lets the guide be written in Markdown and myst-nb executes the example notebook.
``python -m sphinx -W -b html docs docs/_build/html`` builds it with warnings as errors.
"""
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS / "_ext"))
sys.path.insert(0, str(DOCS.parent / "src"))
sys.path.insert(0, str(DOCS))

import make_module_table  # noqa: E402
import roughcontact  # noqa: E402

project = "roughcontact"
author = "the roughcontact developers"
copyright = "2026, the roughcontact developers"
release = roughcontact.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "myst_nb",
    "generated_pages",
]

source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
# the module table is a part of the package guide (included there), not a page of its own
exclude_patterns = ["_build", "**.ipynb_checkpoints", "_ext", str(make_module_table.GENERATED)]
myst_enable_extensions = ["dollarmath", "colon_fence"]
myst_heading_anchors = 3
suppress_warnings = ["myst.header"]

autosummary_generate = True
autodoc_default_options = {"members": True, "undoc-members": False, "show-inheritance": True}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_validation_checks = set()
numpydoc_xref_param_type = False

# the example notebook runs the tiny preset itself when no results are at hand
nb_execution_mode = "force"
nb_execution_timeout = 600
nb_execution_raise_on_error = True

html_theme = "pydata_sphinx_theme"
html_title = f"roughcontact {release}"
html_theme_options = {
    "navigation_depth": 2,
    "show_toc_level": 2,
    # the wide tables of the references and the results pages get the whole width
    "secondary_sidebar_items": {"_generated/*": [], "results/presets/*": []},
}
html_static_path = ["_static"]
html_css_files = ["wide.css"]


def setup(app):
    """The package guide's table of every module (``docs/make_module_table.py``), written into
    ``_generated/`` when the build starts, before any page is read."""
    app.connect("builder-inited", make_module_table.on_builder_inited)
