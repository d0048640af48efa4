"""README.md: the pictures it shows are the pipeline's own, and what it tells to run exists."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ci_build import ROOT, shared_build

README = (ROOT / "README.md").read_text()


@pytest.fixture(scope="session")
def build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """The shared build of tests/ci_build.py, which ran target readme_figure."""
    workdir, record = shared_build(tmp_path_factory, worker_id)
    assert record["build_returncode"] == 0, record["build_log"]
    return workdir


@pytest.mark.parametrize("name", ["fig4_trajectories.png", "animation.gif"])
def test_readme_pictures_are_the_pipelines(build: Path, name: str) -> None:
    """docs/ holds the bytes of a fresh build (else: make readme-figure)."""
    built = (build / "figures" / name).read_bytes()
    assert (build / "docs" / name).read_bytes() == built
    assert (ROOT / "docs" / name).read_bytes() == built, "docs/ is stale: make readme-figure"


def test_make_targets_in_readme_exist() -> None:
    makefile = (ROOT / "Makefile").read_text()
    targets = set(re.findall(r"^([\w-]+):", makefile, flags=re.MULTILINE))
    used = set(re.findall(r"^\s*make ([\w-]+)(?![\w=-])", README, flags=re.MULTILINE))
    used |= set(re.findall(r"`make ([\w-]+)`", README))
    assert used
    assert used <= targets, used - targets


def test_paths_in_readme_exist() -> None:
    paths = re.findall(r"`((?:scripts|workflow|src|tests|profiles|config|docs)/[\w./-]+)`", README)
    assert paths
    missing = [p for p in paths if not (ROOT / p).exists() and "<" not in p and "*" not in p]
    assert missing == []
