"""Sphinx configuration of the documentation site (`make docs`); builds offline."""

import inspect
from importlib import import_module

import turntable

project = "turntable"
author = "turntable developers"
copyright = "turntable developers, MIT licence"
release = version = turntable.__version__

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = ["_build"]
default_role = "py:obj"
myst_enable_extensions = ["dollarmath"]
myst_heading_anchors = 3

autodoc_typehints = "none"
autodoc_member_order = "bysource"
autosummary_generate = False
numpydoc_show_class_members = False
# Every public function documented has an Examples section (run by `make test` as doctests).
API_MODULES = [
    "turntable",
    "turntable.rolling",
    "turntable.film",
    "turntable.fit",
    "turntable.claims",
    "turntable.config",
]
numpydoc_validation_checks = {"EX01"}


def _public_functions(module_name):
    """The functions that autodoc's ``:members:`` documents: those of ``__all__``, else
    those defined in the module."""
    module = import_module(module_name)
    names = getattr(module, "__all__", None) or [
        name
        for name, obj in vars(module).items()
        if getattr(obj, "__module__", None) == module_name and not name.startswith("_")
    ]
    return [f"{module_name}.{n}" for n in names if inspect.isfunction(getattr(module, n))]


API_FUNCTIONS = [f for module in API_MODULES for f in _public_functions(module)]
numpydoc_validation_exclude = {
    "^(?!(?:" + "|".join(f.replace(".", r"\.") for f in API_FUNCTIONS) + ")$)"
}

html_theme = "pydata_sphinx_theme"
html_title = f"turntable {release}"
html_static_path = []
html_show_sourcelink = False
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}


def _plain_bars(app, what, name, obj, options, lines):
    """The docstrings write |x| for an absolute value, never a substitution."""
    lines[:] = [line.replace("|", r"\|") for line in lines]


def setup(app):
    app.connect("autodoc-process-docstring", _plain_bars, priority=400)
