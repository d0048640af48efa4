"""The parts of the documentation site made when it is built (docs/site_pages.py): numbers
rounded, the extras as pyproject.toml lists them, each notebook under a title in order."""

from __future__ import annotations

import json
import sys
import tomllib
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "docs"))
import site_pages  # noqa: E402

FIGURES = ["animation", *yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text())]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("k = 0.05, 0.4, 0.6666666666666666, 1.0", "k = 0.05, 0.4, 0.6667, 1.0"),
        ("Ω = 3.4906585039886595 rad/s", "Ω = 3.491 rad/s"),
        ('"aicc": 10309.818125782538,', '"aicc": 10310,'),
        ("-3.00700498427604 and 0.00018852858805378786", "-3.007 and 0.0001885"),
        ("1e-05, 2.5e-07, 1.25e-3, 12 and 0.2500", "1e-05, 2.5e-07, 1.25e-3, 12 and 0.2500"),
        (
            "v0.2.0, fig4.png, study_k_0.666667",
            "v0.2.0, fig4.png, study_k_0.666667",
        ),
    ],
)
def test_round_floats(text: str, expected: str) -> None:
    assert site_pages.round_floats(text) == expected


@pytest.fixture
def out(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setattr(site_pages, "OUT", tmp_path / "generated")
    return tmp_path / "generated"


def test_installation_lists_every_extra_of_pyproject(out: Path) -> None:
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    site_pages.installation()
    text = (out / "installation.md").read_text()
    assert f"dist/turntable-{project['version']}-py3-none-any.whl" in text
    rows = [line.split(" | ") for line in text.splitlines() if line.startswith("| ")][1:]
    assert {row[0].strip("| ") for row in rows} == set(project["optional-dependencies"])
    for extra, packages in project["optional-dependencies"].items():
        assert f"| {extra} | {', '.join(packages)} |" in text


def _notebook(path: Path) -> None:
    cell = {"cell_type": "code", "id": "a", "metadata": {}, "source": "1", "outputs": []}
    cell["execution_count"] = 1
    path.write_text(
        json.dumps({"cells": [cell], "metadata": {}, "nbformat": 4, "nbformat_minor": 5})
    )


def test_notebooks_titled_and_in_the_order_of_the_article(
    out: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    built, site = tmp_path / "built", tmp_path / "site"
    built.mkdir()
    monkeypatch.setattr(site_pages, "NOTEBOOKS", built)
    monkeypatch.setattr(site_pages, "SITE_NOTEBOOKS", site)
    for name in [*reversed(FIGURES), "study_k_0.666667", "claims_report"]:
        _notebook(built / f"{name}.ipynb")
    site_pages.notebooks()

    toc = (out / "notebooks.rst").read_text().split()
    entries = [e.removeprefix("/notebooks/") for e in toc if e.startswith("/notebooks/")]
    assert entries == [*FIGURES, "claims_report", "study_k_0.666667"]

    def first_cell(name: str) -> str:
        cells = json.loads((site / f"{name}.ipynb").read_text())["cells"]
        assert [c["cell_type"] for c in cells] == ["markdown", "code"]
        return "".join(cells[0]["source"])

    assert first_cell("fig4_trajectories").startswith("# Figure 4: notebook\n")
    assert "`scripts/fig4_trajectories.py`" in first_cell("fig4_trajectories")
    assert "{ref}`the figure <fig4_trajectories>`" in first_cell("fig4_trajectories")
    assert first_cell("study_k_0.666667").startswith("# study_k (0.6667)\n")
    assert "`scripts/study_k.py`" in first_cell("study_k_0.666667")

    (built / "fig4_trajectories.ipynb").unlink()
    with pytest.raises(SystemExit, match=r"fig4_trajectories\.ipynb: missing; run make notebooks"):
        site_pages.notebooks()
