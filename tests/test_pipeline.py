"""The Snakemake workflow: its outputs, the notebooks on demand, byte-identical reruns, and
exactly the jobs a change reruns (on copies of the clean build of tests/ci_build.py)."""

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

OUTPUTS = sorted(f"figures/{name}.{ext}" for name in NAMES for ext in ("pdf", "png"))
SCRIPTS = sorted(p.stem for p in (ROOT / "scripts").glob("*.py"))
DOWNSTREAM_OF_FIGURES = {"paper", "figure_gallery", "all"}
DRAWING = {*NAMES, "study", "animation", "campaign"}  # the jobs that use scripts/_style


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


def test_no_output_of_the_build_is_a_notebook(clean_build: Path) -> None:
    assert not list(clean_build.rglob("*.ipynb"))


@pytest.mark.slow  # two Jupyter kernels; CI also makes every notebook
def test_a_script_as_a_notebook_writes_what_its_job_wrote(copy: Path) -> None:
    """make notebooks: the same script, the job's inputs and params, its outputs moved under
    results/notebooks/<script>/, byte for byte those of the build; run again by itself, the
    notebook writes them again."""
    name = "fig3_modal_terms"
    proc = in_project(copy, f"results/notebooks/{name}.ipynb")
    assert proc.returncode == 0, proc.stderr
    assert job_counts(proc.stderr) == {f"notebook_{name}": 1}  # and no job of the build
    nb = nbformat.read(copy / f"results/notebooks/{name}.ipynb", as_version=4)
    assert "snakemake = SimpleNamespace(\n    rule=" in nb.cells[0].source
    assert "'mu0': [0.1]" in nb.cells[0].source
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert [c.execution_count for c in code] == list(range(1, len(code) + 1))
    assert not {o.output_type for c in code for o in c.outputs} & {"error", "execute_result"}
    assert any("image/png" in o.data for o in nb.cells[-1].outputs)  # the figure inline
    files = [f"figures/{name}.pdf", f"figures/{name}.png"]
    moved = copy / "results" / "notebooks" / name
    assert {f: sha256(moved / f) for f in files} == {f: sha256(copy / f) for f in files}
    for f in files:
        (moved / f).unlink()
    NotebookClient(nb, resources={"metadata": {"path": str(copy)}}).execute()
    assert {f: sha256(moved / f) for f in files} == {f: sha256(copy / f) for f in files}


def test_a_forced_rerun_writes_the_same_bytes(copy: Path) -> None:
    files = ["figures/fig9_fit.pdf", "figures/fig9_fit.png"]
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
    "the physics": (lambda c: _append(c / "src/turntable/spectrum.py"), "everything"),
    # The tracker runs in the jobs of `turntable` and `python -m turntable.campaign` (it
    # fits videos), then in what reads their outputs; not in the physics' figures and claims.
    "the tracker": (
        lambda c: _append(c / "src/turntable/video/hue.py"),
        {"render_video", "track_video", "fit_video", "fit_film", "campaign_film"}
        | {"campaign_fit", "campaign", "fig9_fit", "fig10_video", "film_page"}
        | {"figure_gallery", "all"},
    ),
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
    "the rate of one film": (  # its batch of batch_size films is fitted again, not the others
        lambda c: _edit_campaign(c, ",45.0,", ",46.0,"),
        {"campaign_film": 1, "campaign_fit": 1, "campaign": 1, "all": 1},
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
    assert (plan(copy) if isinstance(expected, dict) else set(plan(copy))) == expected


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
    first = (clean_build / "logs/paper.log").read_text()
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
