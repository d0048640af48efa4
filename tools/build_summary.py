"""Print the short summary that ends `make`: verdict counts, every claim not confirmed with
what its verdict means (the registry's gist), paths.

Usage: ``python tools/build_summary.py [claims.json] [study/summary.json] [campaign/summary.csv]``
(defaults in results/). Reads only the outputs of the build; a missing
file is reported as such instead of failing, so the summary never hides the build's result.
"""

from __future__ import annotations

import csv
import json
import sys
import textwrap
from pathlib import Path

WIDTH = 110


def _counts(verdicts: list[str], order: list[str]) -> str:
    """'2 confirmed, 1 refined, 0 failed': every verdict of ``order``, then any other."""
    names = order + sorted(set(verdicts) - set(order))
    return ", ".join(f"{verdicts.count(v)} {v}" for v in names)


def shorten(line: str, width: int = WIDTH) -> str:
    """``line`` cut to at most ``width`` characters, followed by " ...": at the end of a
    clause ("; " or ", ") among the last 25 characters kept, else at the end of a word, so
    that a number is never cut short."""
    if len(line) <= width:
        return line
    head = line[: width - 4]
    for sep in ("; ", ", "):
        cut = head.rfind(sep)
        if cut >= len(head) - 25:
            return head[:cut] + " ..."
    cut = head.rfind(" ")
    return (head[:cut] if cut > 0 else head) + " ..."


def claims_lines(report: dict, table: str = "results/claims.md") -> list[str]:
    """Verdict counts (all, then the paper's apart from the additions), then each claim
    whose verdict is not 'confirmed' with its gist (wrapped to `WIDTH`), then where the full
    table is."""
    claims = [report["claims"][cid] for cid in report["order"]]
    order = list(report["summary"].get("verdicts", []))
    verdicts = [c["verdict"] for c in claims]
    lines = [f"claims: {len(claims)} checked: {_counts(verdicts, order)}"]
    parts = []
    for source in ("paper", "project"):
        of_source = [c["verdict"] for c in claims if c.get("source", "paper") == source]
        n = len(of_source)
        if n:
            words = "of the paper" if source == "paper" else "addition" + "s" * (n != 1)
            shown = order if source == "paper" else [v for v in order if v in of_source]
            parts.append(f"{n} {words}: {_counts(of_source, shown)}")
    lines.append("  (" + "; ".join(parts) + ")")
    width = max((len(cid) for cid in report["order"]), default=0)
    for cid, claim in zip(report["order"], claims, strict=True):
        if claim["verdict"] == "confirmed":
            continue
        # what the verdict means for this claim, in words (the registry's gist), whole and
        # wrapped; a report without gists shows the summary of the numbers, cut
        head = f"  {claim['verdict']:<11} {cid:<{width}}  "
        if claim.get("gist"):
            lines += textwrap.wrap(
                claim["gist"],
                WIDTH,
                initial_indent=head,
                subsequent_indent=" " * len(head),
                break_long_words=False,
                break_on_hyphens=False,
            )
        else:
            lines.append(shorten(head + claim["summary"]))
    lines.append(f"full table: {table} (and in results/report.html); article: paper/paper.pdf")
    return lines


def study_line(summary: dict) -> str:
    """One line on the parameter study."""
    if summary["all_passed"]:
        return f"study: all checks hold for {len(summary['per_k'])} values of k"
    return "study: failed checks: " + ", ".join(summary["failed"])


def campaign_lines(path: Path) -> list[str]:
    """One line on the campaign, then one per film that failed, with its row and reason."""
    with path.open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    failed = [r for r in rows if r["status"] == "failed"]
    lines = [f"campaign: {len(rows) - len(failed)} films fitted, {len(failed)} failed ({path})"]
    return lines + [
        shorten(f"  failed: row {r['row']} ({r['file']}): {r['warnings']}") for r in failed
    ]


def main(argv: list[str]) -> int:
    claims = Path(argv[1] if len(argv) > 1 else "results/claims.json")
    study = Path(argv[2] if len(argv) > 2 else "results/study/summary.json")
    campaign = Path(argv[3] if len(argv) > 3 else "results/campaign/summary.csv")
    lines = ["", "== turntable: summary of the build =="]
    if claims.is_file():
        lines += claims_lines(json.loads(claims.read_text(encoding="utf-8")))
    else:
        lines.append(f"claims: {claims} is missing")
    if study.is_file():
        lines.append(study_line(json.loads(study.read_text(encoding="utf-8"))))
    if campaign.is_file():
        lines += campaign_lines(campaign)
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
