"""Notebooks of the scripts (rule ``notebook``, workflow/rules/notebooks.smk) and the report.

One notebook is built for real, in a copy of the project in a temporary directory: that of
Fig. 1, whose rule is the fastest. The figure the notebook draws must be byte-identical to
the one the workflow draws, which shows that the injected ``snakemake`` object is
equivalent to the rule's; the executed notebook must hold the figure as an inline image.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SNAKEMAKE = Path(sys.executable).with_name("snakemake")
COPIED = ["Snakefile", "config", "workflow", "scripts", "paper", "src", "profiles"]
SCRIPTS = sorted(p.stem for p in (ROOT / "scripts").glob("*.py"))


def _snakemake(workdir: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [str(SNAKEMAKE), *args, "--cores", "1"],
        cwd=workdir,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A copy of the workflow's sources (no outputs) in a temporary directory."""
    dest = tmp_path_factory.mktemp("project")
    for name in COPIED:
        src = ROOT / name
        if src.is_dir():
            shutil.copytree(src, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
        elif src.is_file():
            shutil.copy2(src, dest / name)
    return dest


@pytest.fixture(scope="module")
def fig1_notebook(project: Path) -> Path:
    """Build figures/fig1_schematic.* and results/notebooks/fig1_schematic.ipynb."""
    result = _snakemake(
        project, "results/notebooks/fig1_schematic.ipynb", "figures/fig1_schematic.png"
    )
    assert result.returncode == 0, result.stdout + result.stderr
    return project


def test_every_script_has_a_notebook_job(project: Path) -> None:
    """A dry run of target `notebooks` plans one notebook job per script of scripts/."""
    result = subprocess.run(
        [str(SNAKEMAKE), "notebooks", "-n"],
        cwd=project,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode == 0, result.stdout + result.stderr
    counts = dict(line.split()[:2] for line in result.stdout.splitlines() if len(line.split()) == 2)
    assert int(counts["notebook"]) == len(SCRIPTS)
    assert len(SCRIPTS) >= 8  # six figures, claims report, article


def test_notebook_has_inline_figure(fig1_notebook: Path) -> None:
    nb = json.loads((fig1_notebook / "results/notebooks/fig1_schematic.ipynb").read_text())
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    # the injected cell comes first and defines the object of rule fig1_schematic
    assert "rulename='fig1_schematic'" in "".join(code[0]["source"])
    images = [o for c in code for o in c["outputs"] if "image/png" in o.get("data", {})]
    assert len(images) == 1
    errors = [o for c in code for o in c["outputs"] if o["output_type"] == "error"]
    assert errors == []
    # every code cell ran, in order
    assert [c["execution_count"] for c in code] == list(range(1, len(code) + 1))


def test_notebook_draws_the_same_figure_elsewhere(fig1_notebook: Path) -> None:
    """Outputs go to results/notebooks/fig1_schematic/, with the same bytes as figures/."""
    built = fig1_notebook / "figures" / "fig1_schematic.png"
    redirected = fig1_notebook / "results/notebooks/fig1_schematic/figures/fig1_schematic.png"
    assert redirected.read_bytes() == built.read_bytes()
    pdf = redirected.with_suffix(".pdf").read_bytes()
    assert pdf.startswith(b"%PDF")
    assert pdf == built.with_suffix(".pdf").read_bytes()


def test_report_holds_figure_and_caption(fig1_notebook: Path, tmp_path: Path) -> None:
    """`snakemake --report` embeds the figure with its caption from workflow/report/."""
    html = tmp_path / "report.html"
    result = _snakemake(fig1_notebook, "--report", str(html), "figures/fig1_schematic.png")
    assert result.returncode == 0, result.stdout + result.stderr
    text = html.read_text()
    caption = (ROOT / "workflow/report/fig1_schematic.rst").read_text()
    first_words = " ".join(caption.replace("**", "").split()[:6])
    plain = re.sub(r"<[^>]+>", "", text.replace("\\n", " "))  # caption is HTML in a JSON string
    assert first_words in " ".join(plain.split())
    assert "fig1_schematic.png" in text
    png = (fig1_notebook / "figures/fig1_schematic.png").stat().st_size
    assert html.stat().st_size > png  # self-contained: the image is inside


def test_every_figure_has_a_caption() -> None:
    """Each of the six figure rules registers its PNG for the report with a caption file."""
    rules = (ROOT / "workflow/rules/figures.smk").read_text()
    for name in [p.stem for p in (ROOT / "scripts").glob("fig*.py")]:
        assert f'caption="../report/{name}.rst"' in rules, name
        assert (ROOT / "workflow/report" / f"{name}.rst").read_text().strip(), name
