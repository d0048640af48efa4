"""The workflow reruns exactly what a change touches, and nothing when the tree moves.

On copies of the clean build of everything (tests/test_pipeline.py: the sources copied into a
temporary directory, the configuration cut down), one thing is changed and a dry run of the
default target tells which jobs Snakemake would run: every job whose script imports the
package after an edit of the package, only the jobs of a script (and those that read its
outputs) after an edit of that script, nothing after a copy of the whole tree.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import yaml

from ci_build import FIGURE_NAMES, base_config, job_counts, shared_build, write_config
from test_pipeline import clean_build, in_project, shared_tmp  # noqa: F401

DRAWING = {*FIGURE_NAMES, "study", "animation"}  # the jobs that use scripts/_style
DOWNSTREAM_OF_FIGURES = {"paper", "figure_gallery", "all"}


def plan(workdir: Path) -> dict[str, int]:
    """The jobs a dry run of the default target would run: {rule: count}."""
    proc = in_project(workdir, "--dry-run", cores=1)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    if "Nothing to be done" in proc.stdout + proc.stderr:
        return {}
    return job_counts(proc.stdout)


@pytest.fixture
def copy(clean_build: Path, tmp_path: Path) -> Path:  # noqa: F811
    """A copy of the clean build, sources and outputs, with their times (like cp -a)."""
    return Path(shutil.copytree(clean_build, tmp_path / "moved", symlinks=True))


@pytest.fixture(scope="module")
def everything(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> dict[str, int]:
    """Every job of the default target: the plan of the project from nothing (tests/ci_build.py),
    with the one value of k of the cut-down configuration."""
    _, record = shared_build(tmp_path_factory, worker_id)
    assert record["plan_returncode"] == 0, record["plan"]
    return job_counts(record["plan"]) | {"study_k": len(base_config()["study"]["k"])}


def test_a_build_and_a_copy_of_it_leave_nothing_to_do(copy: Path) -> None:
    """Inputs are recorded relative to the working directory: moving the tree changes none
    (and so a dry run on the copy shows that the build itself left nothing to do)."""
    assert plan(copy) == {}


@pytest.mark.parametrize("edit", ["append a comment", "add a module"])
def test_editing_the_package_reruns_every_job_that_imports_it(
    copy: Path, everything: dict[str, int], edit: str
) -> None:
    package = copy / "src" / "turntable"
    if edit == "append a comment":
        with open(package / "spectrum.py", "a") as f:
            f.write("# an edit\n")
    else:
        (package / "new_module.py").write_text('"""A new module."""\n')
    # every job: each imports turntable, or reads what such a job wrote
    assert plan(copy) == everything


@pytest.mark.parametrize(
    ("script", "expected"),
    [
        ("scripts/fig2_spectrum.py", {"fig2_spectrum"} | DOWNSTREAM_OF_FIGURES),
        ("scripts/study_k.py", {"study_k", "study", "all"}),
        ("scripts/claims_report.py", {"claims", "claims_table", "paper", "all"}),
        ("scripts/_style/turntable.mplstyle", DRAWING | DOWNSTREAM_OF_FIGURES),
    ],
)
def test_editing_a_script_reruns_only_its_jobs(copy: Path, script: str, expected: set) -> None:
    with open(copy / script, "a") as f:
        f.write("\n# an edit\n" if script.endswith(".py") else "\n")
    planned = plan(copy)
    assert set(planned) == expected
    if "study_k" in expected:
        assert planned["study_k"] == len(base_config()["study"]["k"])  # one job per k


@pytest.mark.parametrize(
    ("section", "key", "expected"),
    [
        ("fig4_trajectories", "mu0", {"fig4_trajectories"} | DOWNSTREAM_OF_FIGURES),
        ("style", "dpi", {*FIGURE_NAMES, "study"} | DOWNSTREAM_OF_FIGURES),
    ],
)
def test_editing_a_parameter_reruns_the_jobs_that_read_it(
    copy: Path, section: str, key: str, expected: set
) -> None:
    config = yaml.safe_load((copy / "config" / "config.yaml").read_text())
    value = config[section][key]
    config[section][key] = [v * 1.1 for v in value] if isinstance(value, list) else value + 1
    write_config(copy, config)
    assert set(plan(copy)) == expected
