"""Licence, citation and archive metadata: valid, and telling the same story everywhere.

CITATION.cff is validated against the official CFF 1.2.0 JSON schema
(tests/data/citation-file-format-1.2.0.schema.json; origin in tests/data/README.md).
"""

from __future__ import annotations

import copy
import importlib.util
import json
import re
import sys
import tomllib
from pathlib import Path

import jsonschema
import pytest
import yaml

from ci_build import full_config

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = json.loads(
    (ROOT / "tests" / "data" / "citation-file-format-1.2.0.schema.json").read_text()
)
PAPER_DOI = "10.20537/nd190206"


def _cff() -> dict:
    # The schema's note: YAML dates must be validated as strings (they are quoted in the file).
    return yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))


def _pyproject() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def _errors(document: dict) -> list[str]:
    validator = jsonschema.Draft7Validator(SCHEMA, format_checker=jsonschema.FormatChecker())
    return [e.message for e in validator.iter_errors(document)]


def test_citation_cff_is_valid_cff_1_2_0() -> None:
    cff = _cff()
    assert cff["cff-version"] == "1.2.0"
    assert _errors(cff) == []


@pytest.mark.parametrize(
    ("what", "break_it"),
    [
        ("no authors", lambda c: c.pop("authors")),
        ("unknown key", lambda c: c.update(url_of_paper="x")),
        ("malformed DOI", lambda c: c["references"][0].update(doi="nd190206")),
        ("unknown licence", lambda c: c.update(license="MIT-ish")),
    ],
    ids=lambda v: v if isinstance(v, str) else "",
)
def test_schema_rejects_a_broken_citation(what: str, break_it) -> None:
    cff = copy.deepcopy(_cff())
    break_it(cff)
    assert _errors(cff), what


def test_citation_names_the_reproduced_paper() -> None:
    refs = _cff()["references"]
    paper = [r for r in refs if r.get("doi") == PAPER_DOI]
    assert len(paper) == 1
    assert paper[0]["type"] == "article"
    assert paper[0]["authors"][0]["family-names"] == "Ivanova"
    assert paper[0]["year"] == 2019


def test_metadata_agree() -> None:
    """Version, licence, title and repository are the same in every metadata file."""
    cff = _cff()
    zenodo = json.loads((ROOT / ".zenodo.json").read_text(encoding="utf-8"))
    project = _pyproject()["project"]
    assert cff["version"] == zenodo["version"] == project["version"]
    assert cff["license"] == project["license"] == "MIT"
    # Zenodo's deposit takes the id of its own licence vocabulary: the SPDX id in lower case
    # (a deposit with "MIT" is refused).
    assert zenodo["license"] == "mit"
    assert cff["title"] == zenodo["title"]
    related = {r["identifier"]: r for r in zenodo["related_identifiers"]}
    assert related[PAPER_DOI]["scheme"] == "doi"
    assert cff["repository-code"] in related
    assert project["license-files"] == ["LICENSE"]
    assert (ROOT / "LICENSE").read_text().startswith("MIT License")
    config = full_config()
    assert config["paper"]["repository"] == cff["repository-code"]


def _release_notes():
    spec = importlib.util.spec_from_file_location(
        "release_notes", ROOT / "tools" / "release_notes.py"
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules["release_notes"] = module
    spec.loader.exec_module(module)
    return module


def test_changelog_has_the_current_version() -> None:
    notes = _release_notes()
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    version = _pyproject()["project"]["version"]
    body = notes.section(changelog, f"v{version}")
    assert body.strip()
    assert "## [" not in body
    assert "## [Unreleased]" in changelog


@pytest.mark.parametrize(
    ("text", "version", "expected"),
    [
        ("## [1.0.0] - 2020-01-01\n\nA\n\n## [0.9.0]\n\nB\n", "v1.0.0", "A\n"),
        ("## [1.0.0] - 2020-01-01\n\nA\n\n## [0.9.0]\n\nB\n", "0.9.0", "B\n"),
        ("## [1.0.0]\n- x\n- y\n", "refs/tags/v1.0.0", "- x\n- y\n"),
    ],
    ids=["first", "last", "ref"],
)
def test_release_notes_section(text: str, version: str, expected: str) -> None:
    assert _release_notes().section(text, version) == expected


@pytest.mark.parametrize(
    "text", ["## [1.0.0]\n\nA\n", "## [2.0.0]\n\n## [1.0.0]\n"], ids=["missing", "empty"]
)
def test_release_notes_reject_missing_or_empty(text: str) -> None:
    with pytest.raises(ValueError, match=r"2\.0\.0"):
        _release_notes().section(text, "v2.0.0")


def test_release_job_uses_the_changelog() -> None:
    wf = yaml.safe_load((ROOT / ".github" / "workflows" / "ci.yml").read_text())
    steps = wf["jobs"]["release"]["steps"]
    runs = " ".join(s.get("run", "") for s in steps)
    assert "tools/release_notes.py" in runs
    gh_release = next(s for s in steps if s.get("uses", "").startswith("softprops/"))
    assert gh_release["with"]["body_path"]


def test_workflow_catalog_file() -> None:
    catalog = yaml.safe_load((ROOT / ".snakemake-workflow-catalog.yml").read_text())
    deploy = catalog["usage"]["software-stack-deployment"]
    assert set(deploy) >= {"conda", "apptainer", "apptainer+conda"}
    assert catalog["usage"]["report"] is True
    # conda: true is a promise that every rule names its environment.
    if deploy["conda"]:
        envs = sorted((ROOT / "workflow" / "envs").glob("*.yaml"))
        assert envs
        for smk in (ROOT / "workflow" / "rules").glob("*.smk"):
            text = smk.read_text()
            runs = len(re.findall(r"^\s+(?:script|shell):", text, re.M))
            assert len(re.findall(r"^\s+conda:", text, re.M)) == runs, smk.name


def test_standardized_usage_layout() -> None:
    """The catalogue lists a workflow under "standardized usage" (and reads its usage file)
    only with the main Snakefile at workflow/Snakefile and configuration instructions in
    config/README.md; the instructions name every section of the configuration."""
    assert (ROOT / "workflow" / "Snakefile").is_file()
    assert not (ROOT / "Snakefile").exists()
    readme = (ROOT / "config" / "README.md").read_text(encoding="utf-8")
    config = full_config()
    figures = yaml.safe_load((ROOT / "workflow" / "figures.yaml").read_text(encoding="utf-8"))
    for section in config:
        named = f"`{section}`" in readme
        in_range = section in figures and f"`{figures[0]}` … `{figures[-1]}`" in readme
        assert named or in_range, section
