"""README.md and the guides of docs/: the pictures shown are the pipeline's own, and the
commands, paths and links they give exist."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from ci_build import ROOT

README = ROOT / "README.md"
PAGES = [README, *sorted((ROOT / "docs").rglob("*.md"))]
PAGES = [p for p in PAGES if "_build" not in p.parts]


def _ids(paths: list[Path]) -> list[str]:
    return [str(p.relative_to(ROOT)) for p in paths]


@pytest.mark.parametrize("name", ["fig4_trajectories.png", "animation.gif", "fig10_video.png"])
def test_readme_pictures_are_the_pipelines(clean_build: Path, name: str) -> None:
    """docs/ holds the bytes of the shared build, which ran target readme_figure (else: make
    readme-figure)."""
    built = (clean_build / "figures" / name).read_bytes()
    assert (clean_build / "docs" / name).read_bytes() == built
    assert (ROOT / "docs" / name).read_bytes() == built, "docs/ is stale: make readme-figure"


def test_make_targets_in_readme_exist() -> None:
    makefile = (ROOT / "Makefile").read_text()
    targets = set(re.findall(r"^([\w-]+):", makefile, flags=re.MULTILINE))
    text = "\n".join(p.read_text() for p in PAGES)
    used = set(re.findall(r"^\s*make ([\w-]+)(?![\w=-])", text, flags=re.MULTILINE))
    used |= set(re.findall(r"`make ([\w-]+)`", text))
    assert {"test", "docs"} <= used
    assert used <= targets, used - targets


@pytest.mark.parametrize("page", PAGES, ids=_ids(PAGES))
def test_paths_and_links_exist(page: Path) -> None:
    """Source paths in backticks, from the root; Markdown links, from the page."""
    text = page.read_text()
    prefixes = "scripts|workflow|src|tests|profiles|config|docs|benchmarks|tools"
    paths = re.findall(rf"`((?:{prefixes})/[\w./-]+)`", text)
    generated = ("docs/_build/",)  # written by make docs
    missing = [
        p
        for p in paths
        if not (ROOT / p).exists() and "<" not in p and "*" not in p and not p.startswith(generated)
    ]
    links = [
        link.split("#")[0]
        for link in re.findall(r"\]\(([^)\s]+)\)", text)
        if not re.match(r"\w+:", link) and not link.startswith("#")
    ]
    missing += [link for link in links if not (page.parent / link).exists()]
    assert (paths and links) or page != README
    assert missing == []
