"""The Snakemake workflow of the figures: outputs, reproducibility, configuration checks.

The workflow runs into temporary directories (``--directory``) with a copy of
config/config.yaml whose sample counts and PNG resolution are reduced, so that a build
takes seconds. Two builds are shared by the whole test run (and by the xdist workers,
through a file lock): a clean one, and one that is killed with SIGKILL after its first
figure and then resumed.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from base64 import urlsafe_b64decode
from collections.abc import Callable
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import matplotlib.image
import pytest
import yaml

from shared_build import build_once, shared_dir

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = str(Path(sys.executable).with_name("snakemake"))
NAMES = [
    "fig1_schematic",
    "fig2_spectrum",
    "fig3_modal_terms",
    "fig4_trajectories",
    "fig5_damping_ratio",
    "fig6_limit",
    "fig7_rolling_resistance",
]
OUTPUTS = sorted(f"figures/{name}.{ext}" for name in NAMES for ext in ("pdf", "png"))
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


# --------------------------------------------------------------------------- utilities
def base_config() -> dict[str, Any]:
    """The project's configuration cut down: fewer curves and samples, a low PNG resolution.

    Every script still runs through all of its code; only the lists are shorter.
    """
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    config["style"]["dpi"] = 60
    for name in NAMES[1:]:
        config[name]["n_points"] = min(config[name]["n_points"], 200)
    config["fig3_modal_terms"]["mu0"] = [0.1]
    config["fig4_trajectories"].update(mu0=[0.3, 1.0], t_span=[[0.0, 20.0], [0.0, 30.0]])
    config["fig5_damping_ratio"]["k"] = [0.4]
    config["fig6_limit"].update(mu0_trajectories=[10.0], mu0_layer=[100.0], n_error=3)
    config["fig7_rolling_resistance"]["n_grid"] = 20
    return config


def write_config(workdir: Path, config: dict[str, Any]) -> None:
    (workdir / "config").mkdir(parents=True, exist_ok=True)
    (workdir / "config" / "config.yaml").write_text(yaml.safe_dump(config, sort_keys=False))


def snakemake_cmd(workdir: Path, *args: str, cores: int = 2) -> list[str]:
    return [
        SNAKEMAKE,
        "--snakefile",
        str(ROOT / "Snakefile"),
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
    write_config(workdir, base_config())
    start = time.perf_counter()
    proc = run_snakemake(workdir, "figures")
    return {
        "returncode": proc.returncode,
        "log": proc.stdout[-3000:] + proc.stderr[-3000:],
        "seconds": time.perf_counter() - start,
    }


def _interrupted_build(workdir: Path) -> dict:
    """Start a one-core build, SIGKILL it after its first figure, then resume it."""
    write_config(workdir, base_config())
    proc = subprocess.Popen(
        snakemake_cmd(workdir, "figures", cores=1),
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
    after_kill = {
        p.name: problem(p) for p in sorted(figures.glob("*")) if not p.name.startswith(".")
    }
    incomplete = sorted(
        Path(urlsafe_b64decode(p.name).decode()).name
        for p in (workdir / ".snakemake" / "incomplete").glob("*")
    )
    # SIGKILL leaves Snakemake's lock behind; --unlock is the documented recovery
    unlocked = run_snakemake(workdir, "--unlock", "figures", cores=1)
    resumed = run_snakemake(workdir, "figures")
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
    proc = run_snakemake(clean_build, "--summary", "figures", cores=1)
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
        Path(o).name for o in OUTPUTS
    )


# --------------------------------------------------------------------------- change detection
def scheduled_rules(workdir: Path) -> set[str]:
    """Rules a dry run of the figures target would execute (from its 'Job stats' table)."""
    proc = run_snakemake(workdir, "-n", "figures", cores=1)
    assert proc.returncode == 0, proc.stderr
    out = proc.stdout + proc.stderr
    return set(re.findall(r"^(fig\d_\w+)\s+1$", out, flags=re.MULTILINE))


@pytest.mark.parametrize(
    ("section", "key", "value", "expected"),
    [
        ("fig4_trajectories", "mu0", [0.3, 2.0], {"fig4_trajectories"}),
        ("style", "dpi", 61, set(NAMES)),
    ],
)
def test_editing_a_parameter_reruns_exactly_the_figures_that_use_it(
    clean_build: Path, tmp_path: Path, section: str, key: str, value: Any, expected: set[str]
) -> None:
    workdir = tmp_path / "copy"
    shutil.copytree(clean_build, workdir, symlinks=True)  # copy2 keeps the mtimes
    config = base_config()
    config[section][key] = value
    write_config(workdir, config)
    assert scheduled_rules(workdir) == expected


# --------------------------------------------------------------------------- interruption
def test_a_killed_build_leaves_no_file_a_later_run_accepts(
    interrupted_build: tuple[Path, dict],
) -> None:
    workdir, record = interrupted_build
    assert record["running_when_killed"], "the build ended before it could be killed"
    finished = {name for name, why in record["after_kill"].items() if why is None}
    assert len(finished) < len(OUTPUTS), "nothing was left to do after the kill"
    # a file under its final name is complete, unless Snakemake marked it incomplete
    broken = {name for name, why in record["after_kill"].items() if why is not None}
    assert broken <= set(record["incomplete_markers"]), record["after_kill"]
    assert record["returncode"] == 0, record["log"]
    for output in OUTPUTS:
        assert problem(workdir / output) is None
    assert not list((workdir / "figures").glob(".*")), "a partial file was left behind"


def test_two_builds_are_byte_identical(
    clean_build: Path, interrupted_build: tuple[Path, dict]
) -> None:
    """The resumed build and the clean build produce the same bytes."""
    other, record = interrupted_build
    assert record["returncode"] == 0, record["log"]
    differ = [o for o in OUTPUTS if sha256(clean_build / o) != sha256(other / o)]
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


# --------------------------------------------------------------------------- bad configurations
def _set(path: str, value: Any) -> Callable[[dict], None]:
    section, key = path.split(".")

    def edit(config: dict) -> None:
        config[section][key] = value

    return edit


def _delete(path: str) -> Callable[[dict], None]:
    section, key = path.split(".")
    return lambda config: config[section].pop(key)


BAD_CONFIGS = {
    "mu0 zero": (
        _set("fig3_modal_terms.mu0", [0.1, 0.0]),
        ["fig3_modal_terms", "mu0", "less than or equal to the minimum of 0"],
    ),
    "k negative": (_set("fig2_spectrum.k", -0.4), ["fig2_spectrum", "'k'", "minimum of 0"]),
    "string for a number": (
        _set("fig5_damping_ratio.n_points", "300"),
        ["fig5_damping_ratio", "n_points", "is not of type 'integer'"],
    ),
    "missing key": (
        _delete("fig6_limit.mu0_layer"),
        ["fig6_limit", "'mu0_layer' is a required property"],
    ),
    "empty list": (
        _set("fig6_limit.mu0_trajectories", []),
        ["fig6_limit", "mu0_trajectories", "should be non-empty"],
    ),
    "unknown key": (
        _set("fig1_schematic.colour", "red"),
        ["fig1_schematic", "Additional properties are not allowed ('colour'"],
    ),
    "time span reversed": (
        _set("fig3_modal_terms.t_span", [8.0, 0.0]),
        ["fig3_modal_terms.t_span = [8.0, 0.0]", "rule fig3_modal_terms"],
    ),
    "one of several time spans reversed": (
        _set("fig4_trajectories.t_span", [[0.0, 20.0], [30.0, 0.0]]),
        ["fig4_trajectories.t_span[1]", "rule fig4_trajectories"],
    ),
    "mu0 range reversed": (
        _set("fig2_spectrum.mu0_range", [10.0, 1.0]),
        ["fig2_spectrum.mu0_range", "rule fig2_spectrum"],
    ),
    "time spans and mu0 of different lengths": (
        _set("fig4_trajectories.t_span", [[0.0, 45.0]]),
        ["fig4_trajectories.t_span has 1 entries", "rule fig4_trajectories"],
    ),
}


def rejection(config: dict) -> str:
    """Return the message with which the workflow rejects `config`, or '' if it accepts it.

    Runs the two checks the Snakefile runs before building the DAG: the JSON schema (with
    the same snakemake.utils.validate call) and check_config of workflow/rules/common.smk.
    """
    from snakemake.exceptions import WorkflowError
    from snakemake.utils import validate

    namespace = {"workflow": SimpleNamespace(basedir=str(ROOT))}
    common = ROOT / "workflow" / "rules" / "common.smk"
    exec(compile(common.read_text(), str(common), "exec"), namespace)
    try:
        validate(config, str(ROOT / "workflow/schemas/config.schema.yaml"), set_default=False)
        namespace["check_config"](config)
    except WorkflowError as exc:
        return str(exc)
    return ""


def test_the_project_configuration_is_accepted() -> None:
    config = yaml.safe_load((ROOT / "config" / "config.yaml").read_text())
    assert rejection(config) == ""
    assert rejection(base_config()) == ""


@pytest.mark.parametrize("case", list(BAD_CONFIGS))
def test_bad_configuration_is_rejected_naming_key_and_rule(case: str) -> None:
    edit, expected = BAD_CONFIGS[case]
    config = base_config()
    edit(config)
    message = rejection(config)
    for text in expected:
        assert text in message, message


@pytest.mark.parametrize("case", ["k negative", "time span reversed"])
def test_bad_configuration_stops_snakemake_before_any_job(tmp_path: Path, case: str) -> None:
    """End to end, for one schema violation and one failed order check."""
    edit, expected = BAD_CONFIGS[case]
    config = base_config()
    edit(config)
    write_config(tmp_path, config)
    existing = tmp_path / "figures" / "fig2_spectrum.pdf"
    existing.parent.mkdir()
    existing.write_bytes(b"%PDF-1.4 an earlier build\n%%EOF\n")
    before = existing.stat().st_mtime_ns

    proc = run_snakemake(tmp_path, "figures", cores=1)

    message = proc.stdout + proc.stderr
    assert proc.returncode != 0
    for text in expected:
        assert text in message, message[-2000:]
    assert existing.read_bytes() == b"%PDF-1.4 an earlier build\n%%EOF\n"
    assert existing.stat().st_mtime_ns == before
    assert sorted(p.name for p in existing.parent.iterdir()) == ["fig2_spectrum.pdf"]
    assert not (tmp_path / "logs").exists(), "a job started"
