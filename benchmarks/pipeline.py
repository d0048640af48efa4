"""Build times of the workflow: figures from nothing, nothing to do, a forced rebuild; and,
on request, the test suite and `make` from a fresh clone.

Each repeat copies the workflow's sources (Snakefile, config, workflow, scripts, paper, src,
profiles) into a fresh temporary directory and runs there, with ``--cores N``, the tree's
own .venv and PYTHONPATH set to the copy's src/ (so that the jobs import the copy's package,
as the Snakefile requires, rather than the tree's editable install), and, as under make,
without PYTHONDONTWRITEBYTECODE:

- ``clean_build_s``: ``snakemake figures`` from nothing (each figure job also writes its
  notebook);
- ``noop_build_s``: ``snakemake`` (the default target) once everything is built: nothing to do;
- ``forced_rebuild_s``: ``snakemake --forceall``, every job of the default target again.

With ``--make-test``, ``make_test_s`` is the wall time of ``make test`` in the tree; with
``--fresh-clone``, ``fresh_clone_make_s`` is that of ``git clone`` + ``make`` (set-up of
.venv included). Wall and CPU time (of the child processes) are recorded with the load
average of the machine, since other processes stretch wall times; the seconds and CPU
seconds of every job of the forced rebuild are read from the files of Snakemake's
``benchmark:`` directive (logs/benchmarks/), where the tree has them.

``--compare OTHER`` measures another checkout the same way (its own .venv, Snakefile and
Makefile), alternating with this one in every repeat, so that both see the same load: the
way to compare before and after a change on a shared machine.

Run ``python benchmarks/pipeline.py`` (``--repeat``, ``--cores``). The result is merged
into ``results/benchmarks.json`` under the key ``pipeline`` (other keys are kept).
"""

from __future__ import annotations

import argparse
import csv
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
# (an older checkout may still have its Snakefile at the root: copied when it exists)
SOURCES = ["Snakefile", "config", "workflow", "scripts", "paper", "src", "profiles"]
TARGETS = {
    "clean_build_s": 12.0,
    "noop_build_s": 1.2,
    "forced_rebuild_s": 20.0,
    "make_test_s": 60.0,
    "fresh_clone_make_s": 90.0,
}


def copy_env(workdir: Path) -> dict[str, str]:
    """The environment of a run in the copy `workdir`: its src/ first on the module path, and
    Python free to write bytecode caches, as under make (the Makefile does not pass
    PYTHONDONTWRITEBYTECODE on; with it, every run would compile every module again)."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    return env | {"PYTHONPATH": str(workdir / "src")}


def timed_run(cmd: list[str], cwd: Path, env: dict[str, str] | None = None) -> tuple[float, float]:
    """Run `cmd` in `cwd`; return (wall seconds, CPU seconds of the child processes)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, check=False, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{shlex.join(cmd)} in {cwd} failed:\n{proc.stderr[-3000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return round(wall, 2), round(cpu, 2)


def job_seconds(workdir: Path) -> dict[str, dict[str, float]]:
    """Seconds and CPU seconds of each job, from Snakemake's benchmark: files."""
    jobs = {}
    for path in sorted((workdir / "logs" / "benchmarks").glob("*.tsv")):
        rows = list(csv.DictReader(path.open(), delimiter="\t"))
        if rows:
            jobs[path.stem] = {"s": float(rows[-1]["s"]), "cpu_s": float(rows[-1]["cpu_time"])}
    return jobs


def one_repeat(tree: Path, cores: int) -> dict[str, Any]:
    """Figures from nothing, then everything, nothing to do, and a forced rebuild."""
    snakemake = str(tree / ".venv" / "bin" / "snakemake")
    workdir = Path(tempfile.mkdtemp(prefix="turntable-pipeline-"))
    run = {"load_average_1min_before": round(os.getloadavg()[0], 2)}
    try:
        for name in SOURCES:
            if (tree / name).exists():
                copy = shutil.copytree if (tree / name).is_dir() else shutil.copy2
                copy(tree / name, workdir / name)

        def cmd(*args: str) -> list[str]:
            return [snakemake, *args, "--cores", str(cores), "--quiet", "all"]

        env = copy_env(workdir)
        clean = timed_run(cmd("figures"), workdir, env)
        run["clean_build_s"], run["clean_build_cpu_s"] = clean
        n_files = len(list((workdir / "figures").glob("fig*.p[dn][fg]")))
        timed_run(cmd(), workdir, env)  # the rest of the default target
        run["noop_build_s"], run["noop_build_cpu_s"] = timed_run(cmd(), workdir, env)
        forced = cmd("--forceall")
        run["forced_rebuild_s"], run["forced_rebuild_cpu_s"] = timed_run(forced, workdir, env)
        run["figure_files"] = n_files
        run["jobs_of_forced_rebuild"] = job_seconds(workdir)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return run


def make_test(tree: Path) -> dict[str, float]:
    """`make test` in the tree (its .venv already set up)."""
    wall, cpu = timed_run(["make", "test"], tree)
    return {"make_test_s": wall, "make_test_cpu_s": cpu}


def fresh_clone_make(tree: Path) -> dict[str, float]:
    """`git clone` of the tree's committed state, then `make`: set-up included."""
    workdir = Path(tempfile.mkdtemp(prefix="turntable-clone-"))
    try:
        clone = workdir / "clone"
        start = time.perf_counter()
        subprocess.run(["git", "clone", "-q", str(tree), str(clone)], check=True)
        env = {k: v for k, v in os.environ.items() if not k.startswith("VIRTUAL_ENV")}
        _, cpu = timed_run(["make"], clone, env=env)
        wall = time.perf_counter() - start
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return {"fresh_clone_make_s": round(wall, 2), "fresh_clone_make_cpu_s": cpu}


def summary(runs: list[dict[str, Any]]) -> dict[str, Any]:
    """Min and median of every measured time, and the job times of the fastest forced run."""
    out: dict[str, Any] = {"runs": runs}
    for name in sorted({k for run in runs for k in run if k.endswith("_s")}):
        values = [run[name] for run in runs if name in run]
        out[name] = {"min": min(values), "median": round(statistics.median(values), 2)}
    best = min(runs, key=lambda run: run["forced_rebuild_s"])
    out["jobs_of_fastest_forced_rebuild"] = best.get("jobs_of_forced_rebuild", {})
    out["meets_targets"] = {
        name: out[name]["min"] <= limit for name, limit in TARGETS.items() if name in out
    }
    return out


def commit(tree: Path) -> str:
    proc = subprocess.run(["git", "rev-parse", "HEAD"], cwd=tree, capture_output=True, text=True)
    return proc.stdout.strip() or "unknown"


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark, print a summary and merge it into the JSON file."""
    argv = list(sys.argv[1:] if argv is None else argv)
    # the first paragraph of the docstring, which spans two lines
    parser = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    parser.add_argument("--repeat", type=int, default=3, help="number of repeats")
    parser.add_argument("--cores", type=int, default=2, help="snakemake --cores")
    parser.add_argument("--make-test", action="store_true", help="also time `make test`")
    parser.add_argument("--fresh-clone", action="store_true", help="also time clone + make")
    parser.add_argument("--compare", type=Path, help="another checkout, measured alternately")
    parser.add_argument("--out", default="results/benchmarks.json", help="JSON file to update")
    args = parser.parse_args(argv)

    trees = {"this": ROOT} | ({"compared": args.compare.resolve()} if args.compare else {})
    runs: dict[str, list[dict[str, Any]]] = {name: [] for name in trees}
    for _ in range(args.repeat):
        for name, tree in reversed(trees.items()):  # the other checkout first, then this one
            run = one_repeat(tree, args.cores)
            if args.make_test:
                run |= make_test(tree)
            if args.fresh_clone:
                run |= fresh_clone_make(tree)
            runs[name].append(run)
    result: dict[str, Any] = {
        "command": shlex.join(["python", "benchmarks/pipeline.py", *argv]),
        "PYTHONDONTWRITEBYTECODE_in_environment": os.environ.get("PYTHONDONTWRITEBYTECODE"),
        "cores": args.cores,
        "cpu_count": os.cpu_count(),
        "machine": f"{platform.system()} {platform.machine()}",
        "targets_s": TARGETS,
        "commit": commit(ROOT),
    } | summary(runs["this"])
    if args.compare:
        result["compared"] = {"tree": str(trees["compared"]), "commit": commit(args.compare)}
        result["compared"] |= summary(runs["compared"])
    for name in TARGETS:
        if name in result:
            other = ""
            if args.compare:
                other = f", compared tree {result['compared'][name]['min']:6.2f} s"
            print(
                f"{name[:-2]:20s} min {result[name]['min']:6.2f} s, median "
                f"{result[name]['median']:6.2f} s (target <= {TARGETS[name]} s){other}"
            )
    out = ROOT / args.out  # an absolute --out replaces ROOT
    merge_results(out, {"pipeline": result})
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
