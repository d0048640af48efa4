"""The package `turntable` requires only numpy and scipy; the claims, the configuration,
the command line's extras, video and the workflow's tools are extras.

Reads the dependencies of pyproject.toml, imports every module of the package in a fresh
interpreter in which the workflow's tools cannot be imported, and installs the wheel in a
fresh venv (offline, from uv's cache) where it solves, fits and plots without the extras.
"""

from __future__ import annotations

import pkgutil
import re
import subprocess
import sys
import tomllib
from collections import Counter
from pathlib import Path

import pytest

import turntable

ROOT = Path(__file__).resolve().parents[1]
UV = Path(sys.executable).with_name("uv")
RUNTIME = {"numpy", "scipy"}
#: The modules of the extras claims and config, which the light install must not load.
EXTRAS_MODULES = ["sympy", "mpmath", "jsonschema", "yaml"]
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


def _project() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]


def test_package_requires_only_the_runtime_dependencies() -> None:
    """The dependencies of the package are numpy and scipy; the workflow's tools are the
    extra ``workflow``, which takes the claims, which take the configuration."""
    project = _project()
    extras = project["optional-dependencies"]
    assert {_requirement_name(r) for r in project["dependencies"]} == RUNTIME
    assert {"matplotlib", "snakemake", "typst", "pillow"} <= set(
        map(_requirement_name, extras["workflow"])
    )
    assert "turntable[claims]" in extras["workflow"]
    assert {"turntable[config]", "sympy", "mpmath"} == set(extras["claims"])
    assert {"pyyaml", "jsonschema"} == set(extras["config"])


def test_each_dependency_is_listed_once() -> None:
    project = _project()
    extras = [r for group in project["optional-dependencies"].values() for r in group]
    names = map(_requirement_name, [*project["dependencies"], *extras])
    twice = [n for n, c in Counter(names).items() if c > 1 and n != "turntable"]
    assert twice == []


def test_the_physics_the_fit_and_the_command_line_load_no_extra() -> None:
    """In this process's environment, with the extras installed: importing the package,
    solving, fitting and ``turntable fit`` load none of the modules of claims and config."""
    code = """
import sys, numpy as np, turntable
from turntable import cli
from turntable.film import EXAMPLE_FILM
turntable.solve(np.array([1.0, 1.0, 0, 0, 0, 1.0]), np.linspace(0, 1, 3), 1.0, 0.4)
cli.main(["fit", str(EXAMPLE_FILM), "--radius", "0.005", "--rpm", "33.3"])
print(*sys.modules)
"""
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=120, check=True
    )
    loaded = {name.split(".")[0] for name in out.stdout.split()}
    assert "scipy" in loaded
    assert loaded & set(EXTRAS_MODULES) == set()


@pytest.fixture(scope="module")
def light(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A fresh venv with the wheel of the package and matplotlib, installed offline by uv
    from its cache (where make put them), with the pinned versions."""
    where = tmp_path_factory.mktemp("light")
    uv = [str(UV), "--offline", "--quiet"]
    subprocess.run(
        [*uv, "build", "--wheel", "--out-dir", str(where / "dist"), str(ROOT)],
        check=True, timeout=300, capture_output=True,
    )  # fmt: skip
    venv = where / "venv"
    subprocess.run([*uv, "venv", "--python", sys.executable, str(venv)], check=True, timeout=60)
    (wheel,) = (where / "dist").glob("turntable-*.whl")
    subprocess.run(
        [*uv, "pip", "install", "--python", str(venv / "bin" / "python"), "--constraints",
         str(ROOT / "constraints.txt"), str(wheel), "matplotlib"],
        check=True, timeout=300, capture_output=True,
    )  # fmt: skip
    return venv / "bin"


@pytest.mark.slow
def test_the_wheel_in_a_fresh_venv_solves_and_plots_without_the_extras(
    light: Path, tmp_path: Path
) -> None:
    """``pip install turntable``: numpy and scipy only; solve, fit and plot load no module
    of the extras claims and config."""
    code = f"""
import sys
import numpy as np, turntable
from turntable.film import EXAMPLE_FILM
from turntable.fit.plot import plot_fit
from turntable.fitting import fitted_film
z = turntable.solve(np.array([1.0, 1.0, 0, 0, 0, 1.0]), np.linspace(0, 1, 3), 1.0, 0.4)
out, film = fitted_film(EXAMPLE_FILM, 0.005, rpm=100 / 3)
plot_fit({str(tmp_path / "fit.png")!r}, film, out)
print(out["selected"], *sys.modules)
"""
    run = subprocess.run(
        [str(light / "python"), "-c", code], capture_output=True, text=True, timeout=120,
        check=False, cwd=tmp_path,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    selected, *modules = run.stdout.split()
    assert selected == "slipping"
    assert (tmp_path / "fit.png").stat().st_size > 0
    assert {m.split(".")[0] for m in modules} & set(EXTRAS_MODULES) == set()
    freeze = subprocess.run(
        [str(UV), "pip", "freeze", "--python", str(light / "python")],
        capture_output=True, text=True, check=True,
    ).stdout  # fmt: skip
    installed = {_requirement_name(line) for line in freeze.splitlines()}
    assert installed & {"sympy", "mpmath", "jsonschema", "pyyaml", "tqdm", "shtab"} == set()


@pytest.mark.slow
def test_the_light_install_s_command_line(light: Path, tmp_path: Path) -> None:
    """The console script of the wheel: --version, a fit, and one line naming the extra
    where ``turntable claims`` needs one."""
    version = subprocess.run(
        [str(light / "turntable"), "--version"], capture_output=True, text=True, check=True
    )
    assert version.stdout.strip() == f"turntable {_project()['version']}"
    claims = subprocess.run(
        [str(light / "turntable"), "claims"], capture_output=True, text=True, check=False
    )
    assert claims.returncode == 2
    assert claims.stderr.count("\n") == 1
    assert "pip install 'turntable[claims]'" in claims.stderr


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


def test_every_dependency_is_pinned_in_constraints_txt() -> None:
    """constraints.txt (make lock: uv pip compile of every extra) pins each dependency of
    pyproject.toml and uv, exactly."""
    pins = {}
    for line in (ROOT / "constraints.txt").read_text(encoding="utf-8").splitlines():
        if line and not line.startswith("#"):
            name, _, rest = line.partition("==")
            pins[re.sub(r"[-_.]+", "-", name.lower())] = rest.split(";")[0].strip()
    project = _project()
    extras = [r for group in project["optional-dependencies"].values() for r in group]
    names = {_requirement_name(r) for r in [*project["dependencies"], *extras, "uv"]}
    names.discard("turntable")
    unpinned = {re.sub(r"[-_.]+", "-", n) for n in names} - {n for n, v in pins.items() if v}
    assert unpinned == set()
