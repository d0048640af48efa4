"""The optional conda environments of the rules pin the versions of constraints.txt.

The rules run in the project's .venv; `snakemake --sdm conda` is an alternative that
must not drift from the one source of pinned versions.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
ENVS = sorted((ROOT / "workflow" / "envs").glob("*.yaml"))


def constraints() -> dict[str, str]:
    pins = {}
    for line in (ROOT / "constraints.txt").read_text().splitlines():
        if line and not line.startswith("#"):
            name, version = line.split("==")
            pins[name.lower().replace("_", "-")] = version
    return pins


@pytest.mark.parametrize("env", ENVS, ids=[p.name for p in ENVS])
def test_conda_environment_pins_match_constraints(env: Path) -> None:
    spec = yaml.safe_load(env.read_text())
    pip = next(d["pip"] for d in spec["dependencies"] if isinstance(d, dict))
    pins = constraints()
    assert pip, f"{env.name} lists no pip packages"
    for requirement in pip:
        name, version = requirement.split("==")
        assert pins[name.lower().replace("_", "-")] == version, f"{env.name}: {requirement}"


def test_there_are_environments() -> None:
    assert len(ENVS) >= 1


def _name(requirement: str) -> str:
    """The normalised distribution name of a requirement ("PyYAML==6.0.3" -> "pyyaml")."""
    for sep in ("==", ">", "<", "[", ";", " "):
        requirement = requirement.split(sep)[0]
    return requirement.strip().lower().replace("_", "-")


@pytest.mark.parametrize("env", ENVS, ids=[p.name for p in ENVS])
def test_conda_environment_has_what_the_jobs_import(env: Path) -> None:
    """The package is installed into the environment without its dependencies
    (turntable.post-deploy.sh, --no-deps), so the environment itself must hold every
    runtime dependency of pyproject.toml and every package of its `workflow` and `notebooks`
    extras (every job runs its script as a notebook)."""
    import tomllib

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    needed = {_name(r) for r in project["dependencies"]}
    for extra in ("workflow", "notebooks"):
        needed |= {_name(r) for r in project["optional-dependencies"][extra]}
    needed -= {"snakemake"}  # the environment's jobs run under the Snakemake that made it
    spec = yaml.safe_load(env.read_text())
    pip = next(d["pip"] for d in spec["dependencies"] if isinstance(d, dict))
    assert needed <= {_name(r) for r in pip}, sorted(needed - {_name(r) for r in pip})
