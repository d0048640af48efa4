"""Work done once per test run and shared by all pytest-xdist workers.

The first worker to ask for a build runs it while holding a file lock; the others wait for
the lock and reuse the result (a directory and a JSON record).
"""

from __future__ import annotations

import fcntl
import json
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest


def shared_dir(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """A temporary directory shared by all xdist workers of this test run."""
    base = tmp_path_factory.getbasetemp()
    return base if worker_id == "master" else base.parent


def build_once(
    shared: Path, name: str, build: Callable[[Path], dict[str, Any]]
) -> tuple[Path, dict[str, Any]]:
    """Run `build` into the empty directory shared/name once per test run.

    Returns the directory and the record `build` returned (JSON-serialisable).
    """
    target = shared / name
    record_file = shared / f"{name}.json"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not record_file.exists():
            shutil.rmtree(target, ignore_errors=True)
            target.mkdir(parents=True)
            record_file.write_text(json.dumps(build(target)))
    return target, json.loads(record_file.read_text())
