"""The one build of the workflow shared by the tests (all xdist workers, through a file lock).

The workflow's sources are copied into a temporary directory, with the configuration cut
down (`CONFIG`: fewer curves, samples and values of k, three films of the campaign in two
batches; Figure 4 and the animation as the README shows them), planned with the SLURM
profile and the dry-run executor, then built there: everything and the README's copies
(target readme_figure). Snakemake runs from the
project's .venv with the copy's package first on the module path.
"""

from __future__ import annotations

import copy
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
import yaml

from shared_build import build_once, shared_dir
from turntable.config import validate

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
FIGURE_NAMES: list[str] = yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text())
COPIED = ["config", "workflow", "scripts", "paper", "src", "profiles"]
CONFIG: dict[str, Any] = {
    "fig2_spectrum": {"n_points": 200},
    "fig3_modal_terms": {"mu0": [0.1], "n_points": 200},
    "fig5_damping_ratio": {"k": [0.4], "n_points": 200},
    "fig6_limit": {"mu0_trajectories": [10.0], "mu0_layer": [100.0], "n_points": 200},
    "fig7_rolling_resistance": {"n_grid": 20, "comparison": "equal_power"},  # the default
    "study": {"k": [0.4], "n_points": 20, "n_times": 20},
    "film": {"fps": 30.0},
    "fig8_measurability": {"n_grid": 8},
    "claims": {},
    "campaign": {"batch_size": 2},
}
# The campaign of the build: the first two films of the table (tracked) and a video, in two
# batches.
CAMPAIGN_ROWS = [1, 2, 7]


def full_config(config: dict[str, Any] | None = None) -> dict[str, Any]:
    """`config` with the defaults of the schema filled in: without one, the reference values."""
    config = copy.deepcopy(config or {})
    assert validate(config, ROOT / "workflow" / "schemas" / "config.schema.yaml") == []
    return config


def snakemake(workdir: Path, *args: str, timeout: float = 900) -> subprocess.CompletedProcess:
    """Run snakemake with `args` in `workdir`, a copy of the sources; `timeout` stops a hung
    build (a loaded machine of 2 cores takes over 300 s for the full one), it times nothing."""
    return subprocess.run(
        [SNAKEMAKE, *args],
        cwd=workdir,
        env=os.environ | {"PYTHONPATH": str(workdir / "src")},
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


def copy_sources(dest: Path, config: dict[str, Any] | None = None) -> Path:
    """Copy the workflow's sources (no outputs) into `dest`, with `config` as its
    config/config.yaml."""
    for name in COPIED:
        shutil.copytree(ROOT / name, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
    if config is not None:
        (dest / "config" / "config.yaml").write_text(yaml.safe_dump(config))
    return dest


def _cut_campaign(dest: Path) -> None:
    table = dest / "config" / "campaign.csv"
    lines = table.read_text().splitlines(keepends=True)
    table.write_text("".join([lines[0], *(lines[i] for i in CAMPAIGN_ROWS)]))


def _build(workdir: Path) -> dict[str, Any]:
    copy_sources(workdir, CONFIG)
    _cut_campaign(workdir)
    plan = snakemake(workdir, "--profile", "profiles/slurm", "--executor", "dryrun")
    build = snakemake(workdir, "all", "readme_figure", "--cores", "2")
    return {
        "plan_returncode": plan.returncode,
        "plan": plan.stdout + plan.stderr,
        "build_returncode": build.returncode,
        "build_log": build.stderr[-5000:],
    }


def shared_build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> tuple[Path, dict]:
    """The directory of the build, and the record of its plan and build."""
    return build_once(shared_dir(tmp_path_factory, worker_id), "build", _build)


def job_counts(plan: str) -> dict[str, int]:
    """The job table of a dry run ("Job stats"): {rule: count}, without the total."""
    counts: dict[str, int] = {}
    for line in plan.partition("Job stats:")[2].splitlines():
        words = line.split()
        if words and words[0] == "total":
            break
        if len(words) == 2 and words[1].isdigit():
            counts[words[0]] = int(words[1])
    return counts
