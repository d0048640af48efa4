"""turntable.provenance: the commit, a dirty tree, the Python and library versions."""

from __future__ import annotations

import platform
import subprocess
import sys
from pathlib import Path

import mpmath
import numpy
import pytest
import scipy
import sympy

import turntable
from turntable.provenance import PACKAGES, UNKNOWN, git_state, package_versions, provenance


def _git(repo: Path, *args: str) -> str:
    return subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@example.org", *args],
        cwd=repo,
        check=True,
        capture_output=True,
        text=True,
    ).stdout.strip()


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    """A git repository with one commit, one tracked file and an ignored folder."""
    _git(tmp_path, "init", "-q")
    (tmp_path / "a.txt").write_text("a\n")
    (tmp_path / ".gitignore").write_text("results/\n")
    _git(tmp_path, "add", "a.txt", ".gitignore")
    _git(tmp_path, "commit", "-q", "-m", "first")
    return tmp_path


def test_clean_checkout(repo: Path) -> None:
    commit, dirty = git_state(repo)
    assert commit == _git(repo, "rev-parse", "HEAD")
    assert dirty is False


def test_ignored_outputs_leave_the_tree_clean(repo: Path) -> None:
    (repo / "results").mkdir()
    (repo / "results" / "claims.json").write_text("{}")
    assert git_state(repo)[1] is False


@pytest.mark.parametrize(
    "change",
    [
        lambda r: (r / "a.txt").write_text("changed\n"),
        lambda r: (r / "new.py").write_text("x = 1\n"),
    ],
    ids=["modified", "untracked"],
)
def test_dirty_checkout(repo: Path, change) -> None:
    change(repo)
    commit, dirty = git_state(repo)
    assert dirty is True
    assert commit == _git(repo, "rev-parse", "HEAD")


def test_new_commit_is_recorded(repo: Path) -> None:
    first = git_state(repo)[0]
    (repo / "a.txt").write_text("b\n")
    _git(repo, "commit", "-q", "-am", "second")
    second, dirty = git_state(repo)
    assert second != first
    assert dirty is False


def test_outside_a_checkout(tmp_path: Path) -> None:
    assert git_state(tmp_path) == (UNKNOWN, None)


def test_versions_are_those_imported() -> None:
    versions = package_versions()
    assert tuple(versions) == PACKAGES
    for module in (numpy, scipy, sympy, mpmath):
        assert versions[module.__name__] == module.__version__
    assert package_versions(("no-such-distribution-xyz",)) == {"no-such-distribution-xyz": None}


def test_record(repo: Path) -> None:
    record = provenance(repo)
    assert record["python"] == platform.python_version()
    assert record["python"].startswith(f"{sys.version_info.major}.{sys.version_info.minor}.")
    assert record["turntable"] == turntable.__version__
    assert record["git_commit"] == _git(repo, "rev-parse", "HEAD")
    assert record["git_dirty"] is False
    assert set(record["packages"]) == {
        "numpy",
        "scipy",
        "mpmath",
        "sympy",
        "matplotlib",
        "snakemake",
        "typst",
    }
