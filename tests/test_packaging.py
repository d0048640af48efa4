"""The package `turntable` requires only what it imports; the workflow's tools are an extra.

Builds the wheel from the tree (pip, with the pinned build back-end from constraints.txt)
and reads its metadata, then imports every module of the package in a fresh interpreter in
which the workflow's tools cannot be imported.
"""

from __future__ import annotations

import email.parser
import os
import pkgutil
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

import turntable

ROOT = Path(__file__).resolve().parents[1]
RUNTIME = {"numpy", "scipy", "sympy", "mpmath", "pyyaml", "jsonschema"}
WORKFLOW_TOOLS = ["matplotlib", "snakemake", "jupytext", "typst", "nbclient", "PIL"]
# Prelude of a child interpreter in which importing a workflow tool raises ImportError.
BLOCK = f"""
import sys
class Block:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in {WORKFLOW_TOOLS!r}:
            raise ImportError('blocked ' + name)
sys.meta_path.insert(0, Block())
"""


@pytest.fixture(scope="module")
def wheel_metadata(tmp_path_factory: pytest.TempPathFactory) -> email.message.Message:
    # Build from a copy of what the sdist holds, so that no build/ folder lands in the tree.
    source = tmp_path_factory.mktemp("source")
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy2(ROOT / name, source / name)
    shutil.copytree(ROOT / "src", source / "src", ignore=shutil.ignore_patterns("*.egg-info"))
    out = tmp_path_factory.mktemp("wheel")
    env = {**os.environ, "PIP_CONSTRAINT": str(ROOT / "constraints.txt")}
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--quiet",
            "--no-deps",
            "--disable-pip-version-check",
            "--wheel-dir",
            str(out),
            str(source),
        ],
        check=True,
        env=env,
        capture_output=True,
        timeout=300,
    )
    (wheel,) = out.glob("turntable-*.whl")
    with zipfile.ZipFile(wheel) as zf:
        name = next(n for n in zf.namelist() if n.endswith(".dist-info/METADATA"))
        licence = [n for n in zf.namelist() if n.endswith("licenses/LICENSE")]
        assert licence, "LICENSE is not in the wheel"
        return email.parser.Parser().parsestr(zf.read(name).decode())


def _requirement_name(requirement: str) -> tuple[str, str | None]:
    name = re.match(r"[A-Za-z0-9_.-]+", requirement).group(0).lower()
    extra = re.search(r"extra\s*==\s*['\"]([^'\"]+)['\"]", requirement)
    return name, extra.group(1) if extra else None


def test_wheel_requires_only_the_runtime_dependencies(wheel_metadata) -> None:
    required = [_requirement_name(r) for r in wheel_metadata.get_all("Requires-Dist")]
    unconditional = {name for name, extra in required if extra is None}
    assert unconditional == RUNTIME
    workflow = {name for name, extra in required if extra == "workflow"}
    assert {"matplotlib", "snakemake", "jupytext", "typst", "pillow"} <= workflow


def test_wheel_licence_metadata(wheel_metadata) -> None:
    assert wheel_metadata["License-Expression"] == "MIT"
    assert wheel_metadata.get_all("License-File") == ["LICENSE"]


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
