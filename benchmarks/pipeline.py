"""Times of the everyday loop: every row of the table of the benchmarks guide, three runs each.

- ``fresh_clone_make_s``: ``git clone`` of the tree's committed state, then ``make``, set-up
  of .venv included (``setup_s``: ``make .venv/.installed-build``, pip installing uv and uv
  the pinned set; ``build_s``: the ``make`` that follows);
- ``make_test_s``: ``make test`` in the tree (its .venv already set up);
- in a copy of the workflow's sources (Snakefile, config, workflow, scripts, paper, src,
  profiles) in a fresh temporary directory, with ``--cores N``, the tree's own .venv and
  PYTHONPATH set to the copy's src/ (so that the jobs import the copy's package, as the
  Snakefile requires), and, as under make, without PYTHONDONTWRITEBYTECODE:
  ``clean_build_s``, ``snakemake figures`` from nothing; ``noop_build_s``, ``snakemake``
  once everything is built: nothing to do (``bare_noop_s``: the same for a Snakefile of one
  rule, measured beside it); ``forced_rebuild_s``, ``snakemake --forceall``;
- ``campaign_s``: ``benchmarks/campaign.py``, ``snakemake campaign`` on 1,000 SYNTHETIC films
  (``--films``) in batches of 50.

Wall and CPU time (of the child processes) are recorded with the load average of the
machine, since other processes stretch wall times. ``--only ROW ...`` measures some rows;
``--compare OTHER`` measures another checkout's rows of the workflow the same way,
alternating with this one, so that both see the same load.

Run ``python benchmarks/pipeline.py`` (``--repeat``, ``--cores``, ``--only``). The result is
merged into ``results/benchmarks.json`` under the key ``pipeline`` (other keys, and the rows
not measured by this run, are kept), and the table of the benchmarks guide
(docs/guides/benchmarks.md, between its markers) is rewritten with its figures.
"""

from __future__ import annotations

import argparse
import json
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
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
import campaign
from results_file import merge_results

ROOT = Path(__file__).resolve().parents[1]
SOURCES = ["config", "workflow", "scripts", "paper", "src", "profiles"]
GUIDE = ROOT / "docs" / "guides" / "benchmarks.md"
BEGIN, END = "<!-- benchmarks/pipeline.py: begin -->", "<!-- benchmarks/pipeline.py: end -->"
# row: (what, command, target in s)
ROWS = {
    "fresh_clone_make_s": ("`make` from a fresh clone, set-up included", "git clone + make", 90),
    "make_test_s": ("`make test`", "make test", 60),
    "forced_rebuild_s": ("forced rebuild", "snakemake --forceall", 20),
    "clean_build_s": ("figures from nothing", "snakemake figures", 12),
    "noop_build_s": ("nothing to do", "snakemake", 1.5),
    "campaign_s": ("1,000 films", "benchmarks/campaign.py", 300),
}
WORKFLOW_ROWS = ["clean_build_s", "noop_build_s", "forced_rebuild_s"]
BARE_SNAKEFILE = """\
rule all:
    input: "a"

rule a:
    output: "a"
    shell: "touch {output}"
"""


def copy_env(workdir: Path) -> dict[str, str]:
    """The environment of a run in the copy `workdir`: its src/ first on the module path, and
    Python free to write bytecode caches, as under make."""
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


def workflow_rows(tree: Path, cores: int) -> dict[str, Any]:
    """Figures from nothing, then everything, nothing to do (and a bare Snakefile's), and a
    forced rebuild."""
    snakemake = str(tree / ".venv" / "bin" / "snakemake")
    workdir = Path(tempfile.mkdtemp(prefix="turntable-pipeline-"))
    run: dict[str, Any] = {}
    try:
        for name in SOURCES:
            shutil.copytree(tree / name, workdir / name)

        def cmd(*args: str) -> list[str]:
            return [snakemake, *args, "--cores", str(cores), "--quiet", "all"]

        env = copy_env(workdir)
        run["clean_build_s"], run["clean_build_cpu_s"] = timed_run(cmd("figures"), workdir, env)
        timed_run(cmd(), workdir, env)  # the rest of the default target
        run["noop_build_s"], run["noop_build_cpu_s"] = timed_run(cmd(), workdir, env)
        forced = cmd("--forceall")
        run["forced_rebuild_s"], run["forced_rebuild_cpu_s"] = timed_run(forced, workdir, env)
        bare = workdir / "bare"
        bare.mkdir()
        (bare / "Snakefile").write_text(BARE_SNAKEFILE)
        timed_run(cmd(), bare, env)
        run["bare_noop_s"], run["bare_noop_cpu_s"] = timed_run(cmd(), bare, env)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return run


def make_test(tree: Path, cores: int) -> dict[str, float]:
    """`make test` in the tree (its .venv already set up)."""
    wall, cpu = timed_run(["make", "test"], tree)
    return {"make_test_s": wall, "make_test_cpu_s": cpu}


def fresh_clone_make(tree: Path, cores: int) -> dict[str, float]:
    """`git clone` of the tree's committed state, then `make`: set-up included."""
    workdir = Path(tempfile.mkdtemp(prefix="turntable-clone-"))
    try:
        clone = workdir / "clone"
        start = time.perf_counter()
        subprocess.run(["git", "clone", "-q", str(tree), str(clone)], check=True)
        env = {k: v for k, v in os.environ.items() if not k.startswith("VIRTUAL_ENV")}
        setup, setup_cpu = timed_run(["make", ".venv/.installed-build"], clone, env=env)
        build, build_cpu = timed_run(["make"], clone, env=env)
        wall = time.perf_counter() - start
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return {
        "fresh_clone_make_s": round(wall, 2),
        "fresh_clone_make_cpu_s": round(setup_cpu + build_cpu, 2),
        "setup_s": setup,
        "build_s": build,
    }


def campaign_row(films: int) -> Callable[[Path, int], dict[str, float]]:
    """``benchmarks/campaign.py --films films`` (this tree's workflow)."""

    def measure(tree: Path, cores: int) -> dict[str, float]:
        result = campaign.run(films, cores)
        return {"campaign_s": result["snakemake_campaign_s"], "campaign_cpu_s": result["cpu_s"]}

    return measure


def summary(runs: list[dict[str, Any]]) -> dict[str, Any]:
    """The runs, and the min and median of every measured time."""
    out: dict[str, Any] = {"runs": runs}
    for name in sorted({k for run in runs for k in run if k.endswith("_s")}):
        values = [run[name] for run in runs if name in run]
        out[name] = {"min": min(values), "median": round(statistics.median(values), 2)}
    out["meets_targets"] = {
        name: out[name]["min"] <= target for name, (*_, target) in ROWS.items() if name in out
    }
    return out


def guide_table(result: dict[str, Any]) -> str:
    """The table of the guide: each row measured, its runs, its target."""
    lines = [
        f"Measured with {', '.join(f'`{c}`' for c in result['commands'])} on "
        f"{result['cpu_count']} cores ({result['machine']})"
        + (
            f", under the load of other processes (a load average of {load['min']}-{load['max']}"
            " over the runs)"
            if (load := result.get("load_average_1min"))
            else ""
        )
        + "; seconds of wall time, each run, the median, and the median CPU time of the "
        "processes (which the load stretches less):",
        "",
        "| what | command | runs | median | CPU | target |",
        "|---|---|---|---|---|---|",
    ]
    for name, (what, command, target) in ROWS.items():
        if name not in result:
            continue
        runs = ", ".join(f"{run[name]:g}" for run in result["runs"] if name in run)
        cpu = result.get(f"{name[:-2]}_cpu_s", {}).get("median")
        lines.append(
            f"| {what} | `{command}` | {runs} | {result[name]['median']:g} s | "
            f"{'' if cpu is None else f'{cpu:g} s'} | {target:g} s |"
        )
    if "setup_s" in result:
        lines += [
            "",
            f"Of `make` from a fresh clone, the set-up (pip installs uv, uv the pinned set) "
            f"took {result['setup_s']['median']:g} s and the build {result['build_s']['median']:g}"
            " s (medians).",
        ]
    if "bare_noop_s" in result:
        lines += [
            "",
            f"A Snakefile of one rule with nothing to do, beside it: "
            f"{result['bare_noop_s']['median']:g} s ({result['bare_noop_cpu_s']['median']:g} s "
            "of CPU; medians).",
        ]
    return "\n".join(lines)


def write_guide(result: dict[str, Any], guide: Path = GUIDE) -> None:
    """Replace the text between the markers of `guide` by `guide_table(result)`."""
    text = guide.read_text()
    head, found, rest = text.partition(BEGIN)
    if not found or END not in rest:
        raise SystemExit(f"{guide}: no markers {BEGIN} ... {END}")
    guide.write_text(f"{head}{BEGIN}\n{guide_table(result)}\n{END}{rest.partition(END)[2]}")


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark, print a summary, merge it into the JSON file and the guide."""
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = argparse.ArgumentParser(description=__doc__.partition("\n")[0])
    parser.add_argument("--repeat", type=int, default=3, help="number of runs of each row")
    parser.add_argument("--cores", type=int, default=2, help="snakemake --cores")
    parser.add_argument("--only", nargs="+", choices=ROWS, help="the rows to measure")
    parser.add_argument("--films", type=int, default=1000, help="films of the campaign")
    parser.add_argument("--compare", type=Path, help="another checkout, measured alternately")
    parser.add_argument("--out", default="results/benchmarks.json", help="JSON file to update")
    parser.add_argument("--no-guide", action="store_true", help="leave the guide as it is")
    parser.add_argument("--guide-only", action="store_true", help="the guide from --out, only")
    args = parser.parse_args(argv)
    if args.guide_only:
        write_guide(json.loads((ROOT / args.out).read_text())["pipeline"])
        return 0
    rows = args.only or list(ROWS)
    steps: list[Callable[[Path, int], dict[str, Any]]] = []
    if set(rows) & set(WORKFLOW_ROWS):
        steps.append(workflow_rows)
    steps += [make_test] if "make_test_s" in rows else []
    steps += [fresh_clone_make] if "fresh_clone_make_s" in rows else []
    steps += [campaign_row(args.films)] if "campaign_s" in rows else []

    trees = {"this": ROOT} | ({"compared": args.compare.resolve()} if args.compare else {})
    runs: dict[str, list[dict[str, Any]]] = {name: [] for name in trees}
    loads = []
    for _ in range(args.repeat):
        for name, tree in reversed(trees.items()):  # the other checkout first, then this one
            run: dict[str, Any] = {}
            for step in steps if name == "this" else [workflow_rows]:
                loads.append(os.getloadavg()[0])
                run |= step(tree, args.cores)
            runs[name].append(run)
    out = ROOT / args.out  # an absolute --out replaces ROOT
    command = shlex.join(["python", "benchmarks/pipeline.py", *argv])
    previous = json.loads(out.read_text()).get("pipeline", {}) if out.exists() else {}
    kept: list[dict[str, Any]] = []
    if previous.get("runs") and not args.compare:  # the rows not measured now are kept
        measured = {key for run in runs["this"] for key in run}
        kept = [{k: v for k, v in run.items() if k not in measured} for run in previous["runs"]]
    if any(kept):
        runs["this"] = [
            (kept[i] if i < len(kept) else {}) | (runs["this"][i] if i < len(runs["this"]) else {})
            for i in range(max(len(kept), len(runs["this"])))
        ]
        loads += list(previous.get("load_average_1min", {}).values())
    commands = [*dict.fromkeys([*previous.get("commands", []), command])]
    result: dict[str, Any] = {
        "commands": commands if any(kept) else [command],
        "cores": args.cores,
        "cpu_count": os.cpu_count(),
        "machine": f"{platform.system()} {platform.machine()}",
        "load_average_1min": {"min": round(min(loads), 1), "max": round(max(loads), 1)},
        "targets_s": {name: target for name, (*_, target) in ROWS.items()},
    } | summary(runs["this"])
    if args.compare:
        result["compared"] = {"tree": str(trees["compared"])} | summary(runs["compared"])
    for name in ROWS:
        if name in result:
            print(
                f"{name[:-2]:20s} min {result[name]['min']:7.2f} s, median "
                f"{result[name]['median']:7.2f} s (target <= {ROWS[name][2]} s)"
            )
    merge_results(out, {"pipeline": result})
    if not args.no_guide:
        write_guide(result)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
