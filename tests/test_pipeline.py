"""The Snakemake workflow: its outputs and notebooks, byte-identical reruns, and exactly the
jobs a change reruns (on copies of the clean build of tests/ci_build.py)."""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import subprocess
from pathlib import Path

import matplotlib.image
import nbformat
import numpy as np
import pytest
import yaml
from nbclient import NotebookClient
from PIL import Image

import ci_build
from ci_build import FIGURE_NAMES as NAMES
from ci_build import ROOT, job_counts, snakemake
from shared_build import shared_dir

OUTPUTS = sorted(f"figures/{name}.{ext}" for name in NAMES for ext in ("pdf", "png"))
SCRIPTS = sorted(p.stem for p in (ROOT / "scripts").glob("*.py"))
DOWNSTREAM_OF_FIGURES = {"paper", "figure_gallery", "all"}
DRAWING = {*NAMES, "study", "animation", "campaign"}  # the jobs that use scripts/_style


@pytest.fixture(scope="session")
def shared_tmp(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    return shared_dir(tmp_path_factory, worker_id)


@pytest.fixture(scope="session")
def clean_build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> Path:
    return ci_build.clean_build(tmp_path_factory, worker_id)


@pytest.fixture
def copy(clean_build: Path, tmp_path: Path) -> Path:
    """A copy of the clean build, sources and outputs, with their times (like cp -a)."""
    return Path(shutil.copytree(clean_build, tmp_path / "moved", symlinks=True))


def in_project(workdir: Path, *args: str, cores: int = 2):
    return snakemake(workdir, "--cores", str(cores), *args)


def plan(workdir: Path, *args: str) -> dict[str, int]:
    """The jobs a dry run of the default target would run: {rule: count}."""
    proc = snakemake(workdir, "--dry-run", *args)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return {} if "Nothing to be done" in proc.stdout + proc.stderr else job_counts(proc.stdout)


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize("output", OUTPUTS)
def test_every_figure_is_a_complete_file(clean_build: Path, output: str) -> None:
    data = (clean_build / output).read_bytes()
    if output.endswith(".pdf"):
        assert data.startswith(b"%PDF-")
        assert data.rstrip().endswith(b"%%EOF")
    else:
        assert min(matplotlib.image.imread(clean_build / output).shape[:2]) >= 50
    assert not list((clean_build / "figures").glob(".*")), "a partial file was left behind"


def test_every_script_ran_once_as_a_notebook_with_its_outputs(clean_build: Path) -> None:
    found = {p.stem: p for p in (clean_build / "results" / "notebooks").glob("*.ipynb")}
    expected = {name for name in SCRIPTS if name != "study_k"} | {"study_k_0.4"}
    assert set(found) == expected
    for name, path in found.items():
        nb = nbformat.read(path, as_version=4)
        first = nb.cells[0].source
        assert "snakemake = SimpleNamespace(\n    rule=" in first, name
        code = [c for c in nb.cells if c.cell_type == "code"]
        assert [c.execution_count for c in code] == list(range(1, len(code) + 1)), name
        kinds = {o.output_type for c in code for o in c.outputs}
        assert not kinds & {"error", "execute_result"}, name
    fig4 = nbformat.read(found["fig4_trajectories"], as_version=4)
    assert "'mu0': [0.1]" in nbformat.read(found["fig3_modal_terms"], 4).cells[0].source
    assert any("image/png" in o.data for o in fig4.cells[-1].outputs)  # the figure inline


def test_a_notebook_runs_again_by_itself_and_writes_the_same_bytes(copy: Path) -> None:
    nb = nbformat.read(copy / "results/notebooks/fig2_spectrum.ipynb", as_version=4)
    before = {
        p: sha256(copy / p) for p in ["figures/fig2_spectrum.pdf", "figures/fig2_spectrum.png"]
    }
    for p in before:
        (copy / p).unlink()
    NotebookClient(nb, resources={"metadata": {"path": str(copy)}}).execute()
    assert {p: sha256(copy / p) for p in before} == before


def test_a_forced_rerun_writes_the_same_bytes(copy: Path) -> None:
    files = ["figures/fig9_fit.pdf", "figures/fig9_fit.png", "results/notebooks/fig9_fit.ipynb"]
    before = {f: sha256(copy / f) for f in files}
    proc = in_project(copy, "figures/fig9_fit.pdf", "--forcerun", "fig9_fit")
    assert proc.returncode == 0, proc.stderr
    assert "fig9_fit" in proc.stderr
    assert {f: sha256(copy / f) for f in files} == before


def test_a_copy_of_the_build_has_nothing_to_do(copy: Path) -> None:
    assert plan(copy) == {}


def test_a_copy_run_with_another_trees_package_stops_before_any_job(copy: Path) -> None:
    """Without the copy's src/ on the module path, .venv imports the project's package."""
    proc = subprocess.run(
        [ci_build.SNAKEMAKE, "--dry-run"], cwd=copy, capture_output=True, text=True, check=False
    )
    assert proc.returncode != 0
    assert f"not from {copy / 'src'}" in proc.stdout + proc.stderr


def _append(path: Path, text: str = "\n# edited\n") -> None:
    with open(path, "a") as f:
        f.write(text)


def _same_values_in_another_order(copy: Path) -> None:
    """The build's values written back with the sections and keys in reverse order, and a
    section of defaults restated: the same configuration, as data."""
    config = yaml.safe_load((copy / "config/config.yaml").read_text())
    restated = {s: dict(reversed(config[s].items())) for s in reversed(list(config))}
    restated["paper"] = {
        "timestamp": 1735689600,
        "repository": "",
    }
    (copy / "config/config.yaml").write_text(yaml.safe_dump(restated, sort_keys=False))


def _change_a_parameter(copy: Path) -> None:
    config = yaml.safe_load((copy / "config/config.yaml").read_text())
    config["fig3_modal_terms"]["mu0"] = [0.2]
    (copy / "config/config.yaml").write_text(yaml.safe_dump(config))


def _edit_campaign(copy: Path, old: str, new: str) -> None:
    """Replace `old` by `new` in the first row of the campaign table that holds it."""
    table = copy / "config/campaign.csv"
    lines = table.read_text().splitlines(keepends=True)
    row = next(i for i, line in enumerate(lines) if old in line)
    lines[row] = lines[row].replace(old, new)
    table.write_text("".join(lines))


EDITS = {
    "the package": (lambda c: _append(c / "src/turntable/spectrum.py"), "everything"),
    "editor files in the package": (
        lambda c: [
            (c / "src/turntable" / n).write_text("x") for n in [".#spectrum.py", "spectrum.py~"]
        ],
        set(),
    ),
    "a script": (
        lambda c: _append(c / "scripts/fig2_spectrum.py"),
        {"fig2_spectrum"} | DOWNSTREAM_OF_FIGURES,
    ),
    "the style": (
        lambda c: _append(c / "scripts/_style/turntable.mplstyle"),
        DRAWING | DOWNSTREAM_OF_FIGURES | {"film_page"},
    ),
    "a caption": (
        lambda c: _append(c / "workflow/report/fig2_spectrum.rst", "\n"),
        {"figure_gallery", "all"},
    ),
    "a parameter": (_change_a_parameter, {"fig3_modal_terms"} | DOWNSTREAM_OF_FIGURES),
    "a label of the campaign": (
        lambda c: _edit_campaign(c, ",felt,", ",wool,"),
        {"campaign", "all"},
    ),
    "the rate of one film": (
        lambda c: _edit_campaign(c, ",45.0,", ",46.0,"),
        {"campaign_film", "campaign_fit", "campaign", "all"},
    ),
    "the same values in another order": (_same_values_in_another_order, set()),
}


@pytest.mark.parametrize("what", EDITS)
def test_a_change_reruns_exactly_the_jobs_it_touches(copy: Path, what: str) -> None:
    edit, expected = EDITS[what]
    edit(copy)
    if expected == "everything":
        expected = set(plan(copy, "--forceall"))
        assert len(expected) >= 20
    assert set(plan(copy)) == expected


def test_the_animation_moves_frame_by_frame(clean_build: Path) -> None:
    a = yaml.safe_load((ROOT / "workflow/schemas/config.schema.yaml").read_text())
    a = {k: v["default"] for k, v in a["properties"]["animation"]["properties"].items()}
    with Image.open(clean_build / "figures/animation.gif") as gif:
        assert (gif.n_frames, gif.info["duration"]) == (a["n_frames"], a["frame_ms"])
        assert 2 * a["size"] <= gif.width <= 2 * a["size"] + 10
        frames = []
        for i in (0, gif.n_frames // 2, gif.n_frames - 1):
            gif.seek(i)
            frames.append(np.asarray(gif.convert("RGB")))
    assert not np.array_equal(frames[0], frames[1])
    assert not np.array_equal(frames[1], frames[2])


def test_the_article_lists_exactly_the_values_that_differ_from_the_defaults(
    clean_build: Path,
) -> None:
    """Compared as data: a value restated as its default (fig7's comparison) is not listed."""
    first = nbformat.read(clean_build / "results/notebooks/build_paper.ipynb", 4).cells[0].source
    defaults = ci_build.full_config()
    expected = sorted(
        f"{section}.{key} = {json.dumps(value)}"
        for section, values in ci_build.CONFIG.items()
        for key, value in values.items()
        if value != defaults[section][key]
    )
    assert expected
    listed = re.findall(r"'([a-z0-9_]+\.[a-z0-9_]+ = [^']*)'", first)
    assert listed == expected
