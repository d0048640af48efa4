"""The package's structure: no import cycle among its modules, no module over 500 lines;
and the code of a job (`turntable._imports.code_of`) holds every module a run imports.

The import graph is read with `ast` (nothing imported): ``turntable.film`` importing
``turntable.fit.models`` depends on ``turntable.fit`` too (but a module does not depend on
the packages it is part of).
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from turntable._imports import PACKAGE, code_of, import_graph, module_names

MAX_LINES = 500


def find_cycle(graph: dict[str, set[str]]) -> list[str]:
    """A cycle of ``graph`` as the list of its nodes (first one repeated), or []."""
    state: dict[str, int] = {}  # 1 on the path, 2 done
    path: list[str] = []

    def visit(node: str) -> list[str]:
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                return [*path[path.index(nxt) :], nxt]
            if nxt not in state and (cycle := visit(nxt)):
                return cycle
        path.pop()
        state[node] = 2
        return []

    for node in sorted(graph):
        if node not in state and (cycle := visit(node)):
            return cycle
    return []


def test_no_import_cycle() -> None:
    graph = import_graph()
    assert "turntable.fit.lsq" in graph["turntable.fit"]
    assert find_cycle(graph) == [], " -> ".join(find_cycle(graph))


@pytest.mark.parametrize("name", sorted(module_names()))
def test_module_is_short(name: str) -> None:
    n = len(module_names()[name].read_text().splitlines())
    assert n <= MAX_LINES, f"{name}: {n} lines"


def test_a_local_import_back_is_a_cycle(tmp_path: Path) -> None:
    """What the check sees: a function-level import that closes a cycle, relative or not."""
    pkg = tmp_path / "turntable"
    (pkg / "fit").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "film.py").write_text("def simulate():\n    from .fit import models\n")
    (pkg / "fit" / "__init__.py").write_text("from turntable.fit.lsq import fit\n")
    (pkg / "fit" / "models.py").write_text("")
    (pkg / "fit" / "lsq.py").write_text("from turntable.film import simulate\n")
    assert find_cycle(import_graph(pkg)) == [
        "turntable.film",
        "turntable.fit",
        "turntable.fit.lsq",
        "turntable.film",
    ]
    (pkg / "film.py").write_text("")
    assert find_cycle(import_graph(pkg)) == []


@pytest.mark.parametrize(
    "module",
    ["turntable", "turntable.fit", "turntable.claims", "turntable.campaign", "turntable.cli"],
)
def test_importing_loads_no_heavy_library(module: str) -> None:
    """scipy, sympy and matplotlib cost 0.3-0.7 s of CPU each to import, in every one of the
    build's processes that imports them; these modules import them where they are used."""
    code = f"import sys, {module}; print(*sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    loaded = {name.split(".")[0] for name in out.stdout.split()}
    assert "numpy" in loaded
    assert loaded & {"scipy", "sympy", "matplotlib"} == set()


# Every module imported alone, in one interpreter: the package's modules it loaded.
_LOADED = """
import importlib, json, sys
out = {}
for name in json.loads(sys.argv[1]):
    for m in [m for m in sys.modules if m == "turntable" or m.startswith("turntable.")]:
        del sys.modules[m]
    importlib.import_module(name)
    out[name] = sorted(m for m in sys.modules if m.split(".")[0] == "turntable")
print(json.dumps(out))
"""


def _loaded(code: str, entries: list[str], **kw) -> dict[str, list[str]]:
    """What ``code`` (`_LOADED`, `_SCRIPT_LOADED`) prints for ``entries``, in a fresh Python."""
    argv = [sys.executable, "-c", code, json.dumps(entries)]
    return json.loads(subprocess.run(argv, capture_output=True, text=True, check=True, **kw).stdout)


def _missing(loaded: dict[str, list[str]], code) -> dict[str, list[str]]:
    """For each entry, the package's modules it loaded that ``code(entry)`` leaves out."""
    files = {path: name for name, path in module_names().items()}
    out = {}
    for entry, names in loaded.items():
        static = {files[p] for p in code(entry) if p in files}
        if set(names) - static:
            out[entry] = sorted(set(names) - static)
    return out


def test_code_of_a_module_holds_every_module_its_import_loads() -> None:
    """The second route: what Python loads, against what `code_of` reads from the source."""
    names = sorted(n for n in module_names() if not n.endswith("__main__"))
    loaded = _loaded(_LOADED, names)
    assert len(names) > 50
    assert _missing(loaded, code_of) == {}


# Each script's imports alone, its folder first on sys.path: the package's modules loaded.
_SCRIPT_LOADED = """
import ast, json, sys
from pathlib import Path
out = {}
for script in json.loads(sys.argv[1]):
    home = str(Path(script).parent)
    for m in list(sys.modules):
        f = getattr(sys.modules[m], "__file__", None) or ""
        if m.split(".")[0] == "turntable" or f.startswith(home):
            del sys.modules[m]
    sys.path.insert(0, home)
    tree = ast.parse(Path(script).read_text())
    body = [n for n in tree.body if isinstance(n, (ast.Import, ast.ImportFrom))]
    exec(compile(ast.Module(body=body, type_ignores=[]), script, "exec"), {})
    sys.path.remove(home)
    out[script] = sorted(m for m in sys.modules if m.split(".")[0] == "turntable")
print(json.dumps(out))
"""


def test_code_of_a_script_holds_every_module_its_imports_load() -> None:
    """The scripts of the workflow's jobs, and the modules beside them that they import
    (``_style``, ``report_figure``), against what `code_of` reads from their source."""
    root = PACKAGE.parents[1]
    scripts = sorted(
        str(p)
        for folder in ("scripts", "workflow/scripts")
        for p in (root / folder).glob("*.py")
        if not p.name.startswith("_")
    )
    loaded = _loaded(_SCRIPT_LOADED, scripts, cwd=root)
    assert len(scripts) > 10
    assert "turntable._atomic" in loaded[str(root / "scripts/fig1_schematic.py")]
    assert _missing(loaded, lambda script: code_of(Path(script))) == {}


def test_code_of_follows_scripts_lazy_imports_and_data(tmp_path: Path) -> None:
    """A script's import of a module beside it is followed; a function's import counts; a
    package importing by name runs all its submodules; a data file goes with the module that
    names it or its folder, and only with that one."""
    pkg = tmp_path / "turntable"
    for folder in ["claims", "templates", "video"]:
        (pkg / folder).mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "_templates.py").write_text("LOADER = ('turntable', 'templates')\n")
    (pkg / "templates" / "page.html.j2").write_text("")
    (pkg / "claims" / "__init__.py").write_text(
        "import importlib\nfor n in ['a']:\n    importlib.import_module(f'{__name__}.{n}')\n"
    )
    (pkg / "claims" / "a.py").write_text("def f():\n    from .. import _templates\n")
    (pkg / "video" / "__init__.py").write_text("")
    (pkg / "video" / "track.py").write_text("")
    scripts = tmp_path / "scripts"
    scripts.mkdir()
    (scripts / "page.py").write_text("from helper import run\n")
    (scripts / "helper.py").write_text("import turntable.claims\n")

    def relative(*entries):
        return sorted(str(p.relative_to(pkg)) for p in code_of(*entries, root=pkg))

    assert relative(scripts / "page.py") == [
        "__init__.py",
        "_templates.py",
        "claims/__init__.py",
        "claims/a.py",
        "templates/page.html.j2",
    ]
    assert relative("turntable.video.track") == [
        "__init__.py",
        "video/__init__.py",
        "video/track.py",
    ]
