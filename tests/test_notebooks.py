"""Each script runs once per build, as a notebook, in the job that writes its outputs.

The notebooks of the clean build of everything (tests/test_pipeline.py, cut-down
configuration) are checked for what a reader needs: the job's ``snakemake`` object in the
first cell, the docstring as text, the figures inline, no error, no warning of the build,
the same bytes from another build. One notebook is run again by hand, as a reader would: it
draws the same figure without touching figures/. The shared build of tests/ci_build.py
plans the whole workflow with the project's own configuration.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import sys
from pathlib import Path

import jupytext
import nbformat
import pytest
import yaml
from nbclient import NotebookClient

from ci_build import ROOT, shared_build, write_config
from test_pipeline import clean_build, in_project, interrupted_build, shared_tmp  # noqa: F401

SCRIPTS = sorted(p.stem for p in (ROOT / "scripts").glob("*.py"))


def notebooks(workdir: Path) -> dict[str, dict]:
    """The notebooks of a build, by file stem."""
    folder = workdir / "results" / "notebooks"
    return {p.stem: json.loads(p.read_text()) for p in sorted(folder.glob("*.ipynb"))}


def code_cells(nb: dict) -> list[dict]:
    return [c for c in nb["cells"] if c["cell_type"] == "code"]


@pytest.fixture(scope="session")
def build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> tuple[Path, dict]:
    workdir, record = shared_build(tmp_path_factory, worker_id)
    assert record["build_returncode"] == 0, record["build_log"]
    return workdir, record


def test_each_script_runs_in_exactly_one_rule(build: tuple[Path, dict]) -> None:
    """Planning the default target: every script of scripts/ is the input `script` of one
    job (one per k for the study), which also writes its notebook; no job runs it again."""
    _, record = build
    assert record["plan_returncode"] == 0, record["plan"]
    jobs = record["plan"].split("\nrule ")[1:]
    for name in SCRIPTS:
        running = [job for job in jobs if re.search(rf"input: .*scripts/{name}\.py\b", job)]
        expected = 4 if name == "study_k" else 1  # the four values of k of config/config.yaml
        assert len(running) == expected, name
        assert all(f"results/notebooks/{name}" in job for job in running), name
    assert "rule notebook:" not in record["plan"]
    assert len(SCRIPTS) >= 10  # nine figures, films, claims report, article, study, animation


def test_every_script_has_its_notebook(clean_build: Path) -> None:  # noqa: F811
    found = notebooks(clean_build)
    for name in SCRIPTS:
        assert name in found or name == "study_k", name
    assert sorted(n for n in found if n.startswith("study_k_")) == ["study_k_0.4"]


RULE_OF = {"claims_report": "claims", "build_paper": "paper", "study_summary": "study"}


def test_first_cell_is_the_jobs_snakemake_object(clean_build: Path) -> None:  # noqa: F811
    for name, nb in notebooks(clean_build).items():
        first = "".join(code_cells(nb)[0]["source"])
        rule = "study_k" if name.startswith("study_k_") else RULE_OF.get(name, name)
        assert f"snakemake = SimpleNamespace(\n    rule={rule!r}," in first, name
        assert not re.search(r"^(import|from) snakemake", first, re.MULTILINE), name
        assert "._" not in first, name  # nothing private of anything
    fig4 = "".join(code_cells(notebooks(clean_build)["fig4_trajectories"])[0]["source"])
    assert "mu0=[0.3, 1.0]," in fig4  # the parameters of the cut-down configuration
    assert "pdf=OUT + 'figures/fig4_trajectories.pdf'," in fig4


def test_docstring_is_text_and_every_cell_ran(clean_build: Path) -> None:  # noqa: F811
    for name, nb in notebooks(clean_build).items():
        assert nb["cells"][1]["cell_type"] == "markdown", name
        assert "".join(nb["cells"][1]["source"]).startswith("`scripts/"), name
        code = code_cells(nb)
        assert [c["execution_count"] for c in code] == list(range(1, len(code) + 1)), name
        outputs = [o for c in code for o in c["outputs"]]
        assert not [o for o in outputs if o["output_type"] in ("error", "execute_result")], name
        assert outputs, f"{name}: no output"  # the last cell shows what was written
        ids = [c["id"] for c in nb["cells"]]
        assert ids == [f"cell-{i}" for i in range(len(ids))], name


def test_figures_are_inline(clean_build: Path) -> None:  # noqa: F811
    found = notebooks(clean_build)
    for name in ["fig1_schematic", "fig4_trajectories", "study_summary"]:
        images = [
            o for c in code_cells(found[name]) for o in c["outputs"] if "image/png" in o["data"]
        ]
        assert len(images) == 1, name


def test_article_notebook_shows_what_it_wrote(clean_build: Path) -> None:  # noqa: F811
    text = json.dumps(notebooks(clean_build)["build_paper"])
    assert "paper/paper.pdf`: " in text
    assert "wrote paper/paper.pdf" in text  # its log


def test_the_build_warns_nothing(clean_build: Path, shared_tmp: Path) -> None:  # noqa: F811
    record = json.loads((shared_tmp / "pipeline-clean.json").read_text())
    assert record["returncode"] == 0
    assert record["warnings"] == []


def test_notebooks_are_byte_reproducible(
    clean_build: Path,  # noqa: F811
    interrupted_build: tuple[Path, dict],  # noqa: F811
) -> None:
    """The clean build and the killed-and-resumed one write the same notebooks for the
    figures that do not show paths of the repository (those differ between the two)."""
    other, record = interrupted_build
    assert record["returncode"] == 0, record["log"]
    for name in ["fig1_schematic", "fig2_spectrum", "fig4_trajectories"]:
        ours = (clean_build / f"results/notebooks/{name}.ipynb").read_text()
        theirs = (other / f"results/notebooks/{name}.ipynb").read_text()
        # the only difference allowed: where the scripts are, seen from the working directory
        scripts = os.path.relpath(ROOT / "scripts", other)
        assert ours == theirs.replace(repr(scripts), repr("scripts")), name


def test_a_notebook_holds_nothing_of_the_other_sections(
    clean_build: Path,  # noqa: F811
    tmp_path: Path,
) -> None:
    """A value of another section changes no notebook but those of the jobs that read it: the
    notebook of Fig. 2, run again after Fig. 4's parameters changed (and Fig. 4 rebuilt),
    has the bytes it had, those a build from nothing would write."""
    workdir = Path(shutil.copytree(clean_build, tmp_path / "w", symlinks=True))
    fig2 = workdir / "results/notebooks/fig2_spectrum.ipynb"
    fig4 = workdir / "results/notebooks/fig4_trajectories.ipynb"
    before = {path: path.read_bytes() for path in (fig2, fig4)}
    first = "".join(code_cells(json.loads(before[fig2]))[0]["source"])
    assert "config={'fig2_spectrum': {" in first
    assert "fig4_trajectories" not in first
    assert "'style'" not in first
    config = yaml.safe_load((workdir / "config/config.yaml").read_text())
    config["fig4_trajectories"]["mu0"] = [m * 1.1 for m in config["fig4_trajectories"]["mu0"]]
    write_config(workdir, config)
    proc = in_project(workdir, "figures/fig4_trajectories.pdf", cores=1)  # only that job
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert fig4.read_bytes() != before[fig4]
    proc = in_project(workdir, "--forcerun", "fig2_spectrum", "figures/fig2_spectrum.pdf")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "fig2_spectrum" in proc.stderr  # it did run again
    assert fig2.read_bytes() == before[fig2]


def test_a_kernel_writes_the_same_notebook_as_the_driver(
    clean_build: Path,  # noqa: F811
    tmp_path: Path,
) -> None:
    """The driver runs the cells in its own process (workflow/scripts/run_notebook.py); a
    Jupyter kernel driven by nbclient, as the workflow did before, run as the workflow runs
    it (TURNTABLE_NOTEBOOK set), writes the same bytes: outputs, counts, metadata."""
    workdir = Path(shutil.copytree(clean_build, tmp_path / "w", symlinks=True))
    path = workdir / "results/notebooks/fig1_schematic.ipynb"
    saved = path.read_text()
    nb = nbformat.reads(saved, as_version=4)
    env = os.environ | {"TURNTABLE_NOTEBOOK": "results/notebooks/fig1_schematic.ipynb"}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"  # this kernel
    client = NotebookClient(
        nb,
        kernel_name="python3",
        record_timing=False,
        extra_arguments=[
            "--HistoryManager.enabled=False",
            "--InteractiveShell.ast_node_interactivity=none",
        ],
        resources={"metadata": {"path": str(workdir)}},
    )
    client.execute(env=env)
    again = nbformat.writes(nb)
    assert again + ("" if again.endswith("\n") else "\n") == saved


def test_a_notebook_runs_again_by_itself(clean_build: Path, tmp_path: Path) -> None:  # noqa: F811
    """Executed again by hand in its folder, the notebook of Fig. 1 draws the same figure
    under results/notebooks/fig1_schematic/, leaving figures/ untouched."""
    workdir = Path(shutil.copytree(clean_build, tmp_path / "w", symlinks=True))
    figures = {p.name: p.stat().st_mtime_ns for p in (workdir / "figures").iterdir()}
    path = workdir / "results/notebooks/fig1_schematic.ipynb"
    nb = nbformat.read(path, as_version=4)
    env = {k: v for k, v in os.environ.items() if k != "TURNTABLE_NOTEBOOK"}
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env['PATH']}"  # this kernel
    client = NotebookClient(
        nb, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    )
    client.execute(env=env)
    again = workdir / "results/notebooks/fig1_schematic"
    for ext in ("png", "pdf"):
        built = (workdir / f"figures/fig1_schematic.{ext}").read_bytes()
        assert (again / f"figures/fig1_schematic.{ext}").read_bytes() == built
    assert {p.name: p.stat().st_mtime_ns for p in (workdir / "figures").iterdir()} == figures
    assert "wrote" in (again / "logs/fig1_schematic.log").read_text()


@pytest.mark.parametrize("name", SCRIPTS)
def test_jupytext_round_trip_leaves_the_script_unchanged(name: str) -> None:
    """Script -> notebook -> script gives the same bytes (scripts/*.ipynb are ignored)."""
    text = (ROOT / "scripts" / f"{name}.py").read_text()
    notebook = jupytext.writes(jupytext.reads(text, fmt="py:percent"), fmt="ipynb")
    assert jupytext.writes(jupytext.reads(notebook, fmt="ipynb"), fmt="py:percent") == text
    assert "scripts/*.ipynb" in (ROOT / ".gitignore").read_text().splitlines()


def test_report_holds_figure_and_caption(clean_build: Path, tmp_path: Path) -> None:  # noqa: F811
    """`snakemake --report` embeds the figure with its caption from workflow/report/."""
    workdir = clean_build
    html = tmp_path / "report.html"
    result = in_project(workdir, "--report", str(html), "figures/fig1_schematic.png")
    assert result.returncode == 0, result.stdout + result.stderr
    text = html.read_text()
    caption = (ROOT / "workflow/report/fig1_schematic.rst").read_text()
    first_words = " ".join(caption.replace("**", "").split()[:6])
    plain = re.sub(r"<[^>]+>", "", text.replace("\\n", " "))  # caption is HTML in a JSON string
    assert first_words in " ".join(plain.split())
    assert "fig1_schematic.png" in text
    png = (workdir / "figures/fig1_schematic.png").stat().st_size
    assert html.stat().st_size > png  # self-contained: the image is inside


def test_every_figure_has_a_caption() -> None:
    """Each figure of the one list has its script and a caption for the report."""
    from ci_build import FIGURE_NAMES

    assert sorted(FIGURE_NAMES) == sorted(p.stem for p in (ROOT / "scripts").glob("fig*.py"))
    for name in FIGURE_NAMES:
        assert (ROOT / "workflow/report" / f"{name}.rst").read_text().strip(), name


def test_a_failing_script_is_told_in_a_plain_traceback(
    clean_build: Path,  # noqa: F811
    tmp_path: Path,
) -> None:
    workdir = Path(shutil.copytree(clean_build, tmp_path / "w", symlinks=True))
    script = workdir / "scripts" / "fig1_schematic.py"
    head, marker, rest = script.read_text().rpartition('"""\n\n# %%\n')  # after the docstring
    script.write_text(head + marker + "raise ValueError('broken on purpose')\n" + rest)
    proc = in_project(workdir, "figures/fig1_schematic.pdf", cores=1)
    assert proc.returncode != 0
    message = proc.stdout + proc.stderr
    assert "scripts/fig1_schematic.py failed, run as a notebook" in message
    assert "ValueError: broken on purpose" in message
    assert "\x1b[" not in message  # no colour codes
