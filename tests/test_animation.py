"""The animation figures/animation.gif: frames, size, same bytes from two builds, in README."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from PIL import Image

from ci_build import ROOT
from test_pipeline import clean_build, interrupted_build, shared_tmp  # noqa: F401

CONFIG = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())["animation"]
MAX_BYTES = 5 * 1024 * 1024


@pytest.fixture(scope="module")
def built(clean_build: Path) -> Path:  # noqa: F811
    """figures/animation.gif of the clean build of tests/test_pipeline.py, whose animation
    section is the project's."""
    config = yaml.safe_load((clean_build / "config" / "config.yaml").read_text())
    assert config["animation"] == CONFIG
    return clean_build / "figures" / "animation.gif"


def test_frames_and_size(built: Path) -> None:
    assert built.stat().st_size <= MAX_BYTES
    with Image.open(built) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == CONFIG["n_frames"]
        # two panels side by side: a square plot between a title band and a time band
        assert CONFIG["size"] < gif.height <= 1.25 * CONFIG["size"]
        assert 2 * CONFIG["size"] <= gif.width <= 2 * CONFIG["size"] + 10
        assert gif.info["loop"] == 0
        assert gif.info["duration"] == CONFIG["frame_ms"]
        frames = []
        for i in (0, gif.n_frames // 2, gif.n_frames - 1):
            gif.seek(i)
            frames.append(np.asarray(gif.convert("RGB")))
    # it moves: the first, middle and last frames all differ
    assert not np.array_equal(frames[0], frames[1])
    assert not np.array_equal(frames[1], frames[2])


def test_two_builds_give_the_same_bytes(
    built: Path,
    interrupted_build: tuple[Path, dict],  # noqa: F811
) -> None:
    """The killed and resumed build of tests/test_pipeline.py draws the same animation."""
    other, record = interrupted_build
    assert record["returncode"] == 0, record["log"]
    assert (other / "figures" / "animation.gif").read_bytes() == built.read_bytes()


def test_readme_animation_is_the_pipeline_animation(built: Path) -> None:
    """docs/animation.gif has the bytes of a fresh build (else: make readme-figure)."""
    docs = ROOT / "docs" / "animation.gif"
    assert (built.parents[1] / "docs" / "animation.gif").read_bytes() == built.read_bytes()
    assert docs.read_bytes() == built.read_bytes(), "docs/ is stale: run `make readme-figure`"


def test_readme_shows_the_animation_first() -> None:
    readme = (ROOT / "README.md").read_text()
    first_screen = "\n".join(readme.splitlines()[:30])
    assert "](docs/animation.gif)" in first_screen
