"""The Snakemake workflow: outputs and reproducibility (bad configurations:
tests/test_config_errors.py; what a change reruns: tests/test_dependencies.py).

The workflow runs in temporary directories with the project's configuration cut down
(tests/ci_build.py: fewer samples, a low PNG resolution), so that a build takes seconds. Two
builds are shared by the whole test run (and by the xdist workers, through a file lock): a
clean build of everything (and of the README's animation) in a copy of the sources, and a
build of three figures and the animation into an empty directory (``--directory``, the
Snakefile of the repository) that is killed with SIGKILL after its first figure and then
resumed.
"""

from __future__ import annotations

import hashlib
import os
import signal
import subprocess
import time
from base64 import urlsafe_b64decode
from pathlib import Path
from typing import Any

import matplotlib.image
import pytest

from ci_build import FIGURE_NAMES as NAMES
from ci_build import ROOT, SNAKEMAKE, base_config, copy_env, copy_sources, write_config
from shared_build import build_once, shared_dir

OUTPUTS = sorted(f"figures/{name}.{ext}" for name in NAMES for ext in ("pdf", "png"))
# Three figures (with their notebooks) and the animation: enough to kill a build between two
# jobs and compare what the resumed build writes with the clean build.
INTERRUPTED = ["fig1_schematic", "fig2_spectrum", "fig4_trajectories"]
INTERRUPTED_TARGETS = [f"figures/{name}.pdf" for name in INTERRUPTED] + ["figures/animation.gif"]
INTERRUPTED_OUTPUTS = [o for o in OUTPUTS if Path(o).stem in INTERRUPTED]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


# --------------------------------------------------------------------------- utilities
def in_project(workdir: Path, *args: str, cores: int = 2) -> subprocess.CompletedProcess:
    """Run the workflow of the project copy in `workdir` (its own Snakefile and sources, the
    project's .venv with the copy's package: tests/ci_build.copy_env)."""
    return subprocess.run(
        [SNAKEMAKE, "--cores", str(cores), *args],
        cwd=workdir,
        env=copy_env(workdir),
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


def snakemake_cmd(workdir: Path, *args: str, cores: int = 2) -> list[str]:
    return [
        SNAKEMAKE,
        "--snakefile",
        str(ROOT / "workflow" / "Snakefile"),
        "--directory",
        str(workdir),
        "--cores",
        str(cores),
        *args,
    ]


def run_snakemake(workdir: Path, *args: str, cores: int = 2) -> subprocess.CompletedProcess:
    return subprocess.run(
        snakemake_cmd(workdir, *args, cores=cores),
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


def problem(path: Path) -> str | None:
    """Return why `path` is not a complete PDF or PNG, or None if it is one."""
    data = path.read_bytes()
    if path.suffix == ".pdf":
        if not data.startswith(b"%PDF-") or not data.rstrip().endswith(b"%%EOF"):
            return f"{path.name}: not a complete PDF"
        return None
    if not data.startswith(PNG_SIGNATURE):
        return f"{path.name}: no PNG signature"
    try:
        image = matplotlib.image.imread(path)
    except Exception as exc:  # any decoding failure means a broken file
        return f"{path.name}: does not decode ({exc})"
    if image.ndim != 3 or min(image.shape[:2]) < 50:
        return f"{path.name}: unexpected image shape {image.shape}"
    return None


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture(scope="session")
def shared_tmp(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    """A temporary directory shared by all xdist workers of this test run."""
    return shared_dir(tmp_path_factory, worker_id)


def _clean_build(workdir: Path) -> dict:
    """Everything (the default target), from a copy of the sources, with the cut-down config."""
    copy_sources(workdir)
    write_config(workdir, base_config())
    start = time.perf_counter()
    proc = in_project(workdir, "all", "readme_animation")
    return {
        "returncode": proc.returncode,
        "log": proc.stdout[-3000:] + proc.stderr[-3000:],
        "warnings": [line for line in proc.stderr.splitlines() if "WARNING" in line],
        "seconds": time.perf_counter() - start,
    }


def _interrupted_build(workdir: Path) -> dict:
    """Start a one-core build, SIGKILL it after its first figure, then resume it."""
    write_config(workdir, base_config())
    proc = subprocess.Popen(
        snakemake_cmd(workdir, *INTERRUPTED_TARGETS, cores=1),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        start_new_session=True,
    )
    figures = workdir / "figures"
    deadline = time.monotonic() + 120.0
    while time.monotonic() < deadline and proc.poll() is None:
        if any(not p.name.startswith(".") for p in figures.glob("*")):
            break
        time.sleep(0.02)
    running_when_killed = proc.poll() is None
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    after_kill = {p.name: problem(p) for p in sorted(figures.glob("fig*"))}
    incomplete = sorted(
        Path(urlsafe_b64decode(p.name).decode()).name
        for p in (workdir / ".snakemake" / "incomplete").glob("*")
    )
    # SIGKILL leaves Snakemake's lock behind; --unlock is the documented recovery
    unlocked = run_snakemake(workdir, "--unlock", *INTERRUPTED_TARGETS, cores=1)
    resumed = run_snakemake(workdir, *INTERRUPTED_TARGETS)
    return {
        "unlock_returncode": unlocked.returncode,
        "running_when_killed": running_when_killed,
        "after_kill": after_kill,
        "incomplete_markers": incomplete,
        "returncode": resumed.returncode,
        "log": resumed.stdout[-3000:] + resumed.stderr[-3000:],
    }


@pytest.fixture(scope="session")
def clean_build(shared_tmp: Path) -> Path:
    workdir, record = build_once(shared_tmp, "pipeline-clean", _clean_build)
    assert record["returncode"] == 0, record["log"]
    return workdir


@pytest.fixture(scope="session")
def interrupted_build(shared_tmp: Path) -> tuple[Path, dict]:
    return build_once(shared_tmp, "pipeline-interrupted", _interrupted_build)


# --------------------------------------------------------------------------- a full build
def test_workflow_declares_exactly_its_figures(clean_build: Path) -> None:
    proc = in_project(clean_build, "--summary", "figures", cores=1)
    assert proc.returncode == 0, proc.stderr
    rows = [line.split("\t") for line in proc.stdout.splitlines() if line.startswith("figures/")]
    assert sorted(row[0] for row in rows) == OUTPUTS
    assert all(row[4] == "ok" and row[5] == "no update" for row in rows), rows


@pytest.mark.parametrize("output", OUTPUTS)
def test_every_output_is_a_valid_file(clean_build: Path, output: str) -> None:
    assert problem(clean_build / output) is None


@pytest.mark.parametrize("name", NAMES)
def test_every_rule_writes_its_log(clean_build: Path, name: str) -> None:
    log = (clean_build / "logs" / f"{name}.log").read_text()
    assert f"wrote figures/{name}.pdf" in log


def test_no_partial_files_are_left(clean_build: Path) -> None:
    assert sorted(p.name for p in (clean_build / "figures").iterdir()) == sorted(
        [Path(o).name for o in OUTPUTS] + ["animation.gif"]
    )


# --------------------------------------------------------------------------- interruption
def test_a_killed_build_leaves_no_file_a_later_run_accepts(
    interrupted_build: tuple[Path, dict],
) -> None:
    workdir, record = interrupted_build
    assert record["running_when_killed"], "the build ended before it could be killed"
    finished = {name for name, why in record["after_kill"].items() if why is None}
    assert len(finished) < len(INTERRUPTED_OUTPUTS), "nothing was left to do after the kill"
    # a file under its final name is complete, unless Snakemake marked it incomplete
    broken = {name for name, why in record["after_kill"].items() if why is not None}
    assert broken <= set(record["incomplete_markers"]), record["after_kill"]
    assert record["returncode"] == 0, record["log"]
    for output in INTERRUPTED_OUTPUTS:
        assert problem(workdir / output) is None
    assert not list((workdir / "figures").glob(".*")), "a partial file was left behind"


def test_two_builds_are_byte_identical(
    clean_build: Path, interrupted_build: tuple[Path, dict]
) -> None:
    """The resumed build and the clean build produce the same figures, byte for byte."""
    other, record = interrupted_build
    assert record["returncode"] == 0, record["log"]
    differ = [o for o in INTERRUPTED_OUTPUTS if sha256(clean_build / o) != sha256(other / o)]
    assert differ == []


def test_saving_is_atomic(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A failure while writing a figure leaves neither the file nor a partial copy."""
    monkeypatch.syspath_prepend(str(ROOT / "scripts"))
    from matplotlib.figure import Figure

    import _style

    class Names(dict):
        __getattr__ = dict.__getitem__

    job = Names(
        output=Names(pdf=str(tmp_path / "f.pdf"), png=str(tmp_path / "f.png")),
        params=Names(dpi=50),
    )
    fig = Figure()
    fig.add_subplot().plot([0, 1])
    real_savefig = fig.savefig

    def savefig_then_fail_on_png(fname: Any, **kwargs: Any) -> None:
        if kwargs["format"] == "png":
            Path(fname).write_bytes(PNG_SIGNATURE)  # a truncated file, then an error
            raise OSError("disk full")
        real_savefig(fname, **kwargs)

    monkeypatch.setattr(fig, "savefig", savefig_then_fail_on_png)
    with pytest.raises(OSError, match="disk full"):
        _style.save(fig, job)
    # the PDF was finished and renamed; the PNG left neither its final name nor a temporary
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.pdf"]
    assert problem(tmp_path / "f.pdf") is None
