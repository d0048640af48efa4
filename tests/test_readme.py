"""README.md: the figure it shows is the pipeline's own, and what it tells to run exists."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest

from ci_build import ROOT, shared_build
from test_pipeline import clean_build, in_project, shared_tmp  # noqa: F401

README = (ROOT / "README.md").read_text()
DOC_FIGURE = ROOT / "docs" / "fig4_trajectories.png"


@pytest.fixture(scope="session")
def build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """The shared build of tests/ci_build.py, which ran target readme_figure."""
    workdir, record = shared_build(tmp_path_factory, worker_id)
    assert record["build_returncode"] == 0, record["build_log"]
    return workdir


def test_readme_figure_is_the_pipeline_figure(build: Path) -> None:
    """docs/fig4_trajectories.png has the bytes of a fresh build (else: make readme-figure)."""
    built = (build / "figures" / "fig4_trajectories.png").read_bytes()
    assert (build / "docs" / "fig4_trajectories.png").read_bytes() == built
    assert DOC_FIGURE.read_bytes() == built, "docs/ is stale: run `make readme-figure`"


def test_the_copies_for_the_readme_are_never_empty(
    clean_build: Path,  # noqa: F811
    tmp_path: Path,
) -> None:
    """The rules that copy a figure and the animation into docs/ declare their outputs
    non-empty (like every other output of the workflow): an empty source, copied, fails the
    job and leaves no empty file under docs/ for the README."""
    copy = Path(shutil.copytree(clean_build, tmp_path / "copy", symlinks=True))
    targets = ["docs/fig4_trajectories.png", "docs/animation.gif"]
    for name in ["fig4_trajectories.png", "animation.gif"]:
        (copy / "figures" / name).write_bytes(b"")
    proc = in_project(copy, *targets, "--keep-going", "--forcerun", *targets, cores=1)
    assert proc.returncode != 0, proc.stdout + proc.stderr
    assert proc.stderr.count("Detected unexpected empty output files") == 2, proc.stderr
    assert not [t for t in targets if (copy / t).exists()]


def test_readme_shows_the_figure() -> None:
    assert "](docs/fig4_trajectories.png)" in README


def test_make_targets_in_readme_exist() -> None:
    makefile = (ROOT / "Makefile").read_text()
    targets = set(re.findall(r"^([\w-]+):", makefile, flags=re.MULTILINE))
    # (make VARIABLE=value sets a variable: not a target)
    used = set(re.findall(r"^\s*make ([\w-]+)(?![\w=-])", README, flags=re.MULTILINE))
    used |= set(re.findall(r"`make ([\w-]+)`", README))
    assert used
    assert used <= targets, used - targets


def test_paths_in_readme_exist() -> None:
    """Every committed path the README names in backquotes exists."""
    committed = [
        "workflow/Snakefile",
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


def test_readme_lists_every_figure_of_the_workflow() -> None:
    """The table of outputs has a row for each figure the workflow draws."""
    from test_pipeline import NAMES

    for name in NAMES:
        assert f"| `figures/{name}.{{pdf,png}}` |" in README, name
    assert f"Figures 5–{len(NAMES)} are new" in README


def test_readme_names_the_runtime_dependencies() -> None:
    """Where the README says what `pip install .` needs, it names exactly the dependencies
    of pyproject.toml."""
    import tomllib

    with open(ROOT / "pyproject.toml", "rb") as fh:
        runtime = {
            re.match(r"[A-Za-z0-9_.-]+", d).group(0)
            for d in tomllib.load(fh)["project"]["dependencies"]
        }
    mentions = re.findall(r"`pip install \.`[^)]*", README)
    assert len(mentions) == 2, mentions
    for text in mentions:
        named = set(
            re.findall(
                r"\b("
                + "|".join(map(re.escape, runtime | {"matplotlib", "snakemake", "typst"}))
                + r")\b",
                text,
            )
        )
        assert named == runtime, text
