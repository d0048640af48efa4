"""Print the short summary that ends `make`: verdict counts, every claim not confirmed, paths.

Usage: ``python tools/build_summary.py [results/claims.json] [results/study/summary.json]``.
Reads only the outputs of the build (the claims report and the study summary); a missing
file is reported as such instead of failing, so the summary never hides the build's result.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

WIDTH = 110


def claims_lines(report: dict, table: str = "results/claims.md") -> list[str]:
    """Verdict counts, then one line per claim whose verdict is not 'confirmed'."""
    counts = {k: v for k, v in report["summary"].items() if k != "total"}
    counted = ", ".join(f"{n} {verdict}" for verdict, n in counts.items() if n)
    lines = [f"claims: {report['summary']['total']} checked: {counted}"]
    width = max((len(cid) for cid in report["order"]), default=0)
    for cid in report["order"]:
        claim = report["claims"][cid]
        if claim["verdict"] == "confirmed":
            continue
        line = f"  {claim['verdict']:<11} {cid:<{width}}  {claim['summary']}"
        lines.append(line if len(line) <= WIDTH else line[: WIDTH - 3] + "...")
    lines.append(f"full table: {table} (and in results/report.html); article: paper/paper.pdf")
    return lines


def study_line(summary: dict) -> str:
    """One line on the parameter study."""
    if summary["all_passed"]:
        return f"study: all checks hold for {len(summary['per_k'])} values of k"
    return "study: failed checks: " + ", ".join(summary["failed"])


def main(argv: list[str]) -> int:
    claims = Path(argv[1] if len(argv) > 1 else "results/claims.json")
    study = Path(argv[2] if len(argv) > 2 else "results/study/summary.json")
    lines = ["", "== turntable: summary of the build =="]
    if claims.is_file():
        lines += claims_lines(json.loads(claims.read_text(encoding="utf-8")))
    else:
        lines.append(f"claims: {claims} is missing")
    if study.is_file():
        lines.append(study_line(json.loads(study.read_text(encoding="utf-8"))))
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
