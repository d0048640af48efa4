"""tools/build_summary.py: the summary `make` prints at the end."""

from __future__ import annotations

import importlib.util
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from turntable.claims.report import summarize

ROOT = Path(__file__).resolve().parents[1]
TOOL = ROOT / "tools" / "build_summary.py"


def _report(verdicts: dict[str, str], added: tuple[str, ...] = ()) -> dict:
    """A claims report as rule `claims` writes it (turntable.claims.report)."""
    records = [
        {
            "id": c,
            "verdict": v,
            "source": "project" if c in added else "paper",
            "summary": f"value of {c} " + "x" * 200,
            "gist": f"what {c} means " + "word " * 40,
        }
        for c, v in verdicts.items()
    ]
    return {
        "order": list(verdicts),
        "summary": summarize(records),
        "claims": {r["id"]: r for r in records},
    }


def _run(tmp_path: Path, report: dict | None, study: dict | None) -> str:
    claims, summary = tmp_path / "claims.json", tmp_path / "summary.json"
    if report is not None:
        claims.write_text(json.dumps(report))
    if study is not None:
        summary.write_text(json.dumps(study))
    out = subprocess.run(
        [sys.executable, str(TOOL), str(claims), str(summary)],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    return out.stdout


def test_lists_every_claim_that_is_not_confirmed(tmp_path: Path) -> None:
    verdicts = {
        "a.one": "confirmed",
        "b.two": "refined",
        "c.three": "failed",
        "d.four": "confirmed",
    }
    report = _report(verdicts, added=("d.four",))
    out = _run(tmp_path, report, {"all_passed": True, "failed": [], "per_k": [1, 2]})
    lines = out.splitlines()
    assert (
        "claims: 4 checked: 2 confirmed, 1 refined, 0 corrected, 0 undecidable, 1 failed" in lines
    )
    # the paper's claims counted apart from the additions, every verdict of the paper's shown
    assert (
        "  (3 of the paper: 1 confirmed, 1 refined, 0 corrected, 0 undecidable, 1 failed; "
        "1 addition: 1 confirmed)"
    ) in lines
    listed = [line for line in lines if re.match(r"  [a-z]+ +[a-z]\.", line)]
    assert [line.split()[:2] for line in listed] == [["refined", "b.two"], ["failed", "c.three"]]
    # each with its gist, whole, wrapped under the start of the text
    text = out.split("  failed ")[1].split("full table")[0]
    assert " ".join(text.split()[1:]) == ("what c.three means " + "word " * 40).strip()
    assert re.search(r"\n {10,}word", out)
    # no Python dict or list printed as such
    assert not re.search(r"[{}\[\]]|': ", out)
    assert all(len(line) <= 110 for line in lines)
    assert any("results/claims.md" in line for line in lines)
    assert "study: all checks hold for 2 values of k" in lines


def test_all_confirmed_lists_none(tmp_path: Path) -> None:
    out = _run(tmp_path, _report({"a.one": "confirmed"}), None)
    assert "claims: 1 checked: 1 confirmed, 0 refined, 0 corrected, 0 undecidable, 0 failed" in out
    assert not [line for line in out.splitlines() if re.match(r"  [a-z]+ +[a-z]\.", line)]


def test_missing_report_and_failed_study(tmp_path: Path) -> None:
    study = {"all_passed": False, "failed": ["k=0.4: damping bound"], "per_k": []}
    out = _run(tmp_path, None, study)
    assert "is missing" in out
    assert "study: failed checks: k=0.4: damping bound" in out


@pytest.mark.parametrize("verdict", ["refined", "corrected", "undecidable", "failed"])
def test_any_verdict_other_than_confirmed_is_listed(verdict: str) -> None:
    spec = importlib.util.spec_from_file_location("build_summary", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    lines = module.claims_lines(_report({"x.y": verdict}))
    assert lines[2].split()[:2] == [verdict, "x.y"]


@pytest.mark.parametrize(
    "summary",
    [
        pytest.param("bound " + "x" * 60 + " constant to 1.3e-15 relative, other", id="word"),
        pytest.param("a" * 70 + " first 2.5e-08; second 1.25e-15 and more", id="clause"),
        pytest.param("x" * 200, id="one-word"),
    ],
)
def test_a_long_summary_is_never_cut_inside_a_number(summary: str) -> None:
    """(For a report without gists.) A cut line ends with " ..." after a whole word or
    clause, at most 110 characters."""
    spec = importlib.util.spec_from_file_location("build_summary", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    full = "  refined     some.claim  " + summary
    line = module.shorten(full)
    assert len(line) <= module.WIDTH
    assert line.endswith(" ...")
    words = [w.rstrip(",;") for w in full.split()]
    assert all(word.rstrip(",;") in words for word in line.removesuffix(" ...").split()), line
