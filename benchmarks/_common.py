"""What the benchmarks of the closed forms share: initial states, error measure, timing, CLI.

The topic scripts (``eigenvalues.py``, ``solution.py``, ``speed.py``) each define ``NAME``
(their key in ``results/benchmarks.json``), ``run(quick)`` and ``print_result(res)``;
`main` runs one or more of them and merges their results into the shared file through
`results_file.merge_results`, its only writer.  The high-precision references come from
`turntable.reference`.
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import shlex
import sys
import timeit
from collections.abc import Callable, Sequence
from pathlib import Path
from types import ModuleType
from typing import Any

import mpmath
import numpy as np
import scipy
from numpy.typing import NDArray

import turntable as tt
from results_file import merge_results
from turntable._blas import BLAS_THREAD_VARIABLES

ROOT = Path(__file__).resolve().parents[1]

K_BALL = 2.0 / 5.0
K_SHELL = 2.0 / 3.0

#: Initial states: Fig. 3 of the paper, Fig. 4 of the paper, and a generic one.
INITIAL_STATES = {
    "fig3 (x=y=1, v=w=0)": (1.0, 1.0, 0.0, 0.0, 0.0, 0.0),
    "fig4 (x=y=1, v=0, w=(0,1))": (1.0, 1.0, 0.0, 0.0, 0.0, 1.0),
    "generic": (0.3, -1.2, 0.7, 0.25, -0.4, 0.9),
}

ERROR_MEASURE = (
    "max over times and components of |z - z_ref|, divided by "
    "max(1, max |z_ref| over the trajectory)"
)


def num(x: Any) -> float | str:
    """Return ``x`` as a JSON-safe float ('inf' / 'nan' as strings)."""
    x = float(x)
    return x if math.isfinite(x) else str(x)


def fmt(x: float | str) -> str:
    """Format a number of `num` in 9 characters."""
    return f"{x:9.1e}" if isinstance(x, float) else f"{x:>9}"


def pf(ok: bool) -> str:
    """PASS or FAIL."""
    return "PASS" if ok else "FAIL"


def command(script: str | Path, argv: Sequence[str]) -> str:
    """Return the command line that runs ``script``, relative to the checkout."""

    def rel(path: str) -> str:
        try:
            return os.path.relpath(path, ROOT) if Path(path).is_absolute() else path
        except ValueError:
            return path

    exe = rel(sys.executable)
    return shlex.join([exe, os.path.relpath(Path(script).resolve(), ROOT), *argv])


def mp_error(z: NDArray[np.float64], zref: NDArray[np.object_]) -> float:
    """Error of ``z`` against the mpmath array ``zref`` (see ERROR_MEASURE)."""
    diff = max(abs(mpmath.mpf(float(a)) - b) for a, b in zip(z.ravel(), zref.ravel(), strict=True))
    scale = max(mpmath.mpf(1), max(abs(b) for b in zref.ravel()))
    return float(diff / scale)


def best_time(fn: Callable[[], object], repeat: int, number: int | None = None) -> float:
    """Return the best time of one call of ``fn``, in seconds (timeit, best of ``repeat``).

    If ``number`` is None it is chosen by ``timeit.Timer.autorange`` so that
    each repeat lasts at least 0.2 s.
    """
    timer = timeit.Timer(fn)
    if number is None:
        number, _ = timer.autorange()
    return min(timer.repeat(repeat=repeat, number=number)) / number


def meta() -> dict[str, str]:
    """Versions of the software the numbers depend on (no dates)."""
    return {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "mpmath": mpmath.__version__,
        "turntable": tt.__version__,
        "machine": f"{platform.system()} {platform.machine()}",
        "blas_threads": ", ".join(f"{v}={os.environ.get(v, '')}" for v in BLAS_THREAD_VARIABLES),
    }


def write_results(path: Path, sections: dict[str, Any]) -> None:
    """Merge ``sections`` into the JSON file at ``path`` (atomically), keeping other keys."""
    merge_results(path, sections)


def main(
    topics: Sequence[ModuleType], script: str | Path, description: str, argv: Sequence[str]
) -> int:
    """Run the benchmarks ``topics``, print them and merge them into the results file.

    Options: ``--quick`` (smaller grids), ``--out`` (the JSON file to update) and, when
    there is more than one topic, ``--sections`` (which of them to run).
    """
    argv = list(argv)
    by_name = {t.NAME: t for t in topics}
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--quick", action="store_true", help="smaller grids, fewer repeats")
    parser.add_argument("--out", default="results/benchmarks.json", help="JSON file to update")
    if len(topics) > 1:
        parser.add_argument(
            "--sections",
            nargs="+",
            choices=list(by_name),
            default=list(by_name),
            help="what to run",
        )
    args = parser.parse_args(argv)
    cmd = command(script, argv)
    results: dict[str, Any] = {}
    for name in getattr(args, "sections", list(by_name)):
        res = by_name[name].run(args.quick)
        res["command"] = cmd
        by_name[name].print_result(res)
        results[name] = res
    results["meta"] = meta()
    out = Path(args.out)
    write_results(out, results)
    print(f"\nwrote {out}")
    return 0
