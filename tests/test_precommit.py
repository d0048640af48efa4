"""The pre-commit hooks run the pinned tools offline and pass on the repository."""

from __future__ import annotations

import shlex
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / ".pre-commit-config.yaml"
BIN = Path(sys.executable).parent
HOOKS = [h for repo in yaml.safe_load(CONFIG.read_text())["repos"] for h in repo["hooks"]]


def test_hooks_are_local_and_cover_the_tools() -> None:
    repos = yaml.safe_load(CONFIG.read_text())["repos"]
    assert [r["repo"] for r in repos] == ["local"]
    tools = {Path(shlex.split(h["entry"])[0]).name for h in HOOKS}
    assert tools == {
        "ruff",
        "snakefmt",
        "codespell",
        "shellcheck",
        "validate-pyproject",
        "actionlint",
    }


@pytest.mark.parametrize("hook", HOOKS, ids=lambda h: h["id"])
def test_hook_tool_is_pinned_in_the_venv(hook: dict) -> None:
    exe = Path(shlex.split(hook["entry"])[0])
    assert exe.parent == Path(".venv/bin")
    assert (BIN / exe.name).is_file(), f"{exe.name} is not installed in {BIN}"


def test_pre_commit_passes_on_every_tracked_file() -> None:
    files = subprocess.run(
        ["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.split()
    result = subprocess.run(
        [str(BIN / "pre-commit"), "run", "--files", *files],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_codespell_hook_finds_a_misspelling(tmp_path: Path) -> None:
    misspelt = "rec" + "ieves"  # split, so that the hook does not flag this file
    bad = tmp_path / "notes.md"
    bad.write_text(f"the ball {misspelt} a spin\n")
    entry = next(h["entry"] for h in HOOKS if h["id"] == "codespell")
    result = subprocess.run(
        [str(BIN / Path(shlex.split(entry)[0]).name), str(bad)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode != 0
    assert misspelt in result.stdout
