"""Work shared by the test run's workers (tests/shared_build.py): done once, behind locks."""

from __future__ import annotations

import threading
import time
from pathlib import Path

from shared_build import build_once, computed_once


def test_a_value_is_computed_once_and_a_busy_one_waited_for_last(tmp_path: Path) -> None:
    calls: list[str] = []
    started = threading.Event()

    def compute(key: str) -> str:
        calls.append(key)
        if key == "slow":
            started.set()
            time.sleep(0.5)
            calls.append("slow done")
        return key.upper()

    first: dict[str, str] = {}
    worker = threading.Thread(
        target=lambda: first.update(computed_once(tmp_path, "values", ["slow"], compute))
    )
    worker.start()
    assert started.wait(10)
    second = computed_once(tmp_path, "values", ["slow", "quick"], compute)
    worker.join()
    assert first == {"slow": "SLOW"}
    assert second == {"slow": "SLOW", "quick": "QUICK"}
    assert calls == ["slow", "quick", "slow done"]


def test_a_build_runs_once_for_two_workers(tmp_path: Path) -> None:
    runs: list[Path] = []

    def build(target: Path) -> dict[str, int]:
        runs.append(target)
        time.sleep(0.3)
        (target / "out.txt").write_text("built")
        return {"files": 1}

    results: list[tuple[Path, dict]] = []
    workers = [
        threading.Thread(target=lambda: results.append(build_once(tmp_path, "b", build)))
        for _ in range(2)
    ]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    assert len(runs) == 1
    assert results == [(tmp_path / "b", {"files": 1})] * 2
    assert (tmp_path / "b" / "out.txt").read_text() == "built"
