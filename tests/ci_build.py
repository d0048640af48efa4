"""Builds of the project shared by the tests, and the helpers to make them.

``shared_build``: the sources are copied into a temporary directory shared by all xdist
workers of the session; the first worker to ask plans the whole workflow there (a dry run
with the SLURM profile and the dry-run executor, for tests/test_study.py and
test_notebooks.py) and builds the README figure (Fig. 4 copied to docs/, for
tests/test_readme.py) with the project's own configuration. A file lock makes the other
workers wait for that build and reuse it.

``base_config``: the project's configuration cut down, for the builds of everything that
take seconds (tests/test_pipeline.py).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

from shared_build import build_once, shared_dir

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
# The one list of the figures (the workflow generates a rule for each).
FIGURE_NAMES: list[str] = yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text())
COPIED = ["config", "workflow", "scripts", "paper", "src", "profiles"]
TARGETS = ["readme_figure"]


def copy_env(workdir: Path) -> dict[str, str]:
    """The environment of the project's .venv running the copy of the sources in `workdir`:
    the copy's src/ first on the module path, so that its jobs import the copy's package
    (the Snakefile refuses to run another tree's package: the editable install of .venv is
    the project's src/, not the copy's)."""
    return os.environ | {"PYTHONPATH": str(workdir / "src")}


def snakemake(workdir: Path, *args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    """Run snakemake with `args` in `workdir`, a copy of the sources."""
    return subprocess.run(
        [SNAKEMAKE, *args],
        cwd=workdir,
        env=copy_env(workdir),
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


def base_config() -> dict[str, Any]:
    """The project's configuration cut down: fewer curves, samples and values of k, a low
    PNG resolution (the animation as configured: docs/animation.gif is compared with it).

    Every script still runs through all of its code; only the lists are shorter.
    """
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    config["style"]["dpi"] = 60
    for name in FIGURE_NAMES:
        if "n_points" in config.get(name, {}):
            config[name]["n_points"] = min(config[name]["n_points"], 200)
    config["fig3_modal_terms"]["mu0"] = [0.1]
    config["fig4_trajectories"].update(mu0=[0.3, 1.0], t_span=[[0.0, 20.0], [0.0, 30.0]])
    config["fig5_damping_ratio"]["k"] = [0.4]
    config["fig6_limit"].update(mu0_trajectories=[10.0], mu0_layer=[100.0])
    config["fig7_rolling_resistance"]["n_grid"] = 20
    config["study"].update(k=[0.4], n_points=20, n_times=20)
    config["film"].update(fps=30.0)
    config["fig8_measurability"]["n_grid"] = 8
    return config


def write_config(workdir: Path, config: dict[str, Any]) -> None:
    (workdir / "config").mkdir(parents=True, exist_ok=True)
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))


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
            env=copy_env(cwd),
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
    """The job table of a dry run ("Job stats"): {rule: count}, without the total."""
    counts: dict[str, int] = {}
    table = plan.partition("Job stats:")[2]
    for line in table.splitlines():
        words = line.split()
        if words and words[0] == "total":
            break
        if len(words) == 2 and words[1].isdigit():
            counts[words[0]] = int(words[1])
    return counts
