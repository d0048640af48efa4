"""Licence, citation and archive metadata: valid, and telling the same story everywhere.

CITATION.cff is validated against the official CFF 1.2.0 JSON schema
(tests/data/citation-file-format-1.2.0.schema.json; origin in tests/data/README.md).
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import json
import re
import sys
import tomllib
from pathlib import Path

import jsonschema
import pytest
import yaml

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


def test_metadata_agree() -> None:
    """Version, licence and title are the same in every metadata file, and none names a
    repository address: the project has none it can confirm (no remote of the clone)."""
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
    assert "repository-code" not in cff
    assert [r for r in related.values() if r["scheme"] == "url"] == []
    assert project["license-files"] == ["LICENSE"]
    assert (ROOT / "LICENSE").read_text().startswith("MIT License")


def _release_notes():
    spec = importlib.util.spec_from_file_location(
        "release_notes", ROOT / "tools" / "release_notes.py"
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules["release_notes"] = module
    spec.loader.exec_module(module)
    return module


def test_version_is_read_from_pyproject() -> None:
    """pyproject.toml holds the version; the package reads it from the installed metadata,
    and the changelog has a dated section for it under an Unreleased one."""
    import turntable

    version = _pyproject()["project"]["version"]
    assert turntable.__version__ == importlib.metadata.version("turntable") == version
    assert not re.search(
        r"^__version__ = [\"']", (ROOT / "src/turntable/__init__.py").read_text(), re.M
    )
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    headings = re.findall(r"^## \[(.+?)\](?: - (\d{4}-\d{2}-\d{2}))?$", changelog, re.M)
    assert headings[:2] == [("Unreleased", ""), (version, _cff()["date-released"])]
    assert _release_notes().section(changelog, version).strip()


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
