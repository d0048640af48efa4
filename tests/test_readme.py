"""README.md: the figure it shows is the pipeline's own, and what it tells to run exists."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
DOC_FIGURE = ROOT / "docs" / "fig4_trajectories.png"
COPIED = ["Snakefile", "config", "workflow", "scripts", "paper", "src", "profiles"]


@pytest.fixture(scope="module")
def fresh_fig4(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """figures/fig4_trajectories.png built by the workflow in a copy of the project."""
    dest = tmp_path_factory.mktemp("readme")
    for name in COPIED:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
        elif src.is_file():
            shutil.copy2(src, dest / name)
    result = subprocess.run(
        [str(Path(sys.executable).with_name("snakemake")), "readme_figure", "--cores", "1"],
        cwd=dest,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    return dest


def test_readme_figure_is_the_pipeline_figure(fresh_fig4: Path) -> None:
    """docs/fig4_trajectories.png has the bytes of a fresh build (else: make readme-figure)."""
    built = (fresh_fig4 / "figures" / "fig4_trajectories.png").read_bytes()
    assert (fresh_fig4 / "docs" / "fig4_trajectories.png").read_bytes() == built
    assert DOC_FIGURE.read_bytes() == built, "docs/ is stale: run `make readme-figure`"


def test_readme_shows_the_figure() -> None:
    assert "](docs/fig4_trajectories.png)" in README


def test_make_targets_in_readme_exist() -> None:
    makefile = (ROOT / "Makefile").read_text()
    targets = set(re.findall(r"^([\w-]+):", makefile, flags=re.MULTILINE))
    used = set(re.findall(r"^\s*make ([\w-]+)", README, flags=re.MULTILINE))
    used |= set(re.findall(r"`make ([\w-]+)`", README))
    assert used
    assert used <= targets, used - targets


def test_paths_in_readme_exist() -> None:
    """Every committed path the README names in backquotes exists."""
    committed = [
        "Snakefile",
        "config/config.yaml",
        "profiles/slurm/config.yaml",
        "workflow/report",
        "constraints.txt",
        "docs/fig4_trajectories.png",
    ]
    for path in committed:
        assert f"`{path}" in README, path
        assert (ROOT / path).exists(), path
    for path in re.findall(r"`((?:scripts|workflow|src|tests|profiles)/[\w./-]+)`", README):
        assert (ROOT / path).exists() or "<" in path or "*" in path, path
