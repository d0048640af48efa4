"""The GitHub Actions workflow passes actionlint, and actionlint does reject a broken one."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
WORKFLOW = ROOT / ".github" / "workflows" / "ci.yml"
ACTIONLINT = Path(sys.executable).with_name("actionlint")

pytestmark = pytest.mark.skipif(
    not ACTIONLINT.is_file(), reason=f"actionlint not installed next to {sys.executable}"
)


def _actionlint(path: Path) -> subprocess.CompletedProcess[str]:
    """Run actionlint on one workflow file, without colours."""
    return subprocess.run(
        [str(ACTIONLINT), "-no-color", str(path)],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def test_workflow_passes_actionlint() -> None:
    result = _actionlint(WORKFLOW)
    assert result.returncode == 0, result.stdout + result.stderr


def test_actionlint_rejects_a_broken_workflow(tmp_path: Path) -> None:
    # The same workflow with one step pointing at an action reference that has no version
    # and one expression naming an undefined context: both are errors actionlint reports.
    text = WORKFLOW.read_text()
    broken = text.replace("actions/checkout@v4.2.2", "actions/checkout", 1)
    broken = broken.replace("${{ env.PYTHON_VERSION }}", "${{ nosuchcontext.version }}", 1)
    assert broken != text
    path = tmp_path / ".github" / "workflows" / "ci.yml"
    path.parent.mkdir(parents=True)
    path.write_text(broken)
    result = _actionlint(path)
    assert result.returncode == 1, result.stdout + result.stderr
    assert "nosuchcontext" in result.stdout
    assert "actions/checkout" in result.stdout


def test_workflow_shape() -> None:
    """Least privilege, cancelled superseded runs, pinned actions, release only on tags."""
    wf = yaml.safe_load(WORKFLOW.read_text())
    assert wf["permissions"] == {"contents": "read"}
    assert wf["concurrency"]["cancel-in-progress"] is True
    jobs = wf["jobs"]
    writers = {name for name, job in jobs.items() if "permissions" in job}
    assert writers == {"release"}
    assert jobs["release"]["permissions"] == {"contents": "write"}
    assert "refs/tags/v" in jobs["release"]["if"]
    uses = [s["uses"] for job in jobs.values() for s in job["steps"] if "uses" in s]
    assert uses
    for ref in uses:
        # an exact release tag vX.Y.Z, never a moving major tag or a branch
        assert re.fullmatch(r"[\w.-]+/[\w.-]+@v\d+\.\d+\.\d+", ref), ref
    # yaml reads the key `on` as True
    assert set(wf[True]) == {"push", "pull_request"}
    assert wf[True]["push"]["tags"] == ["v*"]
