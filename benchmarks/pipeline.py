"""Build time of the figure workflow: a clean build of all six figures, and a no-op rerun.

Each repeat copies config/config.yaml into a fresh temporary directory, runs
``snakemake --directory <tmp> --cores N figures`` there (clean build), then runs the same
command again (nothing to do). Wall time and the CPU time of Snakemake and its jobs are
recorded; the machine's load average is recorded too, since other processes on a shared
machine stretch wall times.

Run ``python benchmarks/pipeline.py`` (``--repeat``, ``--cores``). The result is merged
into ``results/benchmarks.json`` under the key ``pipeline`` (other keys are kept).
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from results_file import merge_results

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
TARGETS = {"clean_build_s": 6.0, "noop_build_s": 1.5}


def timed_run(cmd: list[str]) -> tuple[float, float]:
    """Run `cmd`; return (wall seconds, CPU seconds of the child processes)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{shlex.join(cmd)} failed:\n{proc.stderr[-3000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def one_repeat(cores: int) -> dict[str, float]:
    """Clean build then no-op build of the figures in a fresh temporary directory."""
    workdir = Path(tempfile.mkdtemp(prefix="turntable-pipeline-"))
    try:
        (workdir / "config").mkdir()
        shutil.copy(ROOT / "config" / "config.yaml", workdir / "config" / "config.yaml")
        cmd = [SNAKEMAKE, "--snakefile", str(ROOT / "Snakefile"), "--directory", str(workdir)]
        cmd += ["figures", "--cores", str(cores), "--quiet", "all"]
        load = os.getloadavg()[0]
        clean_wall, clean_cpu = timed_run(cmd)
        noop_wall, noop_cpu = timed_run(cmd)
        n_files = len(list((workdir / "figures").glob("*.p[dn][fg]")))
        if n_files != 12:
            raise RuntimeError(f"expected 12 figure files, found {n_files}")
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return {
        "clean_build_s": clean_wall,
        "clean_build_cpu_s": clean_cpu,
        "noop_build_s": noop_wall,
        "noop_build_cpu_s": noop_cpu,
        "load_average_1min_before": load,
    }


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark, print a summary and merge it into the JSON file."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="number of clean builds")
    parser.add_argument("--cores", type=int, default=2, help="snakemake --cores")
    parser.add_argument("--out", default="results/benchmarks.json", help="JSON file to update")
    args = parser.parse_args(argv)

    runs = [one_repeat(args.cores) for _ in range(args.repeat)]
    result: dict[str, Any] = {
        "command": shlex.join(["python", "benchmarks/pipeline.py", *argv]),
        "cores": args.cores,
        "cpu_count": os.cpu_count(),
        "machine": f"{platform.system()} {platform.machine()}",
        "targets_s": TARGETS,
        "runs": runs,
    }
    for name in ("clean_build_s", "clean_build_cpu_s", "noop_build_s", "noop_build_cpu_s"):
        values = [run[name] for run in runs]
        result[name] = {"min": min(values), "median": statistics.median(values)}
    result["meets_targets"] = {name: result[name]["min"] < limit for name, limit in TARGETS.items()}
    for name in ("clean_build_s", "noop_build_s"):
        stats, cpu = result[name], result[name.replace("_s", "_cpu_s")]
        print(
            f"{name[:-2]:12s} wall min {stats['min']:6.2f} s, median {stats['median']:6.2f} s "
            f"(target < {TARGETS[name]} s); CPU min {cpu['min']:6.2f} s"
        )
    out = ROOT / args.out  # an absolute --out replaces ROOT
    merge_results(out, {"pipeline": result})
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
