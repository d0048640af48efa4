"""The shared results file ``results/benchmarks.json``: each benchmark owns some keys.

The only writer of that file: used by the benchmarks of the closed forms (``benchmarks/run.py``
and the topic scripts it runs), ``benchmarks/pipeline.py`` and ``.ci/run``.
"""

from __future__ import annotations

import json
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
