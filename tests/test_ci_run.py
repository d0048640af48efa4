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
FIGURES = [
    "fig1_schematic",
    "fig2_spectrum",
    "fig3_modal_terms",
    "fig4_trajectories",
    "fig5_damping_ratio",
    "fig6_limit",
]
OUTPUTS = [f"figures/{n}.{ext}" for n in FIGURES for ext in ("pdf", "png")] + [
    "results/claims.md",
    "paper/paper.pdf",
    "results/report.html",
    "figures/animation.gif",
    "results/claims.html",
    "results/figures.html",
    "results/notebooks/fig1_schematic.ipynb",
    "results/notebooks/claims_report.ipynb",
]


def _git(repo: Path, *args: str) -> None:
    subprocess.run(
        ["git", "-c", "user.name=t", "-c", "user.email=t@example.org", *args],
        cwd=repo,
        check=True,
        capture_output=True,
    )


@pytest.fixture
def checkout(tmp_path: Path) -> Path:
    """A committed tree with two scripts, and every output .ci/run expects from them."""
    repo = tmp_path / "repo"
    (repo / ".ci").mkdir(parents=True)
    shutil.copy2(ROOT / ".ci" / "run", repo / ".ci" / "run")
    (repo / "scripts").mkdir()
    for name in ("fig1_schematic", "claims_report"):
        (repo / "scripts" / f"{name}.py").write_text("# a script\n")
    (repo / ".gitignore").write_text("figures/\nresults/\npaper/paper.pdf\n")
    _git(repo, "init", "-q")
    _git(repo, "add", ".")
    _git(repo, "commit", "-q", "-m", "fake checkout")
    for path in OUTPUTS:
        (repo / path).parent.mkdir(parents=True, exist_ok=True)
        (repo / path).write_text("content\n")
    claims = {"claims": {"a.b": {"verdict": "confirmed"}, "c.d": {"verdict": "refined"}}}
    claims["summary"] = {"confirmed": 1, "refined": 1, "failed": 0, "total": 2}
    (repo / "results/claims.json").write_text(json.dumps(claims))
    study = {"all_passed": True, "failed": [], "per_k": [{"k": 0.4}]}
    (repo / "results/study").mkdir(parents=True)
    (repo / "results/study/summary.json").write_text(json.dumps(study))
    return repo


def _check(repo: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        ["bash", ".ci/run", "--check-only"],
        cwd=repo,
        env={**os.environ, "PYTHON": sys.executable},
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def test_passes_when_everything_is_there(checkout: Path) -> None:
    result = _check(checkout)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "tree: clean" in result.stdout


def test_fails_on_a_failed_claim(checkout: Path) -> None:
    path = checkout / "results/claims.json"
    claims = json.loads(path.read_text())
    claims["claims"]["c.d"]["verdict"] = "failed"
    path.write_text(json.dumps(claims))
    result = _check(checkout)
    assert result.returncode == 1
    assert "c.d" in result.stderr


def test_fails_on_a_failed_study_check(checkout: Path) -> None:
    study = {"all_passed": False, "failed": ["k=0.4: roots"], "per_k": [{"k": 0.4}]}
    (checkout / "results/study/summary.json").write_text(json.dumps(study))
    result = _check(checkout)
    assert result.returncode == 1
    assert "k=0.4: roots" in result.stderr


@pytest.mark.parametrize(
    "missing",
    [
        "figures/fig4_trajectories.png",
        "paper/paper.pdf",
        "results/report.html",
        "results/notebooks/claims_report.ipynb",
        "results/claims.json",
        "results/study/summary.json",
    ],
)
def test_fails_on_a_missing_output(checkout: Path, missing: str) -> None:
    (checkout / missing).unlink()
    result = _check(checkout)
    assert result.returncode == 1
    assert missing in result.stderr


def test_fails_on_an_empty_output(checkout: Path) -> None:
    (checkout / "figures/fig2_spectrum.pdf").write_text("")
    result = _check(checkout)
    assert result.returncode == 1
    assert "figures/fig2_spectrum.pdf" in result.stderr


def test_fails_on_a_dirty_tree(checkout: Path) -> None:
    (checkout / "scripts" / "fig1_schematic.py").write_text("# edited by the build\n")
    (checkout / "stray.txt").write_text("left behind\n")
    result = _check(checkout)
    assert result.returncode == 1
    assert "stray.txt" in result.stderr
    assert "scripts/fig1_schematic.py" in result.stderr
