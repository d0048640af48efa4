"""The shared results file ``results/benchmarks.json``: each benchmark owns some keys.

The only writer of that file: used by the benchmarks of the closed forms (``benchmarks/run.py``
and the topic scripts it runs), ``benchmarks/pipeline.py`` and ``.ci/run``.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path
from typing import Any

from turntable._atomic import write_text
from turntable.provenance import provenance

ROOT = Path(__file__).resolve().parents[1]


def merge_results(path: Path, sections: dict[str, Any]) -> None:
    """Set the top-level keys of ``sections`` in the JSON file at ``path``, keeping the others.

    The file is replaced atomically (a temporary file in the same folder, then a rename)
    and is readable by everyone, like any other output. ``provenance`` holds, per key, the
    record of :func:`turntable.provenance.provenance` (commit, dirty tree, versions) of the
    run that wrote that key.
    """
    path = Path(path)
    data: dict[str, Any] = json.loads(path.read_text()) if path.exists() else {}
    data.update(sections)
    record = provenance(ROOT)
    data["provenance"] = data.get("provenance", {}) | {key: record for key in sections}
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, json.dumps(data, indent=2, allow_nan=False) + "\n")


def run_cases(script: str, doc: str, cases: list[str], run, key: str) -> dict[str, Any]:
    """The command line of a benchmark of rendered videos (``--cases``, ``--keep``): ``run``
    (names, folder) over the cases asked for, in ``--keep`` or a temporary folder, its result
    merged under ``key`` with the command that made it; returned."""
    parser = argparse.ArgumentParser(description=doc.partition("\n\n")[0])
    parser.add_argument("--cases", nargs="+", choices=cases, default=cases)
    parser.add_argument("--keep", type=Path, help="render into this folder, reuse its videos")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix=f"turntable-{key}-") as tmp:
        folder = args.keep or Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        res = run(args.cases, folder)
    res["command"] = "python " + " ".join([f"benchmarks/{script}", *sys.argv[1:]])
    merge_results(ROOT / "results/benchmarks.json", {key: res})
    return res
