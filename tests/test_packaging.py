"""The package `turntable` requires only what it imports; the workflow's tools are an extra.

Reads the dependencies of pyproject.toml, then imports every module of the package in a
fresh interpreter in which the workflow's tools cannot be imported.
"""

from __future__ import annotations

import pkgutil
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import turntable

ROOT = Path(__file__).resolve().parents[1]
RUNTIME = {"numpy", "scipy", "sympy", "mpmath", "pyyaml", "jsonschema"}
WORKFLOW_TOOLS = [
    "matplotlib",
    "snakemake",
    "jupytext",
    "typst",
    "nbclient",
    "PIL",
    "av",
    "cv2",
    "jinja2",
    "markupsafe",
]
# Prelude of a child interpreter in which importing a workflow tool raises ImportError.
BLOCK = f"""
import sys
class Block:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in {WORKFLOW_TOOLS!r}:
            raise ImportError('blocked ' + name)
sys.meta_path.insert(0, Block())
"""


def _requirement_name(requirement: str) -> str:
    return re.match(r"[A-Za-z0-9_.-]+", requirement).group(0).lower()


def test_package_requires_only_the_runtime_dependencies() -> None:
    """The dependencies of the package are what it imports; the workflow's tools are the
    extra ``workflow``."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    assert {_requirement_name(r) for r in project["dependencies"]} == RUNTIME
    workflow = {_requirement_name(r) for r in project["optional-dependencies"]["workflow"]}
    assert {"matplotlib", "snakemake", "typst", "pillow"} <= workflow


def test_package_imports_without_the_workflow_tools() -> None:
    """Every module of turntable imports, and solve runs, with the tools made unimportable."""
    modules = sorted(m.name for m in pkgutil.walk_packages(turntable.__path__, prefix="turntable."))
    assert "turntable.solution" in modules
    code = (
        BLOCK
        + f"""
import importlib
for m in {modules!r}:
    importlib.import_module(m)
import numpy as np, turntable
z = turntable.solve(np.array([1.0, 1.0, 0, 0, 0, 1.0]), np.linspace(0, 1, 3), 1.0, 0.4)
assert z.shape == (3, 6)
"""
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=False
    )
    assert result.returncode == 0, result.stderr


def test_blocking_works() -> None:
    """The import block of the test above does catch a module importing a workflow tool."""
    code = BLOCK + "import matplotlib\n"
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=False
    )
    assert result.returncode != 0
    assert "blocked matplotlib" in result.stderr
