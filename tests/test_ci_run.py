"""The checks of .ci/run (``--check-only``) on a small fake checkout: each can fail."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
# A workflow of four outputs standing in for the project's: .ci/run asks Snakemake (a dry
# run) whether the build is complete, so it keeps no list of outputs of its own.
SNAKEFILE = """\
rule all:
    input:
        "figures/fig4_trajectories.png",
        "paper/paper.pdf",
        "results/claims.json",
        "results/study/summary.json",
        "results/notebooks/claims_report.ipynb",


rule make:
    output:
        "{path}",
    shell:
        "echo content > {output}"
"""


def _git(repo: Path, *args: str) -> None:
    subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@example.org", *args],
        cwd=repo,
        check=True,
        capture_output=True,
    )


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A committed tree with a small workflow, built, and the report that make adds."""
    repo = tmp_path_factory.mktemp("ci") / "repo"
    (repo / ".ci").mkdir(parents=True)
    shutil.copy2(ROOT / ".ci" / "run", repo / ".ci" / "run")
    (repo / "Snakefile").write_text(SNAKEFILE)
    ignored = "figures/\nresults/\npaper/paper.pdf\n.snakemake/\n"
    (repo / ".gitignore").write_text(ignored)
    _git(repo, "init", "-q")
    _git(repo, "add", ".")
    _git(repo, "commit", "-q", "-m", "fake checkout")
    subprocess.run([SNAKEMAKE, "--cores", "1"], cwd=repo, check=True, capture_output=True)
    claims = {"claims": {"a.b": {"verdict": "confirmed"}, "c.d": {"verdict": "refined"}}}
    claims["summary"] = {"confirmed": 1, "refined": 1, "failed": 0, "total": 2}
    (repo / "results/claims.json").write_text(json.dumps(claims))
    study = {"all_passed": True, "failed": [], "per_k": [{"k": 0.4}]}
    (repo / "results/study/summary.json").write_text(json.dumps(study))
    (repo / "results/report.html").write_text("<html></html>\n")
    return repo


@pytest.fixture
def checkout(built: Path, tmp_path: Path) -> Path:
    """A copy of the built tree (times kept, so that it stays up to date)."""
    return Path(shutil.copytree(built, tmp_path / "repo", symlinks=True))


def _check(repo: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        ["bash", ".ci/run", "--check-only"],
        cwd=repo,
        env={**os.environ, "PYTHON": sys.executable, "SNAKEMAKE": SNAKEMAKE},
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def test_passes_when_everything_is_there(checkout: Path) -> None:
    result = _check(checkout)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "tree: clean" in result.stdout


def test_fails_on_a_failed_claim_and_on_a_failed_study_check(checkout: Path) -> None:
    """Each of the two checks fails the run and names what failed."""
    path = checkout / "results/claims.json"
    claims = json.loads(path.read_text())
    claims["claims"]["c.d"]["verdict"] = "failed"
    path.write_text(json.dumps(claims))
    study = {"all_passed": False, "failed": ["k=0.4: roots"], "per_k": [{"k": 0.4}]}
    (checkout / "results/study/summary.json").write_text(json.dumps(study))
    result = _check(checkout)
    assert result.returncode == 1
    assert "claims with verdict 'failed': c.d" in result.stderr
    assert "failed checks of the parameter study: k=0.4: roots" in result.stderr
    assert "outputs: complete" in result.stdout  # the other checks still run


def test_fails_on_missing_outputs(checkout: Path) -> None:
    missing = ["figures/fig4_trajectories.png", "results/notebooks/claims_report.ipynb"]
    for path in missing:
        (checkout / path).unlink()
    result = _check(checkout)
    assert result.returncode == 1
    assert "the build is incomplete" in result.stderr
    for path in missing:
        assert path in result.stderr


def test_fails_on_an_outdated_output(checkout: Path) -> None:
    """An output older than its input (here: the Snakefile's rule changed) is planned again."""
    snakefile = checkout / "Snakefile"
    snakefile.write_text(snakefile.read_text().replace("echo content", "echo other content"))
    result = _check(checkout)
    assert result.returncode == 1
    assert "the build is incomplete" in result.stderr


def test_fails_on_an_empty_output_and_without_the_report(checkout: Path) -> None:
    (checkout / "figures/fig4_trajectories.png").write_text("")
    (checkout / "results/report.html").unlink()
    result = _check(checkout)
    assert result.returncode == 1
    assert "figures/fig4_trajectories.png" in result.stderr
    assert "results/report.html" in result.stderr
    assert "the build is incomplete" not in result.stderr  # an empty file is not missing


def test_fails_on_a_dirty_tree(checkout: Path) -> None:
    (checkout / ".gitignore").write_text("figures/\nresults/\n.snakemake/\n")
    (checkout / "stray.txt").write_text("left behind\n")
    result = _check(checkout)
    assert result.returncode == 1
    assert "stray.txt" in result.stderr
    assert ".gitignore" in result.stderr
