"""Work done once per test run and shared by all pytest-xdist workers.

The first worker to ask for a build runs it while holding a file lock; the others wait for
the lock and reuse the result (a directory and a JSON record).  `computed_once` does the
same for values (pickled), one lock per value.
"""

from __future__ import annotations

import json
import pickle
import re
import shutil
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import pytest
from filelock import FileLock, Timeout

from turntable._atomic import replacing


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
    with FileLock(shared / f"{name}.lock"):
        if not record_file.exists():
            shutil.rmtree(target, ignore_errors=True)
            target.mkdir(parents=True)
            record_file.write_text(json.dumps(build(target)))
    return target, json.loads(record_file.read_text())


def computed_once(
    shared: Path, name: str, keys: Sequence[str], compute: Callable[[str], Any]
) -> dict[str, Any]:
    """``{key: compute(key)}`` for every key, each computed once per test run.

    The values are pickled under shared/name, one file per key, each behind its own file
    lock.  A worker first computes the keys that no other worker is computing (a lock it
    can take at once), then waits for the others: two workers that ask for the same keys at
    the same time share the work instead of doing it twice.
    """
    folder = shared / name
    folder.mkdir(parents=True, exist_ok=True)
    values: dict[str, Any] = {}
    pending = list(keys)
    for wait in (False, True):
        busy = []
        for key in pending:
            found = _computed(folder, key, compute, wait)
            if found is _BUSY:
                busy.append(key)
            else:
                values[key] = found
        pending = busy
    return {key: values[key] for key in keys}


_BUSY = object()


def _computed(folder: Path, key: str, compute: Callable[[str], Any], wait: bool) -> Any:
    stem = re.sub(r"[^A-Za-z0-9_.=-]", "_", key)
    result = folder / f"{stem}.pickle"
    try:
        held = FileLock(folder / f"{stem}.lock").acquire(blocking=wait)
    except Timeout:
        return _BUSY
    with held:
        if not result.exists():
            value = compute(key)
            with replacing(result) as tmp:
                tmp.write_bytes(pickle.dumps(value))
            return value
        return pickle.loads(result.read_bytes())
