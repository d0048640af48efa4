"""One real build of part of the project, shared by the tests of the notebooks, the report,
the README figure and the study (tests/test_notebooks.py, test_readme.py, test_study.py).

The sources are copied into a temporary directory shared by all xdist workers of the
session; the first worker to ask plans the whole workflow there (a dry run with the SLURM
profile and the dry-run executor), then builds Fig. 1 with its notebook, the README
figure (Fig. 4 copied to docs/) and the animation (copied to docs/), with the project's own
configuration. A file lock makes
the other workers wait for that build and reuse it.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from shared_build import build_once, shared_dir

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
COPIED = ["Snakefile", "config", "workflow", "scripts", "paper", "src", "profiles"]
TARGETS = [
    "figures/fig1_schematic.png",
    "results/notebooks/fig1_schematic.ipynb",
    "readme_figure",
    "readme_animation",
]


def snakemake(workdir: Path, *args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    """Run snakemake with `args` in `workdir`."""
    return subprocess.run(
        [SNAKEMAKE, *args],
        cwd=workdir,
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


def copy_sources(dest: Path) -> Path:
    """Copy the workflow's sources (no outputs) into `dest`."""
    dest.mkdir(parents=True, exist_ok=True)
    for name in COPIED:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
        elif src.is_file():
            shutil.copy2(src, dest / name)
    return dest


def _build(workdir: Path) -> dict[str, Any]:
    """Plan everything (in a second copy) while building the targets: both at once."""
    plan_dir = copy_sources(workdir.with_name(workdir.name + "-plan"))
    copy_sources(workdir)

    def start(cwd: Path, *args: str) -> subprocess.Popen:
        return subprocess.Popen(
            [SNAKEMAKE, *args],
            cwd=cwd,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
        )

    plan = start(plan_dir, "--profile", "profiles/slurm", "--executor", "dryrun")
    build = start(workdir, *TARGETS, "--cores", "2")
    plan_log, _ = plan.communicate(timeout=300)
    build_log, _ = build.communicate(timeout=300)
    return {
        "plan_returncode": plan.returncode,
        "plan": plan_log,
        "build_returncode": build.returncode,
        "build_log": build_log[-10000:],
    }


def shared_build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> tuple[Path, dict]:
    """The shared project directory and the record of its plan and build."""
    return build_once(shared_dir(tmp_path_factory, worker_id), "ci-build", _build)


def job_counts(plan: str) -> dict[str, int]:
    """The job table of a dry run: {rule: count}."""
    counts = {}
    for line in plan.splitlines():
        words = line.split()
        if len(words) == 2 and words[1].isdigit():
            counts[words[0]] = int(words[1])
    return counts
