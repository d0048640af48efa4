"""The package's structure: no import cycle among its modules, no module over 500 lines.

Every module of src/turntable is parsed with `ast` (nothing is imported): its imports at
the top and inside functions, relative ones resolved.  Importing a submodule runs the
packages above it first, so ``turntable.film`` importing ``turntable.fit.models`` depends
on ``turntable.fit`` too (but a module does not depend on the packages it is part of).
"""

from __future__ import annotations

import ast
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

import turntable

PACKAGE = Path(turntable.__file__).resolve().parent
MAX_LINES = 500


def _module_names(root: Path = PACKAGE) -> dict[str, Path]:
    """Dotted name of every module of the package, e.g. ``turntable.fit.lsq``."""
    out = {}
    for path in sorted(root.rglob("*.py")):
        parts = (root.name, *path.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _imported(name: str, path: Path) -> Iterator[str]:
    """Dotted names that the module ``name`` at ``path`` imports, anywhere in it."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = package.split(".")[: len(package.split(".")) - node.level + 1]
            stem = ".".join(base + ([node.module] if node.module else []))
            if node.level == 0:
                stem = node.module or ""
            yield stem
            yield from (f"{stem}.{a.name}" for a in node.names)


def import_graph(root: Path = PACKAGE) -> dict[str, set[str]]:
    """For each module of the package, the modules of the package that importing it runs."""
    modules = _module_names(root)
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        targets = set()
        for imported in _imported(name, path):
            parts = imported.split(".")
            for i in range(1, len(parts) + 1):
                target = ".".join(parts[:i])
                if target in modules and not name.startswith(target + "."):
                    targets.add(target)
        targets.discard(name)
        graph[name] = targets
    return graph


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


@pytest.mark.parametrize("name", sorted(_module_names()))
def test_module_is_short(name: str) -> None:
    n = len(_module_names()[name].read_text().splitlines())
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
