"""The package's files that a module or a script runs: its imports, followed through it.

Every file is parsed with `ast`; nothing is imported. Imports at the top and inside functions
count, relative ones resolved. Importing a submodule runs the packages above it first. A
package that imports its submodules by name (``importlib.import_module``) runs them all. A
data file (a template, a schema, a table) is read by the modules whose strings name it or
its folder (a module with the string ``"data"`` has the folder ``data``'s files: one input
too many at worst, never one too few). A script's imports of the modules and packages
beside it are followed. The workflow takes a job's code from here (`code_of`): an edit
reruns every job whose code runs the edited file.
"""

from __future__ import annotations

import ast
import functools
from collections.abc import Iterable, Iterator
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent


def module_names(root: Path = PACKAGE) -> dict[str, Path]:
    """Dotted name of every module of the package, e.g. ``turntable.fit.lsq``."""
    out = {}
    for path in sorted(root.rglob("*.py")):
        parts = (root.name, *path.relative_to(root).with_suffix("").parts)
        if not all(p.isidentifier() for p in parts):
            continue  # an editor's file (``.#spectrum.py``), not a module
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(), str(path))


def imported(tree: ast.Module, package: str = "") -> Iterator[str]:
    """Dotted names that `tree` imports anywhere in it; `package` resolves relative ones."""
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level == 0:
                stem = node.module or ""
            else:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                stem = ".".join(base + ([node.module] if node.module else []))
            yield stem
            yield from (f"{stem}.{a.name}" for a in node.names)


def _by_name(tree: ast.Module) -> bool:
    """Whether `tree` imports modules by a computed name (``importlib.import_module``)."""
    return any(
        isinstance(node, ast.Attribute | ast.Name)
        and getattr(node, "attr", getattr(node, "id", "")) == "import_module"
        for node in ast.walk(tree)
    )


def _strings(tree: ast.Module) -> set[str]:
    return {
        node.value
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str)
    }


def _targets(names: Iterable[str], modules: dict[str, Path]) -> set[str]:
    """The package's modules that importing `names` runs, the packages above them too."""
    out = set()
    for name in names:
        parts = name.split(".")
        out |= {".".join(parts[:i]) for i in range(1, len(parts) + 1)} & modules.keys()
    return out


def import_graph(root: Path = PACKAGE) -> dict[str, set[str]]:
    """For each module, the modules of the package it imports (not the packages holding it)."""
    modules = module_names(root)
    graph: dict[str, set[str]] = {}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        tree = _tree(path)
        targets = _targets(imported(tree, package), modules)
        if _by_name(tree) and path.name == "__init__.py":
            targets |= {m for m in modules if m.rpartition(".")[0] == name}
        graph[name] = {t for t in targets if t != name and not name.startswith(t + ".")}
    return graph


def _data_files(root: Path, modules: dict[str, Path]) -> dict[str, list[Path]]:
    """For each module, the package's data files that it names, or whose folder it names."""
    data = [
        p
        for p in sorted(root.rglob("*"))
        if p.is_file()
        and p.suffix not in {".py", ".pyc", ".typed"}
        and not any(part.startswith((".", "__")) for part in p.relative_to(root).parts)
        and not p.name.endswith("~")
    ]
    out = {}
    for name, path in modules.items():
        strings = _strings(_tree(path))
        out[name] = [p for p in data if p.name in strings or p.parent.name in strings]
    return out


def _imported_by_script(script: Path) -> set[str]:
    """Dotted names that `script` imports, and those that the modules and packages beside
    it (in its folder, the first of its ``sys.path``) that it imports import in turn."""
    home, names, todo, seen = script.parent, set(), [script], set()
    while todo:
        path = todo.pop()
        if path in seen:
            continue
        seen.add(path)
        parts = path.relative_to(home).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        found = set(
            imported(_tree(path), name if parts[-1] == "__init__" else name.rpartition(".")[0])
        )
        names |= found
        for dotted in found:
            prefix = dotted.split(".")
            for i in range(1, len(prefix) + 1):
                base = home.joinpath(*prefix[:i])
                todo += [f for f in (base.with_suffix(".py"), base / "__init__.py") if f.is_file()]
    return names


@functools.cache
def _index(root: Path) -> tuple[dict[str, Path], dict[str, set[str]], dict[str, list[Path]]]:
    modules = module_names(root)
    return modules, import_graph(root), _data_files(root, modules)


def code_of(*entries: str | Path, root: Path = PACKAGE) -> list[Path]:
    """The package's files that running `entries` runs or reads, sorted.

    An entry is a module's dotted name (``turntable.cli``) or the path of a script outside
    the package; a script's imports of the modules and packages beside it are followed.
    """
    modules, graph, data = _index(root)
    start: set[str] = set()
    for script in (Path(e) for e in entries if isinstance(e, Path) or e.endswith(".py")):
        start |= _targets(_imported_by_script(script), modules)
    start |= _targets([e for e in entries if isinstance(e, str) and not e.endswith(".py")], modules)
    run, todo = set(), list(start)
    while todo:
        name = todo.pop()
        if name not in run:
            run.add(name)
            todo.extend(graph[name] | _targets([name], modules))
    files = {modules[m] for m in run} | {p for m in run for p in data[m]}
    return sorted(files)
