"""Notebooks of the scripts (rule ``notebook``, workflow/rules/notebooks.smk) and the report.

One notebook is built for real, in the shared build of tests/ci_build.py: that of Fig. 1,
whose rule is the fastest. The figure the notebook draws must be byte-identical to the one
the workflow draws, which shows that the injected ``snakemake`` object is equivalent to the
rule's; the executed notebook must hold the figure as an inline image.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from ci_build import ROOT, job_counts, shared_build, snakemake

SCRIPTS = sorted(p.stem for p in (ROOT / "scripts").glob("*.py"))


@pytest.fixture(scope="session")
def build(tmp_path_factory: pytest.TempPathFactory, worker_id: str) -> tuple[Path, dict]:
    workdir, record = shared_build(tmp_path_factory, worker_id)
    assert record["build_returncode"] == 0, record["build_log"]
    return workdir, record


def test_every_script_has_a_notebook_job(build: tuple[Path, dict]) -> None:
    """Planning the default target gives one notebook job per script of scripts/."""
    _, record = build
    assert record["plan_returncode"] == 0, record["plan"]
    assert job_counts(record["plan"])["notebook"] == len(SCRIPTS)
    for name in SCRIPTS:
        assert f"results/notebooks/{name}.ipynb" in record["plan"]
    assert len(SCRIPTS) >= 8  # six figures, claims report, article (+ the study)


def test_notebook_has_inline_figure(build: tuple[Path, dict]) -> None:
    workdir, _ = build
    nb = json.loads((workdir / "results/notebooks/fig1_schematic.ipynb").read_text())
    code = [c for c in nb["cells"] if c["cell_type"] == "code"]
    # the injected cell comes first and defines the object of rule fig1_schematic
    assert "rulename='fig1_schematic'" in "".join(code[0]["source"])
    images = [o for c in code for o in c["outputs"] if "image/png" in o.get("data", {})]
    assert len(images) == 1
    errors = [o for c in code for o in c["outputs"] if o["output_type"] == "error"]
    assert errors == []
    # every code cell ran, in order
    assert [c["execution_count"] for c in code] == list(range(1, len(code) + 1))


def test_notebook_draws_the_same_figure_elsewhere(build: tuple[Path, dict]) -> None:
    """Outputs go to results/notebooks/fig1_schematic/, with the same bytes as figures/."""
    workdir, _ = build
    built = workdir / "figures" / "fig1_schematic.png"
    redirected = workdir / "results/notebooks/fig1_schematic/figures/fig1_schematic.png"
    assert redirected.read_bytes() == built.read_bytes()
    pdf = redirected.with_suffix(".pdf").read_bytes()
    assert pdf.startswith(b"%PDF")
    assert pdf == built.with_suffix(".pdf").read_bytes()


def test_report_holds_figure_and_caption(build: tuple[Path, dict], tmp_path: Path) -> None:
    """`snakemake --report` embeds the figure with its caption from workflow/report/."""
    workdir, _ = build
    html = tmp_path / "report.html"
    result = snakemake(workdir, "--report", str(html), "figures/fig1_schematic.png")
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
    """Each of the six figure rules registers its PNG for the report with a caption file."""
    rules = (ROOT / "workflow/rules/figures.smk").read_text()
    for name in [p.stem for p in (ROOT / "scripts").glob("fig*.py")]:
        assert f'caption="../report/{name}.rst"' in rules, name
        assert (ROOT / "workflow/report" / f"{name}.rst").read_text().strip(), name
