"""The GitHub Actions workflow: least privilege, pinned actions, releases only from tags.

(actionlint checks the file itself: a pre-commit hook.)
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
WORKFLOW = ROOT / ".github" / "workflows" / "ci.yml"


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
