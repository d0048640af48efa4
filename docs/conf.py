"""Sphinx configuration of the documentation site (`make docs`); builds offline."""

import contextlib
import importlib.metadata
import inspect
import pkgutil
import re
import sys
import zlib
from importlib import import_module
from pathlib import Path

import sphinx.util.logging
from docutils import nodes
from docutils.statemachine import StringList
from sphinx import addnodes
from sphinx.errors import PycodeError
from sphinx.ext.intersphinx import InventoryAdapter
from sphinx.pycode import ModuleAnalyzer
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util.docutils import SphinxDirective

import turntable

sys.path.insert(0, str(Path(__file__).parent))
import site_pages

site_pages.write_all()

project = "turntable"
author = "turntable developers"
copyright = "turntable developers, MIT licence"
release = version = importlib.metadata.version("turntable")

extensions = [
    "myst_nb",  # Markdown (MyST) and the notebooks of docs/notebooks/
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx-mathjax-offline",  # its module name has hyphens
    "sphinx.ext.intersphinx",
    "sphinx_copybutton",
    "matplotlib.sphinxext.plot_directive",
]
exclude_patterns = ["_build", "_intersphinx", "site_pages.py"]
default_role = "py:obj"
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath", "amsmath"]
# The notebooks are shown as `make notebooks` ran them.
nb_execution_mode = "off"

# Every reference must resolve; the ones below name what has no inventory to link to.
nitpicky = True
nitpick_ignore = [
    # OpenCV's documentation is Doxygen, with no Sphinx inventory.
    ("py:obj", "cv2.fitEllipseDirect"),
]

_HERE = Path(__file__).parent
_INVENTORIES = _HERE / "_intersphinx"


def _compressed(name):
    """The inventory of ``_intersphinx/NAME.txt``: its first three lines, then the others
    (its objects) compressed."""
    lines = (_INVENTORIES / f"{name}.txt").read_text().splitlines(keepends=True)
    header = "".join(lines[:3]) + "# The remainder of this file is compressed using zlib.\n"
    body = "".join(line for line in lines if not line.startswith("#"))
    path = _HERE / "_build" / "intersphinx" / f"{name}.inv"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(header.encode() + zlib.compress(body.encode(), 9))
    return str(path)


# Offline: the inventories are in the repository (_intersphinx/README.md).
intersphinx_mapping = {
    "python": ("https://docs.python.org/3/", str(_INVENTORIES / "python.inv")),
    "scipy": ("https://docs.scipy.org/doc/scipy/", str(_INVENTORIES / "scipy.inv")),
    "numpy": ("https://numpy.org/doc/stable/", _compressed("numpy")),
    "matplotlib": ("https://matplotlib.org/stable/", _compressed("matplotlib")),
}
intersphinx_timeout = 1
copybutton_exclude = ".linenos, .gp, .go"
copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True

autodoc_typehints = "none"
autosummary_generate = False
numpydoc_show_class_members = False
# The types of the Parameters and Returns sections link to their documentation.
numpydoc_xref_param_type = True
numpydoc_xref_aliases = {
    "array_like": "numpy.typing.ArrayLike",
    "ndarray": "numpy.ndarray",
    "mapping": ":term:`mapping <python:mapping>`",
    "path-like": ":term:`path-like <python:path-like object>`",
    **{name: f"turntable.film.{name}" for name in ("Camera", "Film", "Rig", "Setup")},
    "Pose": "turntable.video.camera.Pose",
}
# Words of the types that name no object, and the video's internal types (not on the site).
numpydoc_xref_ignore = {
    *("of", "or", "optional", "default", "shape", "each", "and", "a", "the", "low", "high"),
    *("Calibration", "Candidate", "Ellipse", "InputError", "Seed", "VideoError", "VideoInfo"),
}

# The examples of the pages run when the site is built (``{plot}``), shown with their code.
plot_include_source = True
plot_html_show_source_link = False
plot_html_show_formats = False
plot_formats = [("png", 100)]

html_theme = "pydata_sphinx_theme"
html_static_path = ["_static"]
html_css_files = ["custom.css"]
html_title = f"turntable {release}"
html_show_sourcelink = False
html_theme_options = {
    "navigation_with_keys": False,
    "header_links_before_dropdown": 7,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": [],
}
# Pages without sub-pages have no left sidebar, and their text the width it frees.
html_sidebars = {
    page: []
    for page in (
        "index",
        "getting-started",
        "installation",
        "results",
        "theory",
        "citing",
        "changelog",
    )
}

#: The modules of the API reference, one page each (docs/api/).
API_MODULES = [
    "turntable",
    "turntable.rolling",
    "turntable.film",
    "turntable.fit",
    "turntable.claims",
    "turntable.config",
    "turntable.video.track",
    "turntable.video.render",
    "turntable.video.camera",
]


def public_names(module_name):
    """The names of ``__all__``, else those defined in the module (a function or class, or
    a constant with a doc comment ``#:``) and not private."""
    module = import_module(module_name)
    commented = set()
    with contextlib.suppress(PycodeError):
        commented = {a for _, a in ModuleAnalyzer.for_module(module_name).find_attr_docs()}
    return getattr(module, "__all__", None) or [
        name
        for name, obj in vars(module).items()
        if (getattr(obj, "__module__", None) == module_name or name in commented)
        and not name.startswith("_")
    ]


def public_functions(module_name):
    module = import_module(module_name)
    return [n for n in public_names(module_name) if inspect.isfunction(getattr(module, n))]


# Every public function of the API documents its parameters and what it returns, and has an
# Examples section (`make test` runs them).
numpydoc_validation_checks = {"EX01", "PR01", "PR02", "RT01"}
_API_FUNCTIONS = [f"{m}.{n}" for m in API_MODULES for n in public_functions(m)]
numpydoc_validation_exclude = {
    "^(?!(?:" + "|".join(f.replace(".", r"\.") for f in _API_FUNCTIONS) + ")$)"
}


def _doc_commented():
    """Names given a doc comment (#:) in some module of the package: name to a list of
    (module, comment lines)."""
    names = {}
    for info in pkgutil.walk_packages(turntable.__path__, "turntable."):
        with contextlib.suppress(PycodeError):
            for (_, attr), doc in ModuleAnalyzer.for_module(info.name).find_attr_docs().items():
                names.setdefault(attr, []).append((info.name, doc))
    return names


_LOGGER = sphinx.util.logging.getLogger(__name__)
#: Every public class of the API defined by the package has an example too (a warning fails
#: the build).
_EXAMPLES = re.compile(r"^Examples\n-+$", re.MULTILINE)


class ApiMembers(SphinxDirective):
    """``.. api-members:: module``: a table of its public functions, each function, then
    its public classes and its constants that have a doc comment."""

    required_arguments = 1
    commented = _doc_commented()

    def comment(self, module, n):
        """The doc comment of constant ``n`` of ``module``, where the package writes it
        (a name imported from another module keeps its comment there)."""
        places = sorted(self.commented[n], key=lambda place: place[0] != module.__name__)
        for where, doc in places:
            if getattr(import_module(where), n, None) is getattr(module, n):
                doc = list(doc)
                _plain_bars(None, "data", n, None, None, doc)
                return doc
        return []

    def run(self):
        name = self.arguments[0]
        module = import_module(name)
        functions = public_functions(name)
        others = [
            n
            for n in public_names(name)
            if n not in functions and (inspect.isclass(getattr(module, n)) or n in self.commented)
        ]
        lines = [".. autosummary::", "   :nosignatures:", "", *(f"   {n}" for n in functions), ""]
        lines += [line for n in functions for line in (f".. autofunction:: {name}.{n}", "")]
        if others:
            lines += [".. rubric:: Classes and constants", ""]
        for n in others:
            if inspect.isclass(getattr(module, n)):
                cls = getattr(module, n)
                own = cls.__module__.startswith("turntable")  # not one made by jsonschema
                if own and not _EXAMPLES.search(inspect.getdoc(cls) or ""):
                    where = self.get_location()
                    _LOGGER.warning(f"{name}.{n}: no Examples section", location=where)
                lines += [f".. autoclass:: {name}.{n}", "   :members:", ""]
            else:
                value = site_pages.round_floats(repr(getattr(module, n)), 6)
                lines += [f".. py:data:: {n}", f"   :module: {name}", f"   :value: {value}", ""]
                lines += [f"   {line}" if line else "" for line in self.comment(module, n)]
        container = nodes.container()
        self.state.nested_parse(StringList(lines), self.content_offset, container)
        return container.children


def _skip_field_aliases(app, what, name, obj, skip, options):
    """The fields of a NamedTuple are in its Attributes section, not again as members."""
    if (getattr(obj, "__doc__", None) or "").startswith("Alias for field number"):
        return True
    return None


#: Inline code, maths and references, whose text is taken as it is.
_INLINE_LITERAL = re.compile(r"(``.+?``|:math:`[^`]*`|`[^`]*`)")


def _plain_bars(app, what, name, obj, options, lines):
    """The docstrings write |x| for an absolute value, never a substitution: escape it in
    running text (not in code, maths, or the blocks after ``::`` and ``.. math::``)."""
    block_indent = None
    for i, line in enumerate(lines):
        indent = len(line) - len(line.lstrip())
        if block_indent is not None and (not line.strip() or indent > block_indent):
            continue
        block_indent = None
        parts = _INLINE_LITERAL.split(line)
        parts[::2] = [part.replace("|", r"\|") for part in parts[::2]]
        lines[i] = "".join(parts)
        if line.rstrip().endswith("::"):
            block_indent = indent


class LinkCodeNames(SphinxPostTransform):
    """In the Markdown pages, inline code that is the full name of a documented Python
    object (``turntable.solve``, ``turntable.solve()``, ``turntable.solve(...)``), this
    site's or one of the linked projects', links to it."""

    default_priority = 5  # before the references are resolved (10)

    def run(self, **kwargs):
        if not str(self.document.get("source", "")).endswith(".md"):
            return
        domain = self.env.get_domain("py")
        names = set(domain.objects) | set(domain.modules)
        for kind, objects in InventoryAdapter(self.env).main_inventory.items():
            if kind.startswith("py:"):
                names |= set(objects)
        for node in list(self.document.findall(nodes.literal)):
            text = node.astext()
            name = text.removesuffix("()").removesuffix("(...)")
            if name not in names or isinstance(node.parent, nodes.reference):
                continue
            xref = addnodes.pending_xref(
                "", refdomain="py", reftype="obj", reftarget=name, refexplicit=True
            )
            xref += nodes.literal(text, text, classes=["xref", "py", "py-obj"])
            node.replace_self(xref)


def _rounded_signature(app, what, name, obj, options, signature, return_annotation):
    """Default values in signatures with 6 significant digits at most."""
    if signature:
        return site_pages.round_floats(signature, 6), return_annotation
    return None


def setup(app):
    app.connect("autodoc-process-signature", _rounded_signature)
    app.add_post_transform(LinkCodeNames)
    app.add_directive("api-members", ApiMembers)
    app.connect("autodoc-process-docstring", _plain_bars, priority=400)
    app.connect("autodoc-skip-member", _skip_field_aliases)
