"""The project's files that a script imports: the input ``code`` of the job that runs it.

Read by the workflow (workflow/rules/common.smk), so that a job lists exactly the code it
runs: editing a file reruns the jobs whose script imports it, and no other. The imports are
read from the source (``ast``), at any depth (an import inside a function counts), and
followed through the project's own modules:

- ``turntable`` or any module of it: every source file of the package, ``src/turntable/``
  (its modules import one another and read their data files; a new module counts too);
- a module beside the script (its folder is first on ``sys.path`` when it runs:
  ``scripts/_style/`` for scripts/, ``workflow/scripts/report_figure.py`` for
  workflow/scripts/): its file, whose own imports are followed in turn. A package comes
  with the files of its folder that are not Python (``scripts/_style/turntable.mplstyle``,
  which ``_style`` reads); a module of a package (``_style.animation``) with the package;
- anything else (numpy, matplotlib, ...) is an installed package, not an input.

Sources are the files found by glob, but not the hidden files, the editor backups and the
compiled Python (`is_source`), so that opening a file in an editor reruns nothing.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from functools import cache
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: The package every job that imports it depends on as a whole.
PACKAGE = "turntable"
PACKAGE_DIR = ROOT / "src" / PACKAGE

# Files under a source folder that are not sources: compiled Python, and what editors and
# tools leave beside a file (vim's .name.swp, emacs's name~ and #name#, patch leftovers).
NOT_SOURCES = ("~", ".swp", ".swo", ".swx", ".bak", ".orig", ".rej", ".pyc", ".pyo")


def is_source(path: Path, folder: Path) -> bool:
    """Whether ``path``, a file under ``folder``, is a source: not hidden (no part of it below
    ``folder`` starts with a dot: .name.swp, .mypy_cache/), not compiled, not a backup."""
    parts = path.relative_to(folder).parts
    return (
        path.is_file()
        and "__pycache__" not in parts
        and not any(part.startswith(".") for part in parts)
        and not path.name.endswith(NOT_SOURCES)
        and not (path.name.startswith("#") and path.name.endswith("#"))
    )


def sources(folder: Path) -> list[Path]:
    """Every source file under ``folder``, sorted."""
    return sorted(p for p in folder.rglob("*") if is_source(p, folder))


@cache
def package_sources() -> tuple[Path, ...]:
    """Every source file of the package ``src/turntable/``, relative to the repository."""
    return tuple(p.relative_to(ROOT) for p in sources(PACKAGE_DIR))


@cache
def imported_names(path: Path, package: str = "") -> tuple[str, ...]:
    """The absolute names of what the file at ``path`` imports (``package``: the package the
    file belongs to, for its relative imports). ``from a import b`` gives ``a`` and ``a.b``,
    since ``b`` may be a module."""
    return tuple(_imported_names(path, package))


def _imported_names(path: Path, package: str) -> Iterator[str]:
    tree = ast.parse(path.read_bytes(), filename=str(path))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = package.split(".") if package else []
                base = ".".join(parts[: len(parts) - node.level + 1])
                module = ".".join(filter(None, [base, node.module]))
            else:
                module = node.module or ""
            yield module
            yield from (f"{module}.{alias.name}" for alias in node.names)


def _local_module(folder: Path, name: str) -> tuple[Path, str] | None:
    """The file of module ``name`` under ``folder`` and the package of that file, or None."""
    path = folder.joinpath(*name.split("."))
    if (path / "__init__.py").is_file():
        return path / "__init__.py", name
    if path.with_suffix(".py").is_file():
        return path.with_suffix(".py"), name.rpartition(".")[0]
    return None


@cache
def code_inputs(script: Path) -> tuple[Path, ...]:
    """The project's files that ``script`` (a path relative to the repository, or absolute)
    imports, directly or through the project's own modules (see the module's description),
    relative to the repository, sorted; the script itself not included."""
    script = (ROOT / script).resolve()
    folder = script.parent
    found: set[Path] = set()
    uses_package = False
    todo: list[tuple[Path, str]] = [(script, "")]
    seen = {script}
    while todo:
        path, package = todo.pop()
        for name in imported_names(path, package):
            if name.split(".")[0] == PACKAGE:
                uses_package = True
                continue
            parts = name.split(".")
            for depth in range(1, len(parts) + 1):  # _style.animation: _style, then animation
                local = _local_module(folder, ".".join(parts[:depth]))
                if local is None:
                    break
                file = local[0]
                if file in seen:
                    continue
                seen.add(file)
                found.add(file)
                if file.name == "__init__.py":  # what the package reads: the other files
                    found.update(
                        p
                        for p in file.parent.iterdir()
                        if p.suffix != ".py" and is_source(p, file.parent)
                    )
                todo.append(local)
    relative = {p.relative_to(ROOT) for p in found}
    if uses_package:
        relative.update(package_sources())
    return tuple(sorted(relative))
