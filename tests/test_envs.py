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
